//! Per-contact reports (`ReadBack::Contacts`) are world-space facts about each contact patch
//! after the step. Invariants: a box resting anywhere on the ground, turned about the vertical
//! or not, reports its patch centroid at the centre of its bottom face (within 1 mm), also when
//! it rests on another dynamic box (rapier keeps dynamic bodies' solver anchors in body frames
//! after the hook, so anchors cannot be averaged); a box sliding (and tumbling) across the
//! ground reports the velocity of its material point there, v + ω × (p − c), as its slip
//! velocity (within 1e-4 m/s) under every law — stickslip's own target velocities (Regul's
//! creep, anchor corrections) are not a surface's motion; a box carried by a conveyor (a
//! wrapped hook moving the belt's surface) reports no slip against the belt. In 3D and in 2D
//! (stickslip-fixtures2d: boxes along x, not turned).

use stickslip_core::law::{FrictionLaw, Law, Physical, Regularization, Regularized};
use stickslip_core::sliding_curve::Curve;
use stickslip_fixtures::dim::point_velocity;
use stickslip_fixtures::{cuboid3, v3};
use stickslip_rapier::rapier::prelude::*;
use stickslip_rapier::{FrictionMaterial, ReadBack, StickSlip};

const HALF: f32 = 0.2;
const GROUND_TOP: f32 = 0.1;

fn modifier() -> StickSlip {
    let law = Law::elasto_plastic(1e4, 0.5, 0.55, Curve::constant(0.55).unwrap()).unwrap();
    StickSlip::new(FrictionMaterial::new(law)).with_read_back(ReadBack::Contacts)
}

/// A box resting at (x, y, z) turned by `yaw` about the vertical (2D: z and the turn dropped).
fn resting_box(world: &mut PhysicsWorld, x: f32, z: f32, yaw: f32, y: f32) -> ColliderHandle {
    #[cfg(not(dim2))]
    let turn = Vector::new(0.0, yaw, 0.0);
    #[cfg(dim2)]
    let turn = {
        let _ = yaw;
        0.0
    };
    world
        .insert(
            RigidBodyBuilder::dynamic()
                .translation(v3(x, y, z))
                .rotation(turn)
                .can_sleep(false),
            cuboid3(HALF, HALF, HALF).0.density(1000.0),
        )
        .1
}

#[test]
fn resting_boxes_report_their_patch_centroid_in_world_space() {
    let mut world = PhysicsWorld::default();
    let ground = world.insert_collider(cuboid3(20.0, GROUND_TOP, 20.0).0, None);
    let mut m = modifier();
    m.attach(&mut world.colliders, ground, None);
    let spots = [(5.0, 0.0, 0.0), (-3.0, 4.0, 0.6), (2.0, -6.0, 1.2)];
    let mut boxes = Vec::new();
    for &(x, z, yaw) in &spots {
        boxes.push(resting_box(&mut world, x, z, yaw, GROUND_TOP + HALF));
    }
    // A box stacked on the first one: a contact between two dynamic bodies (not hooked
    // unless attached).
    let top = resting_box(&mut world, 5.0, 0.0, 0.3, GROUND_TOP + 3.0 * HALF);
    m.attach(&mut world.colliders, top, None);
    for _ in 0..30 {
        m.step(&mut world);
    }
    for (&c, &(x, z, _)) in boxes.iter().zip(&spots) {
        let r = m
            .reports()
            .unwrap()
            .iter()
            .find(|r| {
                (r.collider1, r.collider2) == (ground, c)
                    || (r.collider1, r.collider2) == (c, ground)
            })
            .expect("a report for each box on the ground");
        let expect = [x, GROUND_TOP, z];
        let err = (0..r.point.len())
            .map(|i| (r.point[i] - expect[i]).abs())
            .fold(0.0, f32::max);
        assert!(err < 1e-3, "box at ({x}, {z}): point {:?}", r.point);
    }
    let r = m
        .reports()
        .unwrap()
        .iter()
        .find(|r| (r.collider1 == top) != (r.collider2 == top) && r.collider1 != ground)
        .expect("a report for the stacked box");
    let expect = [5.0, GROUND_TOP + 2.0 * HALF, 0.0];
    let err = (0..r.point.len())
        .map(|i| (r.point[i] - expect[i]).abs())
        .fold(0.0, f32::max);
    assert!(err < 1e-3, "stacked box: point {:?}", r.point);
}

#[test]
fn a_sliding_box_reports_its_velocity_as_slip() {
    let laws = [
        Law::elasto_plastic(1e4, 0.5, 0.55, Curve::constant(0.55).unwrap()).unwrap(),
        Law::Regularized(
            Regularized::new(Curve::constant(0.5).unwrap(), 0.01, Regularization::Linear).unwrap(),
        ),
        Law::Physical(Physical::new(0.5, Curve::constant(0.4).unwrap()).unwrap()),
    ];
    for law in laws {
        let mut world = PhysicsWorld::default();
        let ground = world.insert_collider(cuboid3(50.0, GROUND_TOP, 50.0).0, None);
        let mut m =
            StickSlip::new(FrictionMaterial::new(law.clone())).with_read_back(ReadBack::Contacts);
        m.attach(&mut world.colliders, ground, None);
        let c = resting_box(&mut world, -10.0, 0.0, 0.0, GROUND_TOP + HALF);
        let body = world.colliders[c].parent().unwrap();
        for _ in 0..10 {
            m.step(&mut world);
        }
        world.bodies[body].set_linvel(v3(3.0, 0.0, 1.0), true);
        for _ in 0..5 {
            m.step(&mut world);
            let b = &world.bodies[body];
            let r = m.reports().unwrap()[0];
            // v + ω × (p − c) at the reported point, in the ground's tangent plane (x, z; in
            // 2D the tangent line x).
            let v = point_velocity(b, Vector::from_array(r.point));
            let d = Vector::from_array(r.slip_velocity) - v;
            #[cfg(not(dim2))]
            let err = d.x.abs().max(d.z.abs());
            #[cfg(dim2)]
            let err = d.x.abs();
            assert!(v.x > 1.0, "{}: still sliding: {v:?}", law.name());
            assert!(
                err < 1e-4,
                "{}: slip {:?} vs velocity {v:?}",
                law.name(),
                r.slip_velocity
            );
        }
    }
}

#[test]
fn a_box_carried_by_a_conveyor_reports_no_slip_against_the_belt() {
    let mut world = PhysicsWorld::default();
    // The user flags the belt for their hook, as they would without stickslip.
    let belt = world.insert_collider(
        cuboid3(50.0, GROUND_TOP, 50.0)
            .0
            .active_hooks(ActiveHooks::MODIFY_SOLVER_CONTACTS),
        None,
    );
    let speed = v3(0.5, 0.0, 0.0);
    let law = Law::elasto_plastic(1e4, 0.5, 0.55, Curve::constant(0.55).unwrap()).unwrap();
    let conveyor = stickslip_fixtures::Conveyor {
        belt,
        velocity: speed,
    };
    let mut m = StickSlip::with_hooks(FrictionMaterial::new(law), conveyor)
        .with_read_back(ReadBack::Contacts);
    m.attach(&mut world.colliders, belt, None);
    let c = resting_box(&mut world, 0.0, 0.0, 0.0, GROUND_TOP + HALF);
    let body = world.colliders[c].parent().unwrap();
    for _ in 0..120 {
        m.step(&mut world);
    }
    // Carried along at the belt's speed, holding: the slip against the belt is the box's
    // velocity minus the surface's.
    let v = world.bodies[body].linvel();
    assert!((v - speed).length() < 1e-3, "carried at {v:?}");
    let r = m.reports().unwrap()[0];
    let slip = Vector::from_array(r.slip_velocity).length();
    assert!(slip < 1e-3, "slip against the belt {:?}", r.slip_velocity);
}
