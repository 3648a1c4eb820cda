//! Stacks and toppling in rapier2d worlds with stickslip attached to every collider (default
//! `StickSlipConfig`), beside plain rapier2d in the same test. Invariants:
//! - a pyramid of 0.5 m boxes (10 on the bottom row, 55 in all; μ 0.5), on a level floor and on
//!   a floor tilted to tan θ = 0.1, stands as still as under plain rapier2d: over 10 s after
//!   2 s of settling, no more boxes moved by more than 1 mm and no more mean downhill creep
//!   than plain rapier2d's or 0.1 mm, whichever is larger — for the elasto-plastic law with
//!   μ_ba = μ_k and with static above kinetic friction (μ_ba 0.5, μ_k 0.3);
//! - a row of 12 dominoes whose first one is tipped all falls, as in plain rapier2d.

mod support;

use stickslip_rapier2d::core::law::Law;
use stickslip_rapier2d::rapier::prelude::*;
use stickslip_rapier2d::{FrictionMaterial, StickSlip};
use support::{G, ep_flat};

const DT: f64 = 1.0 / 60.0;
const MU: f32 = 0.5;
/// Stiffness of the laws here (1/m): g_ba = μ/c = 5 µm.
const C: f64 = 1e5;

/// A world with gravity tilted to `tan_theta` down +x, a ground slab whose top is y = 0, its
/// dynamic bodies, and the friction running it (None: plain rapier2d).
struct Scene {
    world: PhysicsWorld,
    bodies: Vec<RigidBodyHandle>,
    modifier: Option<StickSlip>,
}

impl Scene {
    fn new(tan_theta: f64) -> Scene {
        let mut world = PhysicsWorld::default();
        world.integration_parameters.dt = DT as f32;
        let th = tan_theta.atan();
        world.gravity = Vector::new((G * th.sin()) as f32, -(G * th.cos()) as f32);
        world.insert_collider(
            ColliderBuilder::cuboid(20.0, 0.5)
                .translation(Vector::new(0.0, -0.5))
                .friction(MU),
            None,
        );
        Scene {
            world,
            bodies: Vec::new(),
            modifier: None,
        }
    }

    fn add(&mut self, body: RigidBodyBuilder, collider: ColliderBuilder) {
        let (b, _) = self
            .world
            .insert(body.can_sleep(false), collider.friction(MU));
        self.bodies.push(b);
    }

    /// `law` on every collider (ground and bodies).
    fn attach(mut self, law: Option<Law>) -> Scene {
        self.modifier = law.map(|law| {
            let mut m = StickSlip::new(FrictionMaterial::new(law));
            let all: Vec<ColliderHandle> = self.world.colliders.iter().map(|(h, _)| h).collect();
            for h in all {
                m.attach(&mut self.world.colliders, h, None);
            }
            m
        });
        self
    }

    fn run_for(&mut self, seconds: f64) {
        for _ in 0..(seconds / DT).round() as usize {
            match self.modifier.as_mut() {
                Some(m) => m.step(&mut self.world),
                None => self.world.step(),
            }
        }
    }

    fn positions(&self) -> Vec<Vector> {
        self.bodies
            .iter()
            .map(|b| self.world.bodies[*b].translation())
            .collect()
    }
}

/// A pyramid of 0.5 m boxes (density 500), `size` on the bottom row.
fn pyramid(size: usize, tan_theta: f64, law: Option<Law>) -> Scene {
    let mut s = Scene::new(tan_theta);
    let h = 0.25f32;
    for row in 0..size {
        let n = size - row;
        for i in 0..n {
            let x = (i as f32 - (n - 1) as f32 / 2.0) * 2.0 * h;
            let y = h + row as f32 * 2.0 * h;
            s.add(
                RigidBodyBuilder::dynamic().translation(Vector::new(x, y)),
                ColliderBuilder::cuboid(h, h).density(500.0),
            );
        }
    }
    s.attach(law)
}

/// (boxes moved > 1 mm, mean displacement along +x in m) over 10 s after 2 s.
fn stillness(tan_theta: f64, law: Option<Law>) -> (usize, f64) {
    let mut s = pyramid(10, tan_theta, law);
    s.run_for(2.0);
    let before = s.positions();
    s.run_for(10.0);
    let after = s.positions();
    let moved = before
        .iter()
        .zip(&after)
        .filter(|(a, b)| (**b - **a).length() > 1e-3)
        .count();
    let creep = before
        .iter()
        .zip(&after)
        .map(|(a, b)| (b.x - a.x) as f64)
        .sum::<f64>()
        / before.len() as f64;
    (moved, creep)
}

#[test]
fn a_pyramid_stands_as_under_plain_rapier2d() {
    for tan_theta in [0.0, 0.1] {
        let (plain_moved, plain_creep) = stillness(tan_theta, None);
        println!(
            "pyramid (55 boxes) tan θ {tan_theta}: plain rapier2d > 1 mm {plain_moved}, creep \
             {plain_creep:.2e} m"
        );
        for (name, law) in [
            ("ep 0.5", ep_flat(C, 0.5, 0.5)),
            ("ep 0.5/0.3", ep_flat(C, 0.5, 0.3)),
        ] {
            let (moved, creep) = stillness(tan_theta, Some(law));
            println!("    {name:10} > 1 mm {moved}, creep {creep:.2e} m");
            assert!(
                moved <= plain_moved,
                "{name} at tan θ {tan_theta}: {moved} boxes moved > 1 mm (plain {plain_moved})"
            );
            assert!(
                creep.abs() <= plain_creep.abs().max(1e-4),
                "{name} at tan θ {tan_theta}: crept {creep} m (plain {plain_creep})"
            );
        }
    }
}

#[test]
fn a_pushed_domino_row_all_falls_as_under_plain_rapier2d() {
    let count = 12;
    let fallen = |law: Option<Law>| {
        let mut s = Scene::new(0.0);
        for i in 0..count {
            let mut b = RigidBodyBuilder::dynamic().translation(Vector::new(i as f32 * 0.5, 0.5));
            if i == 0 {
                // Tipped towards the others.
                b = b.angvel(-1.5);
            }
            s.add(b, ColliderBuilder::cuboid(0.05, 0.5).density(700.0));
        }
        let mut s = s.attach(law);
        s.run_for(6.0);
        // A domino has fallen once it leans more than 30° from vertical.
        let angles: Vec<f32> = s
            .bodies
            .iter()
            .map(|b| s.world.bodies[*b].rotation().angle().abs())
            .collect();
        (
            angles.iter().filter(|a| **a > 30f32.to_radians()).count(),
            angles,
        )
    };
    let (plain, plain_angles) = fallen(None);
    println!("dominoes fallen: plain rapier2d {plain}/{count} {plain_angles:.2?}");
    assert_eq!(
        plain, count,
        "plain rapier2d's row must fall for the test to mean anything"
    );
    for (name, law) in [
        ("ep 0.5", ep_flat(C, 0.5, 0.5)),
        ("ep 0.5/0.3", ep_flat(C, 0.5, 0.3)),
    ] {
        let (n, angles) = fallen(Some(law));
        println!("    {name:10} {n}/{count} {angles:.2?}");
        assert_eq!(n, count, "{name}: only {n} of {count} dominoes fell");
    }
}
