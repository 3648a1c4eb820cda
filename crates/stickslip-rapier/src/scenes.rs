//! Ready-made reference scenes: the worlds stickslip's tests, examples and benchmarks measure
//! against analytic results (a box on an incline, on a belt, dragged over a vibrating plate, the
//! seed's Example 1), plus [`Conveyor`], a surface-velocity hook to wrap.

use rapier3d::prelude::*;

/// A box resting on a large fixed ground slab.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BoxOnGround {
    /// Half-extent of the cubic box (m).
    pub half: f32,
    /// Mass of the box (kg).
    pub mass: f32,
    /// Incline angle θ (rad): gravity is tilted about z so the slope runs down along +x.
    pub incline: f64,
    /// Gravity magnitude (m/s²); 0 for a box pressed by forces only.
    pub gravity: f32,
    /// Time step (s).
    pub dt: f32,
    /// Whether the box may rotate (off: pure sliding, no rocking on the compliant contact).
    pub rotations: bool,
}

impl Default for BoxOnGround {
    fn default() -> Self {
        BoxOnGround {
            half: 0.25,
            mass: 125.0,
            incline: 0.0,
            gravity: 9.81,
            dt: 1.0 / 60.0,
            rotations: true,
        }
    }
}

/// The handles of a [`BoxOnGround`] world.
pub struct BoxScene {
    /// The world.
    pub world: PhysicsWorld,
    /// The box.
    pub body: RigidBodyHandle,
    /// The box's collider.
    pub box_collider: ColliderHandle,
    /// The ground's collider (attach the friction modifier to it).
    pub ground: ColliderHandle,
}

impl BoxOnGround {
    /// Builds the world: ground top at y = 0.1, box resting on it, sleeping disabled (a
    /// sleeping box would hide creep), colliders' own friction 0.
    pub fn build(&self) -> BoxScene {
        let mut world = PhysicsWorld::default();
        world.integration_parameters.dt = self.dt;
        let (s, c) = (self.incline.sin() as f32, self.incline.cos() as f32);
        world.gravity = Vector::new(self.gravity * s, -self.gravity * c, 0.0);
        let ground = world.insert_collider(
            ColliderBuilder::cuboid(200.0, 0.1, 50.0).friction(0.0),
            None,
        );
        let h = self.half;
        let (body, box_collider) = world.insert(
            RigidBodyBuilder::dynamic()
                .translation(Vector::new(0.0, 0.1 + h, 0.0))
                .can_sleep(false)
                .enabled_rotations(self.rotations, self.rotations, self.rotations),
            ColliderBuilder::cuboid(h, h, h)
                .density(self.mass / (8.0 * h * h * h))
                .friction(0.0),
        );
        BoxScene {
            world,
            body,
            box_collider,
            ground,
        }
    }
}

impl BoxScene {
    /// Position of the box's centre along x (m).
    pub fn x(&self) -> f64 {
        self.world.bodies[self.body].translation().x as f64
    }

    /// Velocity of the box along x (m/s).
    pub fn vx(&self) -> f64 {
        self.world.bodies[self.body].linvel().x as f64
    }

    /// Replaces the user forces on the box by `force` (N, world).
    pub fn set_force(&mut self, force: Vector) {
        let b = &mut self.world.bodies[self.body];
        b.reset_forces(true);
        b.add_force(force, true);
    }
}

/// A conveyor: the `belt` collider's surface moves at `velocity` (world), through rapier's
/// per-contact target tangent velocity. Wrap it with [`crate::StickSlip::with_hooks`] and the
/// friction law works relative to the moving surface.
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
        if let Some(m) = ctx.rigid_mut() {
            for c in m.solver_contacts.iter_mut() {
                c.tangent_velocity = v;
            }
        }
    }
}
