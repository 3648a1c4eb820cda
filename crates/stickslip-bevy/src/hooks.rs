//! The plugin's own rapier hooks, wrapped by the stickslip modifier: moving surfaces.

use rapier3d::prelude as rp;
use std::collections::HashMap;

/// Gives the contacts of colliders with a `SurfaceVelocity` their target tangent velocity.
#[derive(Debug, Default)]
pub struct SurfaceHooks {
    pub(crate) surfaces: HashMap<rp::ColliderHandle, rp::Vector>,
}

impl rp::PhysicsHooks for SurfaceHooks {
    fn modify_solver_contacts(&self, ctx: &mut rp::ContactModificationContext) {
        // tangent_velocity is the target velocity of collider 2 relative to collider 1.
        let v1 = self.surfaces.get(&ctx.collider1).copied();
        let v2 = self.surfaces.get(&ctx.collider2).copied();
        if v1.is_none() && v2.is_none() {
            return;
        }
        let v = v1.unwrap_or(rp::Vector::ZERO) - v2.unwrap_or(rp::Vector::ZERO);
        if let Some(m) = ctx.rigid_mut() {
            let n = *m.normal;
            let tangential = v - n * n.dot(v);
            for c in m.solver_contacts.iter_mut() {
                c.tangent_velocity = tangential;
            }
        }
    }
}
