//! A conveyor written as a user's own hook.

use stickslip_rapier::rapier::prelude::*;

/// A conveyor written as a user's own hook (the tests of wrapped hooks; stickslip's own is
/// [`stickslip_rapier::StickSlip::set_surface_velocity`]): the `belt` collider's surface moves at
/// `velocity` (world), through rapier's per-contact target tangent velocity. Flag the belt
/// collider with
/// `ActiveHooks::MODIFY_SOLVER_CONTACTS` (as without stickslip), wrap the conveyor with
/// [`stickslip_rapier::StickSlip::with_hooks`], and the friction law works relative to the moving
/// surface.
#[derive(Debug, Clone, Copy)]
pub struct Conveyor {
    /// The belt collider.
    pub belt: ColliderHandle,
    /// Surface velocity (m/s, world).
    pub velocity: Vector,
}

impl PhysicsHooks for Conveyor {
    fn modify_solver_contacts(&self, ctx: &mut ContactModificationContext) {
        // tangent_velocity is the target velocity of collider 2 relative to collider 1.
        let v = if ctx.collider1 == self.belt {
            self.velocity
        } else if ctx.collider2 == self.belt {
            -self.velocity
        } else {
            return;
        };
        // rapier 0.35 keeps the solver contacts on the context; 0.36 behind `rigid_mut`.
        #[cfg(rapier_035)]
        let contacts = ctx.solver_contacts.iter_mut();
        #[cfg(not(rapier_035))]
        let Some(contacts) = ctx.rigid_mut().map(|m| m.solver_contacts.iter_mut()) else {
            return;
        };
        for c in contacts {
            c.tangent_velocity = v;
        }
    }
}
