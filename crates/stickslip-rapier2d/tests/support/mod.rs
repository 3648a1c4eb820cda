//! Shared 2D scenes of the rapier2d tests: a box on a ground under tilted gravity (an
//! incline without rotated frames), the plain-rapier2d and stickslip steppers, materials.
#![allow(dead_code)]

use stickslip_rapier2d::core::law::Law;
use stickslip_rapier2d::core::sliding_curve::Curve;
use stickslip_rapier2d::rapier::prelude::*;
use stickslip_rapier2d::{FrictionMaterial, StickSlip};

/// Standard gravity (m/s²).
pub const G: f64 = 9.81;

/// The EP law of the tests: c = 1e4 1/m, μ_ba = 0.5, μ_max = 0.55, sliding at μ_k.
pub fn ep(mu_k: f64) -> Law {
    Law::elasto_plastic(1e4, 0.5, 0.55, Curve::constant(mu_k).unwrap()).unwrap()
}

/// A box of half-extent 0.25 m (density 1000: 250 kg per m of depth) resting on a fixed
/// ground, with gravity tilted by `theta` so that the ground is an incline descending
/// towards +x.
pub struct BoxOnIncline {
    pub world: PhysicsWorld,
    pub body: RigidBodyHandle,
    pub ground: ColliderHandle,
    pub cube: ColliderHandle,
}

impl BoxOnIncline {
    pub fn new(theta: f64, friction: f32) -> Self {
        let mut world = PhysicsWorld {
            gravity: Vector::new((G * theta.sin()) as f32, -(G * theta.cos()) as f32),
            ..PhysicsWorld::default()
        };
        let ground =
            world.insert_collider(ColliderBuilder::cuboid(50.0, 0.1).friction(friction), None);
        let (body, cube) = world.insert(
            RigidBodyBuilder::dynamic()
                .translation(Vector::new(0.0, 0.35))
                .can_sleep(false),
            ColliderBuilder::cuboid(0.25, 0.25)
                .density(1000.0)
                .friction(friction),
        );
        BoxOnIncline {
            world,
            body,
            ground,
            cube,
        }
    }

    /// stickslip with `law` on both colliders.
    pub fn attach(&mut self, law: Law) -> StickSlip {
        let mut m = StickSlip::new(FrictionMaterial::new(law));
        m.attach(&mut self.world.colliders, self.ground, None);
        m.attach(&mut self.world.colliders, self.cube, None);
        m
    }

    pub fn x(&self) -> f64 {
        self.world.bodies[self.body].translation().x as f64
    }

    pub fn vx(&self) -> f64 {
        self.world.bodies[self.body].linvel().x as f64
    }
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

/// A sled: a box of half-extent `half` and mass `mass`, rotations locked, on a long fixed
/// plate whose top is y = 0.1, gravity off (the test presses it with a force), stepped at
/// `dt`; both colliders' rapier friction `friction`, sleeping off.
pub struct Sled {
    pub world: PhysicsWorld,
    pub body: RigidBodyHandle,
    pub plate: ColliderHandle,
    pub sled: ColliderHandle,
}

impl Sled {
    pub fn new(half: f32, mass: f32, dt: f64, friction: f32) -> Self {
        Sled::with_order(half, mass, dt, friction, false)
    }

    /// [`Sled::new`], the sled inserted before the plate when `sled_first` (rapier2d then
    /// lists the sled as the pair's collider 1: the contact normal points down).
    pub fn with_order(half: f32, mass: f32, dt: f64, friction: f32, sled_first: bool) -> Self {
        let mut world = PhysicsWorld {
            gravity: Vector::ZERO,
            ..PhysicsWorld::default()
        };
        world.integration_parameters.dt = dt as f32;
        let plate_builder = ColliderBuilder::cuboid(500.0, 0.1).friction(friction);
        let body_builder = RigidBodyBuilder::dynamic()
            .translation(Vector::new(0.0, 0.1 + half))
            .lock_rotations()
            .can_sleep(false);
        let sled_builder = ColliderBuilder::cuboid(half, half)
            .density(mass / (4.0 * half * half))
            .friction(friction);
        let (plate, (body, sled)) = if sled_first {
            let bs = world.insert(body_builder, sled_builder);
            (world.insert_collider(plate_builder, None), bs)
        } else {
            let p = world.insert_collider(plate_builder, None);
            (p, world.insert(body_builder, sled_builder))
        };
        Sled {
            world,
            body,
            plate,
            sled,
        }
    }

    /// stickslip with `law` on both colliders (the pair is the law's alone).
    pub fn attach(&mut self, law: Law) -> StickSlip {
        let mut m = StickSlip::new(FrictionMaterial::new(law));
        m.attach(&mut self.world.colliders, self.plate, None);
        m.attach(&mut self.world.colliders, self.sled, None);
        m
    }

    pub fn x(&self) -> f64 {
        self.world.bodies[self.body].translation().x as f64
    }

    pub fn vx(&self) -> f64 {
        self.world.bodies[self.body].linvel().x as f64
    }

    pub fn mass(&self) -> f64 {
        self.world.bodies[self.body].mass() as f64
    }

    /// Replaces the user forces on the sled by `force` (N, world).
    pub fn set_force(&mut self, force: Vector) {
        let b = &mut self.world.bodies[self.body];
        b.reset_forces(true);
        b.add_force(force, true);
    }

    /// Imposes the sled's velocity along x (keeping its normal velocity).
    pub fn drive(&mut self, vx: f64) {
        let b = &mut self.world.bodies[self.body];
        let vy = b.linvel().y;
        b.set_linvel(Vector::new(vx as f32, vy), true);
    }
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
