//! Shared by the ordinary-scenes suites: one scene run with plain rapier friction or with
//! stickslip (default configuration) attached to every collider, stepped the same way.

#![allow(dead_code)]

use stickslip_core::law::{Law, Regularization, Regularized};
use stickslip_core::sliding_curve::Curve;
use stickslip_fixtures::ordinary::OrdinaryScene;
use stickslip_rapier::rapier::prelude::*;
use stickslip_rapier::{FrictionMaterial, ReadBack, StickSlip};

/// Who decides the friction of a scene.
#[derive(Debug, Clone)]
pub enum Friction {
    /// rapier's own Coulomb friction (the colliders' coefficient).
    Plain,
    /// rapier's own friction, every collider flagged for a contact hook that changes
    /// nothing: rapier never recycles the contacts of a hooked pair (it recomputes them every
    /// step), which alone changes some scenes — the baseline for what any hook gets.
    Hooked,
    /// stickslip with this law on every collider.
    Law(&'static str, Law),
}

impl Friction {
    /// A short label for printed tables.
    pub fn name(&self) -> &'static str {
        match self {
            Friction::Plain => "plain",
            Friction::Hooked => "no-op hook",
            Friction::Law(n, _) => n,
        }
    }
}

/// Stiffness of the elasto-plastic laws here (1/m): g_ba = μ/c = 5 µm at μ 0.5.
pub const C: f64 = 1e5;

/// The elasto-plastic law with static and sliding coefficient `mu` (what plain rapier's `mu`
/// means), or with static `mu_s` above a flat sliding `mu_k`.
pub fn ep(mu_s: f64, mu_k: f64) -> Law {
    Law::elasto_plastic(C, mu_s, mu_s.max(mu_k), Curve::constant(mu_k).unwrap()).unwrap()
}

/// Every law stickslip has, at coefficient `mu` (Regul creeps below ġ_t0 = 1 mm/s by design).
pub fn all_laws(mu: f64) -> Vec<Friction> {
    vec![
        Friction::Law("ep", ep(mu, mu)),
        Friction::Law(
            "phys",
            Law::Physical(
                stickslip_core::law::Physical::new(mu, Curve::constant(mu).unwrap()).unwrap(),
            ),
        ),
        Friction::Law(
            "coulomb",
            Law::Coulomb(stickslip_core::law::Coulomb::new(mu).unwrap()),
        ),
        Friction::Law(
            "regul",
            Law::Regularized(
                Regularized::new(Curve::constant(mu).unwrap(), 1e-3, Regularization::Linear)
                    .unwrap(),
            ),
        ),
    ]
}

/// A contact hook that changes nothing.
pub struct NoOp;

impl PhysicsHooks for NoOp {}

/// A scene and the friction running it.
pub struct Run {
    pub scene: OrdinaryScene,
    pub modifier: Option<StickSlip>,
    hooked: bool,
}

impl Run {
    /// `friction` on every collider of `scene` (stickslip with reports on).
    pub fn new(mut scene: OrdinaryScene, friction: &Friction) -> Run {
        let modifier = match friction {
            Friction::Plain => None,
            Friction::Hooked => {
                for c in scene.all_colliders() {
                    scene.world.colliders[c].set_active_hooks(ActiveHooks::MODIFY_SOLVER_CONTACTS);
                }
                None
            }
            Friction::Law(_, law) => {
                let mut m = StickSlip::new(FrictionMaterial::new(law.clone()))
                    .with_read_back(ReadBack::Contacts);
                for c in scene.all_colliders() {
                    m.attach(&mut scene.world.colliders, c, None);
                }
                Some(m)
            }
        };
        Run {
            scene,
            modifier,
            hooked: matches!(friction, Friction::Hooked),
        }
    }

    pub fn step(&mut self) {
        match self.modifier.as_mut() {
            Some(m) => m.step(&mut self.scene.world),
            None if self.hooked => self.scene.world.step_with_events(&NoOp, &()),
            None => self.scene.world.step(),
        }
    }

    pub fn steps(&mut self, n: usize) {
        for _ in 0..n {
            self.step();
        }
    }

    pub fn dt(&self) -> f64 {
        self.scene.world.integration_parameters.dt as f64
    }

    pub fn body(&self, i: usize) -> &RigidBody {
        &self.scene.world.bodies[self.scene.bodies[i]]
    }

    pub fn body_mut(&mut self, i: usize) -> &mut RigidBody {
        &mut self.scene.world.bodies[self.scene.bodies[i]]
    }

    /// Steps for `seconds`.
    pub fn run_for(&mut self, seconds: f64) {
        let n = (seconds / self.dt()).round() as usize;
        self.steps(n);
    }
}

/// Relative error of `measured` against `expected`.
pub fn rel(measured: f64, expected: f64) -> f64 {
    (measured - expected) / expected
}
