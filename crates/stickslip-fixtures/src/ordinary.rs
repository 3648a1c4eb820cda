//! The scenes every rapier world is made of — things that roll, stack, topple and spin, on
//! grounds of every shape rapier has — built the same way for plain rapier and for stickslip, so
//! a test or a benchmark runs both side by side. Every collider gets the friction coefficient
//! `mu` (rapier's own friction, used when nothing is attached); gravity is tilted about z so a
//! slope of tan θ runs down along +x. The 2D build (cfg `dim2`) has what a plane has: the
//! cuboid ground, the pyramid and the brick wall, the dominoes.

use crate::{cuboid3, v3};
use stickslip_rapier::rapier::prelude::*;

/// A world with its ground and the bodies a scene measures.
pub struct OrdinaryScene {
    /// The world.
    pub world: PhysicsWorld,
    /// The ground's colliders (one, or the tiles of a compound).
    pub ground: Vec<ColliderHandle>,
    /// The dynamic bodies, in the scene's order.
    pub bodies: Vec<RigidBodyHandle>,
}

impl OrdinaryScene {
    /// Every collider of the world (ground and bodies): what a user attaches to give the whole
    /// scene stickslip's friction.
    pub fn all_colliders(&self) -> Vec<ColliderHandle> {
        self.world.colliders.iter().map(|(h, _)| h).collect()
    }

    /// Positions of the bodies.
    pub fn positions(&self) -> Vec<Vector> {
        self.bodies
            .iter()
            .map(|h| self.world.bodies[*h].translation())
            .collect()
    }
}

/// A world stepped at `dt` with gravity g tilted so that a slope of `tan_theta` runs down +x.
pub fn slope_world(tan_theta: f64, dt: f64) -> PhysicsWorld {
    let mut world = PhysicsWorld::default();
    world.integration_parameters.dt = dt as f32;
    let theta = tan_theta.atan();
    let g = 9.81f64;
    world.gravity = v3((g * theta.sin()) as f32, -(g * theta.cos()) as f32, 0.0);
    world
}

/// The shape of a ground whose top face is the plane y = 0 over |x|, |z| ≤ `half`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Ground {
    /// One cuboid.
    Cuboid,
    /// A triangle mesh of 1 m squares (two triangles each), `FIX_INTERNAL_EDGES`.
    #[cfg(not(dim2))]
    TriMesh,
    /// A flat heightfield of 1 m cells, `FIX_INTERNAL_EDGES`.
    #[cfg(not(dim2))]
    HeightField,
    /// A compound of 1 m square cuboid tiles.
    #[cfg(not(dim2))]
    Compound,
}

impl Ground {
    /// Inserts the ground (fixed, friction `mu`) and returns its collider.
    pub fn insert(self, world: &mut PhysicsWorld, half: f32, mu: f32) -> ColliderHandle {
        #[cfg(not(dim2))]
        let n = (2.0 * half).round().max(1.0) as usize;
        let builder = match self {
            Ground::Cuboid => cuboid3(half, 0.5, half).0.translation(v3(0.0, -0.5, 0.0)),
            #[cfg(not(dim2))]
            Ground::TriMesh => {
                let mut vertices = Vec::with_capacity((n + 1) * (n + 1));
                for i in 0..=n {
                    for k in 0..=n {
                        vertices.push(Vector::new(i as f32 - half, 0.0, k as f32 - half));
                    }
                }
                let at = |i: usize, k: usize| (i * (n + 1) + k) as u32;
                let mut indices = Vec::with_capacity(2 * n * n);
                for i in 0..n {
                    for k in 0..n {
                        indices.push([at(i, k), at(i, k + 1), at(i + 1, k)]);
                        indices.push([at(i + 1, k), at(i, k + 1), at(i + 1, k + 1)]);
                    }
                }
                // The flags only fail on degenerate input; this grid has none.
                ColliderBuilder::trimesh_with_flags(
                    vertices,
                    indices,
                    TriMeshFlags::FIX_INTERNAL_EDGES,
                )
                .expect("a regular grid is a valid triangle mesh")
            }
            #[cfg(not(dim2))]
            Ground::HeightField => ColliderBuilder::heightfield_with_flags(
                Array2::repeat(n + 1, n + 1, 0.0),
                Vector::new(2.0 * half, 1.0, 2.0 * half),
                HeightFieldFlags::FIX_INTERNAL_EDGES,
            ),
            #[cfg(not(dim2))]
            Ground::Compound => {
                let mut tiles = Vec::with_capacity(n * n);
                for i in 0..n {
                    for k in 0..n {
                        let centre =
                            Vector::new(i as f32 + 0.5 - half, -0.25, k as f32 + 0.5 - half);
                        tiles.push((
                            Pose::from_translation(centre),
                            SharedShape::cuboid(0.5, 0.25, 0.5),
                        ));
                    }
                }
                ColliderBuilder::compound(tiles)
            }
        };
        world.insert_collider(builder.friction(mu), None)
    }
}

/// A body that rolls: its cross-section is a circle of the given radius about z (in 2D:
/// the ball, a disc).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Roller {
    /// A solid ball.
    Ball,
    /// A solid cylinder lying on its side (axis along z, length 2 r).
    #[cfg(not(dim2))]
    Cylinder,
    /// A capsule lying on its side (axis along z, cylinder part 2 r long).
    #[cfg(not(dim2))]
    Capsule,
}

/// A [`Roller`] of radius `r` (m, density 1000) at rest on a ground of `ground` shape, on a
/// slope of `tan_theta`, all friction `mu`, stepped at `dt`. Bodies never sleep.
pub fn roller_on_slope(
    roller: Roller,
    r: f32,
    ground: Ground,
    tan_theta: f64,
    mu: f32,
    dt: f64,
) -> OrdinaryScene {
    let mut world = slope_world(tan_theta, dt);
    let ground = ground.insert(&mut world, 20.0, mu);
    let rot = AngVector::default();
    let (shape, rotation) = match roller {
        Roller::Ball => (ColliderBuilder::ball(r), rot),
        // rapier's cylinder and capsule builders run along y: a quarter turn about x lays
        // them along z.
        #[cfg(not(dim2))]
        Roller::Cylinder => (
            ColliderBuilder::cylinder(r, r),
            Vector::new(std::f32::consts::FRAC_PI_2, 0.0, 0.0),
        ),
        #[cfg(not(dim2))]
        Roller::Capsule => (ColliderBuilder::capsule_z(r, r), rot),
    };
    let body = world.insert_body(
        RigidBodyBuilder::dynamic()
            .translation(v3(-15.0, r, 0.0))
            .rotation(rotation)
            .can_sleep(false),
    );
    world.insert_collider(shape.density(1000.0).friction(mu), Some(body));
    OrdinaryScene {
        world,
        ground: vec![ground],
        bodies: vec![body],
    }
}

/// Moment of inertia over m r² about the roll axis (z in the world) of a body.
pub fn roll_inertia_ratio(world: &PhysicsWorld, body: RigidBodyHandle, r: f32) -> f64 {
    let b = &world.bodies[body];
    let props = b.mass_properties().local_mprops;
    // In 2D the principal inertia is about z.
    #[cfg(dim2)]
    let izz = props.principal_inertia();
    // The world's z axis in the body's frame, then I_zz = zᵀ I z.
    #[cfg(not(dim2))]
    let izz = {
        let z = b.rotation().inverse() * Vector::Z;
        let principal = props.principal_inertia_local_frame.inverse() * z;
        let i = props.principal_inertia();
        i.x * principal.x * principal.x
            + i.y * principal.y * principal.y
            + i.z * principal.z * principal.z
    };
    izz as f64 / (b.mass() as f64 * (r as f64).powi(2))
}

/// A stack of boxes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Stack {
    /// A pyramid of 0.5 m cubes, `size` on the bottom row (size (size+1)/2 boxes).
    Pyramid,
    /// A brick wall, `size` rows of bricks (0.4 × 0.2 × 0.2 m) in running bond: rows of 6
    /// bricks, and between them rows offset by half a brick, of 5 bricks and a half brick at
    /// each end.
    Wall,
    /// A plank tower: `size` crossed layers of 4 planks (1.6 × 0.1 × 0.2 m).
    #[cfg(not(dim2))]
    Tower,
    /// A tower in the layout of rapier's `keva3` example: `size` blocks (at most 3) of planks
    /// 0.1 × 0.5 × 2 m standing on edge, stacked from the widest, each block's layers crossed
    /// (planks of one direction end to end, of the other spaced) and its top closed by planks
    /// lying flat side by side. Three blocks: 444 planks, with faces that touch at zero gap.
    #[cfg(not(dim2))]
    Keva,
}

/// A [`Stack`] of `size` on a cuboid floor tilted to `tan_theta` (down +x), all friction `mu`,
/// stepped at `dt`. Bodies never sleep (a sleeping body would hide creep).
pub fn stack(kind: Stack, size: usize, tan_theta: f64, mu: f32, dt: f64) -> OrdinaryScene {
    let mut world = slope_world(tan_theta, dt);
    let ground = Ground::Cuboid.insert(&mut world, 20.0, mu);
    let mut bodies = Vec::new();
    let mut add = |world: &mut PhysicsWorld, at: Vector, half: Vector| {
        #[cfg(not(dim2))]
        let shape = ColliderBuilder::cuboid(half.x, half.y, half.z);
        #[cfg(dim2)]
        let shape = ColliderBuilder::cuboid(half.x, half.y);
        let (b, _) = world.insert(
            RigidBodyBuilder::dynamic().translation(at).can_sleep(false),
            shape.density(500.0).friction(mu),
        );
        bodies.push(b);
    };
    match kind {
        Stack::Pyramid => {
            let h = 0.25;
            for row in 0..size {
                let n = size - row;
                for i in 0..n {
                    let x = (i as f32 - (n - 1) as f32 / 2.0) * 2.0 * h;
                    let y = h + row as f32 * 2.0 * h;
                    add(&mut world, v3(x, y, 0.0), Vector::splat(h));
                }
            }
        }
        Stack::Wall => {
            let (hx, hy, hz) = (0.2, 0.1, 0.1);
            let half = v3(hx, hy, hz);
            // Running bond: every other row is offset by half a brick, with a half brick at
            // each end, so every brick rests with its centre of mass inside what carries it
            // (a row of six offset bricks had its end bricks' centres of mass right over the
            // edge below: plain rapier dropped one with contact recycling on and kept it with
            // recycling off).
            let half_brick = v3(hx / 2.0, hy, hz);
            for row in 0..size {
                let y = half.y + row as f32 * 2.0 * half.y;
                if row % 2 == 0 {
                    for i in 0..6 {
                        add(
                            &mut world,
                            v3((i as f32 - 2.5) * 2.0 * half.x, y, 0.0),
                            half,
                        );
                    }
                } else {
                    for i in 0..5 {
                        add(
                            &mut world,
                            v3((i as f32 - 2.0) * 2.0 * half.x, y, 0.0),
                            half,
                        );
                    }
                    for side in [-1.0, 1.0] {
                        let x = side * (5.0 * half.x + half_brick.x);
                        add(&mut world, v3(x, y, 0.0), half_brick);
                    }
                }
            }
        }
        #[cfg(not(dim2))]
        Stack::Tower => {
            let (long, thick, wide) = (0.8f32, 0.05f32, 0.1f32);
            for layer in 0..size {
                let y = thick + layer as f32 * 2.0 * thick;
                for i in 0..4 {
                    let across = (i as f32 - 1.5) * 0.4;
                    let (at, half) = if layer % 2 == 0 {
                        (Vector::new(0.0, y, across), Vector::new(long, thick, wide))
                    } else {
                        (Vector::new(across, y, 0.0), Vector::new(wide, thick, long))
                    };
                    add(&mut world, at, half);
                }
            }
        }
        #[cfg(not(dim2))]
        Stack::Keva => {
            let half = Vector::new(0.05, 0.25, 1.0);
            let mut base = 0.0;
            // (planks across a layer, layers) of each block, widest first.
            for (numx, numy) in [(3usize, 9usize), (2, 7), (1, 5)].into_iter().take(size) {
                base = keva_block(&mut world, &mut add, half, base, numx, numy);
            }
        }
    }
    OrdinaryScene {
        world,
        ground: vec![ground],
        bodies,
    }
}

/// One block of [`Stack::Keva`] (rapier's `keva3` `build_block`), centred on the y axis with
/// its bottom at `base`: returns the height of its top.
#[cfg(not(dim2))]
fn keva_block(
    world: &mut PhysicsWorld,
    add: &mut impl FnMut(&mut PhysicsWorld, Vector, Vector),
    half: Vector,
    base: f32,
    numx: usize,
    numy: usize,
) -> f32 {
    let dims = [half, Vector::new(half.z, half.y, half.x)];
    let width = 2.0 * half.z * numx as f32;
    let numz = 3 * numx + 1;
    let spacing = (half.z * numx as f32 - half.x) / (numz as f32 - 1.0);
    let shift = Vector::new(-width / 2.0, base, -width / 2.0);
    let (mut nx, mut nz) = (numx, numz);
    for i in 0..numy {
        std::mem::swap(&mut nx, &mut nz);
        let dim = dims[i % 2];
        let y = dim.y * i as f32 * 2.0;
        for j in 0..nx {
            let x = if i % 2 == 0 {
                spacing * j as f32 * 2.0
            } else {
                dim.x * j as f32 * 2.0
            };
            for k in 0..nz {
                let z = if i % 2 == 0 {
                    dim.z * k as f32 * 2.0
                } else {
                    spacing * k as f32 * 2.0
                };
                add(world, Vector::new(x, y, z) + dim + shift, dim);
            }
        }
    }
    // The top, closed by planks lying flat.
    let height = 2.0 * half.y * numy as f32;
    let dim = Vector::new(half.z, half.x, half.y);
    for i in 0..(width / (2.0 * dim.x)) as usize {
        for j in 0..(width / (2.0 * dim.z)) as usize {
            let at = Vector::new(2.0 * dim.x * i as f32, height, 2.0 * dim.z * j as f32);
            add(world, at + dim + shift, dim);
        }
    }
    base + height + 2.0 * dim.y
}

/// A box (2 × 0.2 × 2 m, mass `box_mass`) on level ground, carrying `balls` balls of radius
/// 0.1 m (mass `ball_mass` each) on its top, all friction `mu`. Body 0 is the box.
#[cfg(not(dim2))]
pub fn box_with_balls(
    balls: usize,
    box_mass: f32,
    ball_mass: f32,
    mu: f32,
    dt: f64,
) -> OrdinaryScene {
    let mut world = slope_world(0.0, dt);
    let ground = Ground::Cuboid.insert(&mut world, 30.0, mu);
    let half = Vector::new(1.0, 0.1, 1.0);
    let (carrier, _) = world.insert(
        RigidBodyBuilder::dynamic()
            .translation(Vector::new(0.0, half.y, 0.0))
            .can_sleep(false),
        ColliderBuilder::cuboid(half.x, half.y, half.z)
            .mass(box_mass)
            .friction(mu),
    );
    let mut bodies = vec![carrier];
    let r = 0.1f32;
    for i in 0..balls {
        let x = (i % 3) as f32 * 0.5 - 0.5;
        let z = (i / 3) as f32 * 0.5 - 0.5;
        let (b, _) = world.insert(
            RigidBodyBuilder::dynamic()
                .translation(Vector::new(x, 2.0 * half.y + r, z))
                .can_sleep(false),
            ColliderBuilder::ball(r).mass(ball_mass).friction(mu),
        );
        bodies.push(b);
    }
    OrdinaryScene {
        world,
        ground: vec![ground],
        bodies,
    }
}

/// The handles of a [`cart`]: the chassis is body 0, the four wheels bodies 1–4.
pub const CART_WHEEL_RADIUS: f32 = 0.2;

/// A cart on level ground: a 1.6 × 0.2 × 0.8 m chassis of `chassis_mass` on four solid
/// cylinder wheels (radius 0.2 m, width 0.1 m, mass `wheel_mass`) on revolute joints about z,
/// all friction `mu`. Body 0 is the chassis, bodies 1–4 the wheels.
#[cfg(not(dim2))]
pub fn cart(chassis_mass: f32, wheel_mass: f32, mu: f32, dt: f64) -> OrdinaryScene {
    let mut world = slope_world(0.0, dt);
    let ground = Ground::Cuboid.insert(&mut world, 30.0, mu);
    let r = CART_WHEEL_RADIUS;
    let y = r + 0.05;
    let (chassis, _) = world.insert(
        RigidBodyBuilder::dynamic()
            .translation(Vector::new(0.0, y, 0.0))
            .can_sleep(false),
        ColliderBuilder::cuboid(0.8, 0.1, 0.4)
            .mass(chassis_mass)
            .friction(mu),
    );
    let mut bodies = vec![chassis];
    for (x, z) in [(-0.6f32, -0.5f32), (-0.6, 0.5), (0.6, -0.5), (0.6, 0.5)] {
        let centre = Vector::new(x, r, z);
        let (wheel, _) = world.insert(
            RigidBodyBuilder::dynamic()
                .translation(centre)
                .rotation(Vector::new(std::f32::consts::FRAC_PI_2, 0.0, 0.0))
                .can_sleep(false),
            ColliderBuilder::cylinder(0.05, r)
                .mass(wheel_mass)
                .friction(mu),
        );
        let joint = RevoluteJointBuilder::new(Vector::Z)
            .local_anchor1(centre - Vector::new(0.0, y, 0.0))
            .local_anchor2(Vector::ZERO)
            .contacts_enabled(false);
        // The wheel's frame is turned a quarter about x: its own axis is y.
        let mut joint: GenericJoint = joint.into();
        joint.set_local_axis2(Vector::Y);
        world.insert_impulse_joint(chassis, wheel, joint);
        bodies.push(wheel);
    }
    OrdinaryScene {
        world,
        ground: vec![ground],
        bodies,
    }
}

/// A row of `count` dominoes (0.1 × 1.0 × 0.5 m, 0.5 m apart along x) standing on level
/// ground, all friction `mu`; the first one is tipped towards the others.
pub fn dominoes(count: usize, mu: f32, dt: f64) -> OrdinaryScene {
    let mut world = slope_world(0.0, dt);
    let ground = Ground::Cuboid.insert(&mut world, 30.0, mu);
    let mut bodies = Vec::with_capacity(count);
    for i in 0..count {
        let mut b = RigidBodyBuilder::dynamic()
            .translation(v3(i as f32 * 0.5, 0.5, 0.0))
            .can_sleep(false);
        if i == 0 {
            b = b.angvel(crate::dim::spin(-1.5));
        }
        let (h, _) = world.insert(b, cuboid3(0.05, 0.5, 0.25).0.density(700.0).friction(mu));
        bodies.push(h);
    }
    OrdinaryScene {
        world,
        ground: vec![ground],
        bodies,
    }
}

/// A 0.5 m cube (density 1000) on level ground spinning about the vertical at `spin` rad/s,
/// all friction `mu`.
#[cfg(not(dim2))]
pub fn spinning_box(spin: f32, mu: f32, dt: f64) -> OrdinaryScene {
    let mut world = slope_world(0.0, dt);
    let ground = Ground::Cuboid.insert(&mut world, 20.0, mu);
    let (b, _) = world.insert(
        RigidBodyBuilder::dynamic()
            .translation(Vector::new(0.0, 0.25, 0.0))
            .angvel(Vector::new(0.0, spin, 0.0))
            .can_sleep(false),
        ColliderBuilder::cuboid(0.25, 0.25, 0.25)
            .density(1000.0)
            .friction(mu),
    );
    OrdinaryScene {
        world,
        ground: vec![ground],
        bodies: vec![b],
    }
}

/// A 0.5 m cube (density 1000) resting on a ground of `ground` shape on a slope of
/// `tan_theta`, all friction `mu`, straddling the cell edge at z = 0 (on a mesh, heightfield
/// or compound it touches several cells from the start) near the origin (f32 positions
/// resolve sub-micrometre creep there).
pub fn box_on_slope(ground: Ground, tan_theta: f64, mu: f32, dt: f64) -> OrdinaryScene {
    let mut world = slope_world(tan_theta, dt);
    let ground = ground.insert(&mut world, 20.0, mu);
    let (b, _) = world.insert(
        RigidBodyBuilder::dynamic()
            .translation(v3(-0.3, 0.25, 0.0))
            .can_sleep(false),
        cuboid3(0.25, 0.25, 0.25).0.density(1000.0).friction(mu),
    );
    OrdinaryScene {
        world,
        ground: vec![ground],
        bodies: vec![b],
    }
}
