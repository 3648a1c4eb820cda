//! Bad states in a running world never poison stickslip: random sequences of hostile
//! operations on a world of boxes on an EP ground with a vibration source — NaN, ±∞ and huge
//! velocities, positions and forces injected into bodies, steps with NaN, ±∞, zero, negative
//! and huge dt (skipped whole by `StickSlip::step`), colliders removed, detached and re-attached, materials and vibrations set on
//! handles that do not exist — interleaved with ordinary steps. After every step the
//! modifier's clock and world totals are finite and every contact report is finite; once
//! every body is put back into a finite state, a few steps later the world steps on with
//! finite contacts again. Deterministic (fixed seed, see `support/deterministic.rs`).

#[path = "support/deterministic.rs"]
mod support;

use proptest::prelude::*;
use rapier3d::prelude::*;
use stickslip::core::law::Law;
use stickslip::core::sliding_curve::Curve;
use stickslip::core::waveform::Waveform;
use stickslip::rapier::{
    Amplitude, ContactReport, FrictionMaterial, StickSlip, VibrationDirection, VibrationMode,
    VibrationSource,
};
use support::deterministic;

const HOSTILE: &[f32] = &[
    f32::NAN,
    f32::INFINITY,
    f32::NEG_INFINITY,
    f32::MAX,
    -f32::MAX,
    1e30,
    -1e30,
    1e-45,
    0.0,
];

#[derive(Debug, Clone)]
enum Op {
    Step,
    BadDt(f32),
    Velocity { body: usize, value: f32 },
    Position { body: usize, value: f32 },
    Force { body: usize, value: f32 },
    RemoveCollider(usize),
    Detach(usize),
    Reattach(usize),
    ForgedHandle(u32),
}

fn op() -> impl Strategy<Value = Op> {
    let hostile = prop::sample::select(HOSTILE);
    prop_oneof![
        8 => Just(Op::Step),
        1 => prop::sample::select(vec![f32::NAN, f32::INFINITY, -1.0, 0.0, 1e30, -f32::MAX, 1e-45])
            .prop_map(Op::BadDt),
        2 => (0usize..4, hostile.clone()).prop_map(|(body, value)| Op::Velocity { body, value }),
        1 => (0usize..4, hostile.clone()).prop_map(|(body, value)| Op::Position { body, value }),
        1 => (0usize..4, hostile).prop_map(|(body, value)| Op::Force { body, value }),
        1 => (0usize..5).prop_map(Op::RemoveCollider),
        1 => (0usize..5).prop_map(Op::Detach),
        1 => (0usize..5).prop_map(Op::Reattach),
        1 => any::<u32>().prop_map(Op::ForgedHandle),
    ]
}

fn material() -> FrictionMaterial {
    FrictionMaterial::new(
        Law::elasto_plastic(1e5, 0.5, 0.55, Curve::constant(0.45).unwrap()).unwrap(),
    )
}

fn vibration(mode: VibrationMode) -> VibrationSource {
    VibrationSource::new(
        VibrationDirection::Normal,
        Amplitude::Ratio(0.4),
        50.0,
        Waveform::Sine,
        0.0,
        mode,
    )
    .unwrap()
}

fn finite_report(r: &ContactReport) -> bool {
    [r.mu, r.limit, r.normal_force, r.dissipated_power]
        .iter()
        .all(|x| x.is_finite())
        && r.friction_force.iter().all(|x| x.is_finite())
        && r.slip_velocity.iter().all(|x| x.is_finite())
        && r.point.iter().all(|x| x.is_finite())
        && r.normal.iter().all(|x| x.is_finite())
}

fn check(m: &StickSlip, when: &str) -> Result<(), TestCaseError> {
    prop_assert!(m.time().is_finite(), "{when}: clock {}", m.time());
    let t = m.totals().unwrap();
    prop_assert!(
        t.dissipated_energy.is_finite()
            && t.dissipated_power.is_finite()
            && t.normal_force.is_finite()
            && t.friction_force.is_finite(),
        "{when}: totals {t:?}"
    );
    for r in m.reports().unwrap() {
        prop_assert!(finite_report(r), "{when}: report {r:?}");
    }
    Ok(())
}

proptest! {
    #![proptest_config(deterministic(96))]

    #[test]
    fn hostile_operations_never_poison_the_friction_state(
        ops in prop::collection::vec(op(), 1..40),
        averaged in any::<bool>(),
    ) {
        let mut world = PhysicsWorld::default();
        world.integration_parameters.dt = 1.0 / 240.0;
        let ground = world.insert_collider(ColliderBuilder::cuboid(20.0, 0.1, 20.0), None);
        let mut bodies = Vec::new();
        let mut colliders = vec![ground];
        for i in 0..4 {
            let (b, c) = world.insert(
                RigidBodyBuilder::dynamic()
                    .translation(Vector::new(i as f32 * 0.5, 0.2, 0.0))
                    .can_sleep(false),
                ColliderBuilder::cuboid(0.1, 0.1, 0.1).density(500.0),
            );
            bodies.push(b);
            colliders.push(c);
        }
        let mode = if averaged { VibrationMode::Averaged } else { VibrationMode::TimeResolved };
        let mut m = StickSlip::new(material()).with_read_back(stickslip::rapier::ReadBack::Contacts);
        m.attach(&mut world.colliders, ground, None);
        m.set_vibration(ground, vibration(mode));
        for _ in 0..30 {
            m.step(&mut world);
        }
        check(&m, "settled")?;

        for (k, op) in ops.iter().enumerate() {
            let when = format!("op {k} {op:?}");
            match *op {
                Op::Step => m.step(&mut world),
                Op::BadDt(dt) => {
                    // Skipped whole: neither the clock nor any body moves.
                    let good = world.integration_parameters.dt;
                    let before = m.time();
                    let poses: Vec<_> = bodies.iter().map(|b| world.bodies[*b].translation()).collect();
                    world.integration_parameters.dt = dt;
                    m.step(&mut world);
                    world.integration_parameters.dt = good;
                    prop_assert_eq!(m.time().to_bits(), before.to_bits(), "{}: the clock moved", when);
                    for (b, p) in bodies.iter().zip(&poses) {
                        let now = world.bodies[*b].translation();
                        prop_assert!(
                            now == *p || (now.is_nan() && p.is_nan()),
                            "{}: a body moved", when
                        );
                    }
                }
                Op::Velocity { body, value } => {
                    world.bodies[bodies[body]].set_linvel(Vector::new(value, 0.0, value), true);
                }
                Op::Position { body, value } => {
                    world.bodies[bodies[body]].set_translation(Vector::new(value, 0.2, 0.0), true);
                }
                Op::Force { body, value } => {
                    world.bodies[bodies[body]].add_force(Vector::new(value, 0.0, 0.0), true);
                }
                Op::RemoveCollider(i) => {
                    m.detach(&mut world.colliders, colliders[i]);
                    world.remove_collider(colliders[i]);
                }
                Op::Detach(i) => m.detach(&mut world.colliders, colliders[i]),
                Op::Reattach(i) => {
                    m.attach(&mut world.colliders, colliders[i], Some(material()));
                    m.set_vibration(colliders[i], vibration(mode));
                }
                Op::ForgedHandle(raw) => {
                    let h = ColliderHandle::from_raw_parts(raw, raw % 7);
                    m.attach(&mut world.colliders, h, Some(material()));
                    m.set_material(h, material());
                    m.set_vibration(h, vibration(mode));
                    m.detach(&mut world.colliders, h);
                }
            }
            check(&m, &when)?;
        }

        // Repair: every body back to a finite rest state above the ground, forces cleared.
        for (i, b) in bodies.iter().enumerate() {
            let body = &mut world.bodies[*b];
            body.reset_forces(true);
            body.set_translation(Vector::new(i as f32 * 0.5, 0.2, 0.0), true);
            body.set_rotation(Rotation::IDENTITY, true);
            body.set_linvel(Vector::ZERO, true);
            body.set_angvel(Vector::ZERO, true);
        }
        for _ in 0..60 {
            m.step(&mut world);
        }
        check(&m, "after the repair")?;
        for b in &bodies {
            let body = &world.bodies[*b];
            prop_assert!(
                body.translation().is_finite() && body.linvel().is_finite(),
                "after the repair: body {:?} {:?}",
                body.translation(),
                body.linvel()
            );
        }
    }
}
