//! What differs between the two rapier versions these sources build against: rapier3d 0.36
//! (plain rapier users: the `stickslip-rapier` package) and 0.35.0-glamx0.2 (the version
//! bevy_rapier3d 0.36 pins: the `stickslip-rapier-035` package builds the same files with
//! `cfg(rapier_035)`). Everything else stickslip uses is the same in both.
//!
//! - The hook context: 0.36 wraps the manifold in `ctx.rigid()` / `ctx.rigid_mut()` (a pair of
//!   soft surfaces has none); 0.35 has its fields on the context. Under 0.35 the trait
//!   [`RigidManifold`] gives the context the same two methods.
//! - The normal impulse a manifold's points report after a solve ([`solve_impulse`]).

/// The normal impulse of a manifold's last solve, from the impulses its points report
/// (`reported`, summed), the warm-start impulses they carry now (`warm_now`) and, where known,
/// the warm start that solve started from (`warm_before`). rapier 0.36 reports the solve's own
/// impulse (the sum over its substeps); 0.35 adds the warm start the first substep re-applied
/// (`impulse_accumulator` starts at 0 there, at minus the warm start in 0.36): ~1/4 too much
/// with 4 substeps. Without `warm_before`, 0.35 takes the warm start now (the last substep's
/// impulse, which the solve leaves behind as the next warm start) for it: exact at a steady
/// load.
#[inline]
#[allow(unused_variables)]
pub(crate) fn solve_impulse(reported: f64, warm_now: f64, warm_before: Option<f64>) -> f64 {
    #[cfg(not(rapier_035))]
    {
        reported
    }
    #[cfg(rapier_035)]
    {
        reported - warm_before.unwrap_or(warm_now)
    }
}

/// The warm start a record remembers for the next reading (rapier 0.35 only).
#[inline]
#[allow(unused_variables)]
pub(crate) fn warm_before(rec: &crate::contact_store::ContactRecord) -> Option<f64> {
    #[cfg(not(rapier_035))]
    {
        None
    }
    #[cfg(rapier_035)]
    {
        // 0 until the record has seen a solve start: the contact's first solve starts cold.
        Some(rec.warm_start_impulse as f64)
    }
}

/// Remembers the warm start the coming solve starts from (rapier 0.35 only).
#[inline]
#[allow(unused_variables)]
pub(crate) fn remember_warm_start(rec: &mut crate::contact_store::ContactRecord, warm: f64) {
    #[cfg(rapier_035)]
    {
        rec.warm_start_impulse = warm as f32;
    }
}

/// The largest relative drift (m) over which rapier recycles a pair's contacts: the
/// prediction distance (the window of a pair with nothing touching yet), or the recycle
/// distance if smaller; 0 when rapier does not recycle.
pub(crate) fn recycle_window(params: &rapier::prelude::IntegrationParameters) -> f32 {
    if params.contact_recycling {
        params
            .contact_recycle_distance()
            .min(params.prediction_distance())
            .max(0.0)
    } else {
        0.0
    }
}

/// The friction coefficient rapier gives a pair of colliders on a full contact update:
/// their coefficients by the combine rule that wins (`CoefficientCombineRule::combine`, which
/// 0.35 keeps private: there, the same code).
pub(crate) fn combined_friction(
    a: &rapier::prelude::Collider,
    b: &rapier::prelude::Collider,
) -> f32 {
    use rapier::prelude::CoefficientCombineRule as Rule;
    let (c1, c2) = (a.friction(), b.friction());
    let (r1, r2) = (a.friction_combine_rule(), b.friction_combine_rule());
    #[cfg(not(rapier_035))]
    {
        Rule::combine(c1, c2, r1, r2)
    }
    #[cfg(rapier_035)]
    {
        match r1.max(r2) {
            Rule::Average => (c1 + c2) / 2.0,
            Rule::Min => c1.min(c2).abs(),
            Rule::Multiply => c1 * c2,
            Rule::Max => c1.max(c2),
            Rule::ClampedSum => (c1 + c2).clamp(0.0, 1.0),
            Rule::GeometricMean => (c1.max(0.0) * c2.max(0.0)).sqrt(),
        }
    }
}

#[cfg(rapier_035)]
pub(crate) use v035::RigidManifold;

#[cfg(rapier_035)]
mod v035 {
    use rapier::geometry::SolverContacts;
    use rapier::prelude::*;

    /// The manifold of a hook call, read-only (0.36's `ctx.rigid()`).
    pub(crate) struct ManifoldRef<'s, 'a> {
        pub manifold: &'a ContactManifold,
        pub solver_contacts: &'s SolverContacts,
        pub user_data: &'s u32,
    }

    /// The manifold of a hook call, to modify (0.36's `ctx.rigid_mut()`).
    pub(crate) struct ManifoldMut<'s, 'a> {
        pub manifold: &'a ContactManifold,
        pub solver_contacts: &'s mut SolverContacts,
        pub normal: &'s mut Vector,
        pub friction: &'s mut Real,
        pub user_data: &'s mut u32,
    }

    /// 0.36's accessors on a 0.35 context (every 0.35 pair is rigid).
    pub(crate) trait RigidManifold<'a> {
        fn rigid(&self) -> Option<ManifoldRef<'_, 'a>>;
        fn rigid_mut(&mut self) -> Option<ManifoldMut<'_, 'a>>;
    }

    impl<'a> RigidManifold<'a> for ContactModificationContext<'a> {
        fn rigid(&self) -> Option<ManifoldRef<'_, 'a>> {
            Some(ManifoldRef {
                manifold: self.manifold,
                solver_contacts: self.solver_contacts,
                user_data: self.user_data,
            })
        }

        fn rigid_mut(&mut self) -> Option<ManifoldMut<'_, 'a>> {
            Some(ManifoldMut {
                manifold: self.manifold,
                solver_contacts: self.solver_contacts,
                normal: self.normal,
                friction: self.friction,
                user_data: self.user_data,
            })
        }
    }
}
