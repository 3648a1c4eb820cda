//! The rapier hooks of a bracketed step: the app's own `BevyPhysicsHooks` first on the pairs
//! the app flagged, then stickslip (the surface velocities, then its law on its pairs).

use bevy_rapier::pipeline::{ContactModificationContextView, PairFilterContextView};
use bevy_rapier::prelude::BevyPhysicsHooks;
use bevy_rapier::rapier::geometry::SolverFlags;
use bevy_rapier::rapier::pipeline::{ContactModificationContext, PairFilterContext, PhysicsHooks};
use stickslip_rapier::StickSlip;

/// The app's hooks as rapier hooks. Which pairs they see is stickslip's to decide (the
/// modifier owns whose hook flag is whose, see `StickSlip::modify_solver_contacts_with`);
/// in a context stickslip does not bracket it has no flags and they see every pair.
pub(crate) struct UserHooks<'a, T> {
    pub(crate) user: &'a T,
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
        self.user
            .modify_solver_contacts(ContactModificationContextView { raw: &mut *context });
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
