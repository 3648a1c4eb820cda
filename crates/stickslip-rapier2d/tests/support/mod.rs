//! What the rapier2d tests not yet written once for both dimensions share (the others are
//! crates/stickslip-fixtures/tests, built for 2D by stickslip-fixtures2d): the plain-rapier2d
//! and stickslip steppers, materials, a user's conveyor hook.
#![allow(dead_code)]

use stickslip_rapier2d::StickSlip;
use stickslip_rapier2d::core::law::Law;
use stickslip_rapier2d::core::sliding_curve::Curve;
use stickslip_rapier2d::rapier::prelude::*;

/// Standard gravity (m/s²).
pub const G: f64 = 9.81;

/// The EP law of the tests: c = 1e4 1/m, μ_ba = 0.5, μ_max = 0.55, sliding at μ_k.
pub fn ep(mu_k: f64) -> Law {
    Law::elasto_plastic(1e4, 0.5, 0.55, Curve::constant(mu_k).unwrap()).unwrap()
}

/// Steps `world` `n` times with `modifier`, or plain rapier2d without one.
pub fn run(world: &mut PhysicsWorld, modifier: Option<&mut StickSlip>, n: usize) {
    match modifier {
        Some(m) => {
            for _ in 0..n {
                m.step(world);
            }
        }
        None => {
            for _ in 0..n {
                world.step();
            }
        }
    }
}

/// The elasto-plastic law in the seed's sharp limit: stiffness `c`, break-away μ_ba = μ_max =
/// `mu_s`, sliding at a flat `mu_k` (μ_k ≤ μ_s: static above kinetic friction).
pub fn ep_flat(c: f64, mu_s: f64, mu_k: f64) -> Law {
    Law::elasto_plastic(c, mu_s, mu_s, Curve::constant(mu_k).unwrap()).unwrap()
}

/// The user's conveyor hook: the `belt` collider's surface moves at `velocity` (world),
/// through rapier2d's per-contact target tangent velocity. The user flags the belt with
/// `ActiveHooks::MODIFY_SOLVER_CONTACTS`, as without stickslip.
#[derive(Debug, Clone, Copy)]
pub struct Conveyor {
    pub belt: ColliderHandle,
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
        if let Some(m) = ctx.rigid_mut() {
            for c in m.solver_contacts.iter_mut() {
                c.tangent_velocity = v;
            }
        }
    }
}
