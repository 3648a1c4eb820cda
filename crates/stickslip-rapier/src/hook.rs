//! stickslip's [`PhysicsHooks`] impl: plumbing around the engine-free kernel's
//! [`stickslip_core::contact::step_contact`].
//! Per manifold it finds the contact's record, lets the wrapped hook run with its own
//! `user_data`, gathers the step's inputs from the manifold and the bodies (normal force and
//! measured friction of the last solve, the slip of the touching points at the centroid of the
//! solver contacts), and writes the friction limit and target velocity the step returns.
//! rapier keeps one friction coefficient and (by default in 3D, `FrictionModel::Simplified`)
//! one friction constraint per manifold, so stickslip keeps one friction state per manifold.

use crate::collider_map::ColliderMap;
use crate::contact_store::{ContactKey, ContactRecord, ManifoldPart, is_composite};
use crate::measure::{Measured, centroid, measure, point_velocity};
use crate::modifier::StickSlip;
#[cfg(rapier_035)]
use crate::rapier_compat::RigidManifold;
use crate::surface::surface_target;
use crate::warnings::Warning;
use rapier::prelude::*;
use std::sync::atomic::Ordering;
use stickslip_core::contact::{ContactInput, step_contact};
use stickslip_core::law::Law;

/// The key of a manifold (see [`ManifoldPart`]): two convex shapes have one manifold; a
/// composite shape one per sub-shape pair, or, when rapier clusters them for the solver, one
/// per contact normal — also while only one manifold is left, so the record survives the
/// pair dropping to a single manifold and back.
fn key(ctx: &ContactModificationContext, m: &ContactManifold, clustering: bool) -> ContactKey {
    let (c1, c2) = (ctx.collider1, ctx.collider2);
    let composite = |h| {
        ctx.colliders
            .get(h)
            .is_some_and(|c| is_composite(c.shape()))
    };
    let part = if !(composite(c1) || composite(c2)) {
        ManifoldPart::Whole
    } else if clustering {
        let n1 = m
            .subshape_pos1()
            .map_or(m.local_n1, |p| p.rotation * m.local_n1);
        ManifoldPart::cluster(n1)
    } else {
        ManifoldPart::Subshapes(m.subshape1, m.subshape2)
    };
    ContactKey { c1, c2, part }
}

pub(crate) fn inv_mass(bodies: &RigidBodySet, h: Option<RigidBodyHandle>) -> f64 {
    h.and_then(|h| bodies.get(h))
        .filter(|b| b.is_dynamic())
        .map_or(0.0, |b| {
            let m = b.mass() as f64;
            if m > 0.0 { 1.0 / m } else { 0.0 }
        })
}

/// The wrapped hooks, called only on the user's pairs (`theirs`), then the surface
/// velocities (see `surface`): what every pair gets before stickslip's law.
struct UsersPairsOnly<'a, I: ?Sized> {
    hooks: &'a I,
    theirs: bool,
    surfaces: &'a ColliderMap<Vector>,
}

impl<I: PhysicsHooks + ?Sized> UsersPairsOnly<'_, I> {
    fn modify_solver_contacts(&self, ctx: &mut ContactModificationContext) {
        if self.theirs {
            self.hooks.modify_solver_contacts(ctx);
        }
        if self.surfaces.is_empty() {
            return;
        }
        let pair = (ctx.collider1, ctx.collider2);
        if let Some(r) = ctx.rigid_mut() {
            let v = surface_target(self.surfaces, pair, *r.normal);
            if v != Vector::ZERO {
                for c in r.solver_contacts.iter_mut() {
                    c.tangent_velocity += v;
                }
            }
        }
    }
}

impl<H: PhysicsHooks> PhysicsHooks for StickSlip<H> {
    fn filter_contact_pair(&self, context: &PairFilterContext) -> Option<SolverFlags> {
        self.inner.filter_contact_pair(context)
    }

    fn filter_intersection_pair(&self, context: &PairFilterContext) -> bool {
        self.inner.filter_intersection_pair(context)
    }

    fn modify_solver_contacts(&self, ctx: &mut ContactModificationContext) {
        self.modify_solver_contacts_with(ctx, &self.inner);
    }
}

impl<H> StickSlip<H> {
    /// Whether rapier would call the user's hook on this pair without stickslip: one of its
    /// colliders carries a `MODIFY_SOLVER_CONTACTS` flag that [`Self::attach`] did not turn on.
    fn hooked_by_user(&self, ctx: &ContactModificationContext) -> bool {
        // The bits first: a pair of colliders stickslip flagged needs no collider lookup.
        [ctx.collider1, ctx.collider2].into_iter().any(|h| {
            !self.flagged.contains(h)
                && ctx.colliders.get(h).is_some_and(|c| {
                    c.active_hooks()
                        .contains(ActiveHooks::MODIFY_SOLVER_CONTACTS)
                })
        })
    }

    /// stickslip's `modify_solver_contacts` with `inner` as the wrapped hooks instead of the
    /// modifier's own (for integrations whose user hooks only exist during a step, such as
    /// bevy_rapier's `BevyPhysicsHooks`): pairs stickslip does not own go to `inner` alone; on
    /// its pairs `inner` runs first, on its own `user_data`. `inner` runs only where rapier
    /// would call it without stickslip: on pairs with a collider whose
    /// `MODIFY_SOLVER_CONTACTS` flag is not one [`Self::attach`] turned on.
    pub fn modify_solver_contacts_with<I: PhysicsHooks + ?Sized>(
        &self,
        ctx: &mut ContactModificationContext,
        inner: &I,
    ) {
        // The wrapped hook sees the pairs it would see without stickslip: those with a
        // collider whose hook flag is not stickslip's.
        let inner = &UsersPairsOnly {
            hooks: inner,
            theirs: self.hooked_by_user(ctx),
            surfaces: &self.surfaces,
        };
        // Pairs without an attached collider are the user's alone.
        if !self.owns(ctx.collider1, ctx.collider2) {
            inner.modify_solver_contacts(ctx);
            return;
        }
        if !self.clock.open {
            self.warned.once(
                Warning::NoBeginStep,
                "stickslip: the physics hook ran without StickSlip::begin_step since the last \
                 end_step; stickslip leaves such steps to rapier's friction (call begin_step \
                 before and end_step after every PhysicsPipeline::step, or use \
                 StickSlip::step)",
            );
            inner.modify_solver_contacts(ctx);
            return;
        }
        let Some(rigid) = ctx.rigid() else {
            inner.modify_solver_contacts(ctx);
            return;
        };
        let manifold = rigid.manifold;
        // A manifold without solver contacts (a pair inside the prediction distance, not
        // touching, or a contact that let go) has nothing for the law: it keeps no record
        // (one it had is swept; the kernel relaxes an unloaded contact's spring anyway), so
        // stickslip keeps state for touching contacts only, unless the wrapped hook keeps a
        // value in its user_data.
        if rigid.solver_contacts.is_empty() {
            let key = key(ctx, manifold, self.clock.clustering);
            let ours = *rigid.user_data;
            let inner_before = self.store.inner_user_data(ours, &key);
            if let Some(r) = ctx.rigid_mut() {
                *r.user_data = inner_before;
            }
            inner.modify_solver_contacts(ctx);
            let Some(r) = ctx.rigid_mut() else { return };
            let inner_data = *r.user_data;
            if inner_data == 0 {
                return;
            }
            let mut user_data = ours;
            self.store
                .with_record(&mut user_data, &key, self.clock.mark(), |rec, _, ours| {
                    rec.inner_user_data = inner_data;
                    *r.user_data = ours;
                });
            return;
        }
        let key = key(ctx, manifold, self.clock.clustering);
        let Some(rigid) = ctx.rigid() else { return };
        let mut user_data = *rigid.user_data;
        // The wrapped hook first, with no lock of stickslip's held, on its own user_data.
        let inner_before = self.store.inner_user_data(user_data, &key);
        if let Some(r) = ctx.rigid_mut() {
            *r.user_data = inner_before;
        }
        inner.modify_solver_contacts(ctx);
        let inner_after = ctx.rigid().map_or(inner_before, |r| *r.user_data);
        let step = self.clock.mark();
        let (c1, c2) = (ctx.collider1, ctx.collider2);
        self.store
            .with_record_filed(&mut user_data, &key, step, |rec, _, ours, filed| {
                rec.inner_user_data = inner_after;
                if let Some(r) = ctx.rigid_mut() {
                    *r.user_data = ours;
                }
                let patch = matches!(key.part, ManifoldPart::Cluster(_));
                let woken = |h| self.recycling.next.contains(h);
                if std::mem::take(&mut rec.ahead) && !(woken(c1) || woken(c2)) {
                    // `end_step` did this step (the pair was to be recycled and a later pair
                    // hooked one of its colliders again): the solver gets what it found.
                    if let Some(m) = ctx.rigid_mut() {
                        *m.friction = rec.state.limit;
                    }
                } else {
                    let measured = patch.then(|| self.patches_measured.get(filed)).flatten();
                    self.apply(ctx, rec, measured.as_ref());
                }
                if patch {
                    // A dynamic side first: the narrow phase finds a pair by walking the
                    // first collider's pairs, and a composite ground or drum has hundreds.
                    let dynamic = |b: Option<RigidBodyHandle>| {
                        b.and_then(|b| ctx.bodies.get(b))
                            .is_some_and(|b| b.is_dynamic())
                    };
                    let (a, b) = if !dynamic(ctx.rigid_body1) {
                        (ctx.collider2, ctx.collider1)
                    } else {
                        (ctx.collider1, ctx.collider2)
                    };
                    let index = |h: ColliderHandle| h.0.into_raw_parts().0;
                    crate::collider_map::push_slack(
                        &mut crate::contact_store::lock(&self.patches_seen),
                        (index(a), index(b), ours),
                    );
                }
            });
    }
}

impl<H> StickSlip<H> {
    /// `measured`: the last solve at this manifold, if `end_step` measured it (a contact
    /// patch of a composite shape); otherwise it is read from the manifold's points.
    fn apply(
        &self,
        ctx: &mut ContactModificationContext,
        rec: &mut ContactRecord,
        measured: Option<&Measured>,
    ) {
        let (c1, c2) = (ctx.collider1, ctx.collider2);
        let colliders = ctx.colliders;
        self.laws
            .with_pair_law(&self.attached, colliders, (c1, c2), &self.warned, |law| {
                self.step_manifold(ctx, rec, measured, law)
            });
    }

    fn step_manifold(
        &self,
        ctx: &mut ContactModificationContext,
        rec: &mut ContactRecord,
        measured: Option<&Measured>,
        law: &Law,
    ) {
        let (c1, c2) = (ctx.collider1, ctx.collider2);
        let bodies = ctx.bodies;
        let (rb1, rb2) = (ctx.rigid_body1, ctx.rigid_body2);
        let source = self.vibrations.get(c1).or_else(|| self.vibrations.get(c2));
        let rel = if self.vibrations.get(c1).is_some() {
            -1.0
        } else {
            1.0
        };
        let Some(m) = ctx.rigid_mut() else { return };
        let dt = self.clock.dt;
        if m.solver_contacts.is_empty() || !(dt > 0.0) {
            return;
        }
        let basis = crate::tangent::basis(*m.normal);
        let (p, surface) = centroid(m.solver_contacts);
        if surface != Vector::ZERO && !self.moving_surfaces.load(Ordering::Relaxed) {
            self.moving_surfaces.store(true, Ordering::Relaxed);
        }
        // ġ = v₂ − v₁ of the touching material points (relative to a moving surface).
        let slip = basis.project(crate::tangent::world(
            point_velocity(bodies, rb2, p) - point_velocity(bodies, rb1, p) - surface,
        ));
        let from_points = measure(
            m.manifold,
            m.solver_contacts,
            dt,
            crate::rapier_compat::warm_before(rec),
        );
        crate::rapier_compat::remember_warm_start(rec, from_points.warm_start_impulse);
        // A patch measured after the last solve: what rapier carried over to the points it
        // solves now is its warm start.
        let (meas, warm_start) = match measured {
            Some(last) if last.normal_force > 0.0 => {
                (*last, from_points.normal_force / last.normal_force)
            }
            Some(last) => (*last, 1.0),
            None => (from_points, 1.0),
        };
        let limit_before = rec.state.limit.to_bits();
        let out = step_contact(
            &mut rec.state,
            &ContactInput::new(law, &basis, dt)
                .with_solve(
                    meas.normal_force,
                    basis.project(crate::tangent::world(meas.mu)),
                    slip,
                )
                .with_source(source, rel)
                .at_time(self.clock.time)
                .with_inv_mass(inv_mass(bodies, rb1) + inv_mass(bodies, rb2))
                .with_stiffness_time(self.config.stiffness_time)
                .with_warm_start(warm_start),
        );
        *m.friction = rec.state.limit;
        if out.target != [0.0; 2] {
            let v = crate::tangent::vector(basis.lift(out.target));
            for c in m.solver_contacts.iter_mut() {
                c.tangent_velocity += v;
            }
        }
        // A write that changed keeps the pair hooked without being tried for recycling
        // after the step (see `recycle`): it will most likely change again.
        let changed = rec.state.limit.to_bits() != limit_before
            || out.target != [0.0; 2]
            || source.is_some()
            || surface != Vector::ZERO;
        if changed {
            self.mark_active(bodies, ctx.colliders, c1, c2);
        }
    }
}
