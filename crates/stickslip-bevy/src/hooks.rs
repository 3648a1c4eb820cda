//! The rapier hooks of a bracketed step: the app's own `BevyPhysicsHooks` first on the pairs
//! the app flagged, then stickslip (the surface velocities, then its law on its pairs).

use bevy_rapier3d::pipeline::{ContactModificationContextView, PairFilterContextView};
use bevy_rapier3d::prelude::BevyPhysicsHooks;
use bevy_rapier3d::rapier::geometry::{ColliderHandle, SolverFlags};
use bevy_rapier3d::rapier::pipeline::ActiveHooks;
use bevy_rapier3d::rapier::pipeline::{
    ContactModificationContext, PairFilterContext, PhysicsHooks,
};
use std::collections::HashSet;
use stickslip_rapier_035::StickSlip;

/// The app's hooks as rapier hooks.
pub(crate) struct UserHooks<'a, T> {
    pub(crate) user: &'a T,
    /// The colliders whose hook flag is stickslip's, not the app's.
    pub(crate) hook_flags: &'a HashSet<ColliderHandle>,
}

impl<T> UserHooks<'_, T> {
    /// Whether bevy_rapier would call the app's hook on this pair without stickslip.
    fn apps_pair(&self, context: &ContactModificationContext) -> bool {
        [context.collider1, context.collider2].into_iter().any(|h| {
            !self.hook_flags.contains(&h)
                && context.colliders.get(h).is_some_and(|c| {
                    c.active_hooks()
                        .contains(ActiveHooks::MODIFY_SOLVER_CONTACTS)
                })
        })
    }
}

impl<T: BevyPhysicsHooks> PhysicsHooks for UserHooks<'_, T> {
    fn filter_contact_pair(&self, context: &PairFilterContext) -> Option<SolverFlags> {
        self.user
            .filter_contact_pair(PairFilterContextView { raw: context })
    }

    fn filter_intersection_pair(&self, context: &PairFilterContext) -> bool {
        self.user
            .filter_intersection_pair(PairFilterContextView { raw: context })
    }

    fn modify_solver_contacts(&self, context: &mut ContactModificationContext) {
        if self.apps_pair(context) {
            self.user
                .modify_solver_contacts(ContactModificationContextView { raw: &mut *context });
        }
    }
}

/// The hooks rapier gets: stickslip (when it brackets this context) wrapping the app's.
pub(crate) struct StepHooks<'a, T> {
    pub(crate) stickslip: Option<&'a StickSlip>,
    pub(crate) user: UserHooks<'a, T>,
}

impl<T: BevyPhysicsHooks> PhysicsHooks for StepHooks<'_, T> {
    fn filter_contact_pair(&self, context: &PairFilterContext) -> Option<SolverFlags> {
        self.user.filter_contact_pair(context)
    }

    fn filter_intersection_pair(&self, context: &PairFilterContext) -> bool {
        self.user.filter_intersection_pair(context)
    }

    fn modify_solver_contacts(&self, context: &mut ContactModificationContext) {
        match self.stickslip {
            Some(s) => s.modify_solver_contacts_with(context, &self.user),
            None => self.user.modify_solver_contacts(context),
        }
    }
}
