//! Scenes after rapier's own `examples3d` (see the parent module's docs): what a new user
//! ports first, with stickslip attached to every collider.

use super::{Driver, MU, Scene};
use rapier3d::prelude::*;

/// Builds `scene` into `world`, pushes every collider stickslip attaches to, and returns the
/// collider a vibration source goes on (the ground, drum or first platform).
pub fn build(
    scene: Scene,
    world: &mut PhysicsWorld,
    hooked: &mut Vec<ColliderHandle>,
    drivers: &mut Vec<Driver>,
) -> ColliderHandle {
    match scene {
        Scene::Drum { cubes } => drum(world, hooked, cubes),
        Scene::Heightfield { bodies } => heightfield(world, hooked, bodies),
        Scene::Compounds { bodies } => compounds(world, hooked, bodies),
        Scene::Platforms { boxes } => platforms(world, hooked, drivers, boxes),
        Scene::Dominoes { count } => dominoes(world, hooked, count),
        Scene::Keva => keva(world, hooked),
        _ => unreachable!("not a scene after rapier's examples: {scene:?}"),
    }
}

fn insert(
    world: &mut PhysicsWorld,
    hooked: &mut Vec<ColliderHandle>,
    body: RigidBodyBuilder,
    collider: ColliderBuilder,
) -> (RigidBodyHandle, ColliderHandle) {
    let (b, c) = world.insert(body, collider.friction(MU));
    hooked.push(c);
    (b, c)
}

/// A closed drum (r 3 m, 3 m long: 24 staves and two end plates, one compound) on a
/// velocity-based kinematic body turning at 1 rad/s about z, filled with a cube grid.
fn drum(
    world: &mut PhysicsWorld,
    hooked: &mut Vec<ColliderHandle>,
    cubes: usize,
) -> ColliderHandle {
    let (radius, half_len, staves) = (3.0f32, 1.5f32, 24);
    let mut parts = Vec::new();
    let chord = 2.0 * radius * (std::f32::consts::PI / staves as f32).tan();
    for k in 0..staves {
        let a = k as f32 * std::f32::consts::TAU / staves as f32;
        let pose = Pose::from_parts(
            Vector::new(a.cos() * (radius + 0.1), a.sin() * (radius + 0.1), 0.0),
            Rotation::from_axis_angle(Vector::Z, a),
        );
        parts.push((
            pose,
            SharedShape::cuboid(0.1, chord * 0.5 + 0.05, half_len + 0.2),
        ));
    }
    for z in [-1.0f32, 1.0] {
        let pose = Pose::from_translation(Vector::new(0.0, 0.0, z * (half_len + 0.1)));
        parts.push((pose, SharedShape::cuboid(radius + 0.2, radius + 0.2, 0.1)));
    }
    let (_, drum) = insert(
        world,
        hooked,
        RigidBodyBuilder::kinematic_velocity_based()
            .translation(Vector::new(0.0, 4.0, 0.0))
            .angvel(Vector::new(0.0, 0.0, 1.0)),
        ColliderBuilder::compound(parts),
    );
    let side = (cubes as f64).cbrt().ceil() as usize;
    let (half, gap) = (0.1f32, 0.25f32);
    for k in 0..cubes {
        let (i, j, l) = (k % side, (k / side) % side, k / (side * side));
        let c = |i: usize| (i as f32 - (side - 1) as f32 * 0.5) * gap;
        insert(
            world,
            hooked,
            RigidBodyBuilder::dynamic().translation(Vector::new(c(i), 4.0 + c(l), c(j))),
            ColliderBuilder::cuboid(half, half, half),
        );
    }
    drum
}

/// Where body `k` of a heap starts: layers of 8 × 8, `spacing` apart, the lowest at `base`,
/// each `layer` above the last.
fn dropped(k: usize, spacing: f32, base: f32, layer: f32) -> Vector {
    let (i, j, l) = (k % 8, (k / 8) % 8, k / 64);
    Vector::new(
        (i as f32 - 3.5) * spacing,
        base + l as f32 * layer,
        (j as f32 - 3.5) * spacing,
    )
}

/// Boxes, balls and capsules (in turn) dropped in layers of 8 × 8 over a 40 m heightfield of
/// gentle waves (50 × 50 cells).
fn heightfield(
    world: &mut PhysicsWorld,
    hooked: &mut Vec<ColliderHandle>,
    bodies: usize,
) -> ColliderHandle {
    let n = 51;
    let mut heights = Vec::with_capacity(n * n);
    for i in 0..n {
        for j in 0..n {
            let (x, z) = (i as f32 / 5.0, j as f32 / 5.0);
            heights.push(x.sin() * z.cos() * 0.5);
        }
    }
    let ground = world.insert_collider(
        ColliderBuilder::heightfield(Array2::new(n, n, heights), Vector::new(40.0, 1.0, 40.0))
            .friction(MU),
        None,
    );
    hooked.push(ground);
    for k in 0..bodies {
        let at = dropped(k, 1.2, 2.0, 1.2);
        let shape = match k % 3 {
            0 => ColliderBuilder::cuboid(0.3, 0.3, 0.3),
            1 => ColliderBuilder::ball(0.3),
            _ => ColliderBuilder::capsule_y(0.2, 0.25),
        };
        insert(
            world,
            hooked,
            RigidBodyBuilder::dynamic().translation(at),
            shape,
        );
    }
    ground
}

/// U-shaped compounds (a 1 m base and two 0.6 m uprights) dropped in layers of 8 × 8; they
/// would sleep within the settle steps, so they do not (the heap's contacts are measured).
fn compounds(
    world: &mut PhysicsWorld,
    hooked: &mut Vec<ColliderHandle>,
    bodies: usize,
) -> ColliderHandle {
    let ground = world.insert_collider(
        ColliderBuilder::cuboid(30.0, 0.1, 30.0)
            .translation(Vector::new(0.0, -0.1, 0.0))
            .friction(MU),
        None,
    );
    hooked.push(ground);
    for k in 0..bodies {
        let at = dropped(k, 1.5, 0.5, 1.0);
        let parts = vec![
            (Pose::IDENTITY, SharedShape::cuboid(0.5, 0.1, 0.25)),
            (
                Pose::from_translation(Vector::new(-0.4, 0.4, 0.0)),
                SharedShape::cuboid(0.1, 0.3, 0.25),
            ),
            (
                Pose::from_translation(Vector::new(0.4, 0.4, 0.0)),
                SharedShape::cuboid(0.1, 0.3, 0.25),
            ),
        ];
        insert(
            world,
            hooked,
            RigidBodyBuilder::dynamic().translation(at).can_sleep(false),
            ColliderBuilder::compound(parts),
        );
    }
    ground
}

/// Six 3 m platforms on position-based kinematic bodies swinging along x, carrying the boxes
/// in 4-high stacks (3 × 3 stacks a platform).
fn platforms(
    world: &mut PhysicsWorld,
    hooked: &mut Vec<ColliderHandle>,
    drivers: &mut Vec<Driver>,
    boxes: usize,
) -> ColliderHandle {
    let mut first = None;
    for p in 0..6 {
        let origin = Vector::new(0.0, 0.0, (p as f32 - 2.5) * 5.0);
        let (body, c) = insert(
            world,
            hooked,
            RigidBodyBuilder::kinematic_position_based().translation(origin),
            ColliderBuilder::cuboid(1.5, 0.1, 1.5),
        );
        first.get_or_insert(c);
        drivers.push(Driver {
            body,
            origin,
            direction: Vector::X,
            amplitude: 1.0,
            frequency: 0.2,
        });
    }
    let per_platform = boxes.div_ceil(6);
    for k in 0..boxes {
        let (p, r) = (k / per_platform, k % per_platform);
        let (stack, level) = (r / 4, r % 4);
        let at = Vector::new(
            ((stack % 3) as f32 - 1.0) * 0.9,
            0.1 + 0.25 + level as f32 * 0.5,
            (p as f32 - 2.5) * 5.0 + ((stack / 3) as f32 - 1.0) * 0.9,
        );
        insert(
            world,
            hooked,
            RigidBodyBuilder::dynamic().translation(at),
            ColliderBuilder::cuboid(0.25, 0.25, 0.25),
        );
    }
    first.expect("six platforms")
}

/// Dominoes (0.1 × 1 × 0.5 m, 0.5 m apart) in rows of 100 on a ground, the first of each row
/// pushed over with 1 rad/s; sleeping off, so the wave and the rows leaning on each other
/// after it are measured, not a sleeping world.
fn dominoes(
    world: &mut PhysicsWorld,
    hooked: &mut Vec<ColliderHandle>,
    count: usize,
) -> ColliderHandle {
    let rows = count.div_ceil(100);
    let ground = world.insert_collider(
        ColliderBuilder::cuboid(40.0, 0.1, rows as f32 + 2.0)
            .translation(Vector::new(20.0, -0.1, rows as f32 * 0.5))
            .friction(MU),
        None,
    );
    hooked.push(ground);
    for k in 0..count {
        let (i, row) = (k % 100, k / 100);
        let mut body = RigidBodyBuilder::dynamic()
            .translation(Vector::new(i as f32 * 0.5, 0.5, row as f32 * 1.0))
            .can_sleep(false);
        if i == 0 {
            body = body.angvel(Vector::new(0.0, 0.0, -1.0));
        }
        insert(
            world,
            hooked,
            body,
            ColliderBuilder::cuboid(0.05, 0.5, 0.25),
        );
    }
    ground
}

/// The tower of `stickslip_fixtures::ordinary::stack(Stack::Keva, 3, ..)` on level ground: 444 planks.
fn keva(world: &mut PhysicsWorld, hooked: &mut Vec<ColliderHandle>) -> ColliderHandle {
    use stickslip_fixtures::ordinary::{Stack, stack};
    let scene = stack(Stack::Keva, 3, 0.0, MU, 1.0 / 60.0);
    *world = scene.world;
    hooked.extend(world.colliders.iter().map(|(h, _)| h));
    scene.ground[0]
}
