//! Bad input in a running world never crashes, allocates by an untrusted number or poisons
//! the friction state. Invariants (regressions of reported failures): `attach`,
//! `set_material` and `set_vibration` with a handle that is not in the collider set
//! (`ColliderHandle::invalid()`, a huge index) are no-ops that allocate nothing; a step with a
//! NaN, infinite or negative dt leaves the modifier's clock, totals and contact states as they
//! were; NaN, infinite or absurd (f32::MAX) velocities injected into a body never reach the
//! friction state (its contact is reset and reported with `reset`, every report and total
//! stays finite) and the contacts of other bodies carry on unchanged; parameters that would
//! overflow (or underflow) in a step — c·F_n beyond range, force amplitudes of 1e39 N,
//! sliding curves reaching 1e30 — are refused by the constructors with the parameter's name
//! and its admissible range.
#![cfg(not(dim2))] // no 2D form yet: stickslip-fixtures2d compiles it empty

use stickslip_core::law::Law;
use stickslip_core::sliding_curve::Curve;
use stickslip_core::waveform::Waveform;
use stickslip_fixtures::BoxOnGround;
use stickslip_rapier::rapier::prelude::*;
use stickslip_rapier::{
    Amplitude, FrictionMaterial, StickSlip, VibrationDirection, VibrationMode, VibrationSource,
};

fn material() -> FrictionMaterial {
    FrictionMaterial::new(
        Law::elasto_plastic(1e5, 0.5, 0.5, Curve::constant(0.4).unwrap()).unwrap(),
    )
}

#[test]
fn handles_outside_the_collider_set_are_no_ops() {
    let mut scene = BoxOnGround::default().build();
    let mut m = StickSlip::new(material()).with_read_back(stickslip_rapier::ReadBack::Contacts);
    let forged = ColliderHandle::from_raw_parts(u32::MAX - 1, 7);
    for h in [ColliderHandle::invalid(), forged] {
        m.attach(&mut scene.world.colliders, h, Some(material()));
        m.set_material(h, material());
        let src = VibrationSource::new(
            VibrationDirection::Normal,
            Amplitude::Ratio(0.3),
            50.0,
            Waveform::Sine,
            0.0,
            VibrationMode::Averaged,
        )
        .unwrap();
        m.set_vibration(h, src);
        assert!(m.vibration(h).is_none());
        m.detach(&mut scene.world.colliders, h);
    }
    m.attach(&mut scene.world.colliders, scene.ground, None);
    for _ in 0..10 {
        m.step(&mut scene.world);
    }
    assert_eq!(m.active_contacts(), 1);
}

#[test]
fn bad_time_steps_leave_the_modifier_untouched() {
    let mut scene = BoxOnGround::default().build();
    let mut m = StickSlip::new(material()).with_read_back(stickslip_rapier::ReadBack::Contacts);
    m.attach(&mut scene.world.colliders, scene.ground, None);
    scene.set_force(Vector::new(20.0, 0.0, 0.0));
    for _ in 0..30 {
        m.step(&mut scene.world);
    }
    let (time, totals) = (m.time(), m.totals().unwrap());
    for bad in [f32::NAN, f32::INFINITY, -1.0 / 60.0, 0.0] {
        let mut params = scene.world.integration_parameters;
        params.dt = bad;
        m.begin_step(&params, &scene.world.bodies, &mut scene.world.colliders);
        // (rapier itself is not stepped with the bad dt here: that is the caller's business)
        m.end_step(
            &scene.world.narrow_phase,
            &scene.world.bodies,
            &mut scene.world.colliders,
        );
        assert_eq!(m.time(), time, "dt {bad}");
        assert_eq!(
            m.totals().unwrap().dissipated_energy,
            totals.dissipated_energy
        );
    }
    for _ in 0..10 {
        m.step(&mut scene.world);
    }
    assert!(m.time().is_finite() && m.totals().unwrap().dissipated_energy.is_finite());
    assert!(m.time() > time);
}

#[test]
fn nan_velocities_never_reach_the_friction_state() {
    let mut world = PhysicsWorld::default();
    world.insert_collider(ColliderBuilder::cuboid(20.0, 0.1, 20.0), None);
    let mut boxes = Vec::new();
    for i in 0..2 {
        let (b, _) = world.insert(
            RigidBodyBuilder::dynamic()
                .translation(Vector::new(3.0 * i as f32, 0.3, 0.0))
                .can_sleep(false),
            ColliderBuilder::cuboid(0.2, 0.2, 0.2).density(1000.0),
        );
        boxes.push(b);
    }
    let mut m = StickSlip::new(material()).with_read_back(stickslip_rapier::ReadBack::Contacts);
    // Every collider attached: a quiet box given a velocity between steps is hooked at once
    // (an unattached one would be seen after its step, see the `recycle` docs).
    let all: Vec<_> = world.colliders.iter().map(|(h, _)| h).collect();
    for h in all {
        m.attach(&mut world.colliders, h, None);
    }
    for _ in 0..20 {
        m.step(&mut world);
    }
    // A finite but absurd velocity first (impulses overflow f32), then NaN and ∞.
    let mut seen_reset = false;
    for v in [
        Vector::new(-f32::MAX, 0.0, 0.0),
        Vector::new(f32::NAN, 0.0, f32::INFINITY),
    ] {
        world.bodies[boxes[0]].set_linvel(v, true);
        for _ in 0..5 {
            m.step(&mut world);
            for r in m.reports().unwrap() {
                let numbers = [r.mu, r.limit, r.normal_force, r.dissipated_power];
                assert!(numbers.iter().all(|x| x.is_finite()), "{r:?}");
                assert!(r.friction_force.iter().all(|x| x.is_finite()), "{r:?}");
                assert!(r.slip_velocity.iter().all(|x| x.is_finite()), "{r:?}");
                seen_reset |= r.reset;
            }
            let t = m.totals().unwrap();
            assert!(
                t.dissipated_energy.is_finite() && t.friction_force.is_finite(),
                "{t:?}"
            );
        }
    }
    // The poisoned contact is reported as reset while it touches the ground.
    assert!(seen_reset, "a reset contact is reported");
    // The healthy box still rests where it was.
    let p = world.bodies[boxes[1]].translation();
    assert!(p.is_finite() && (p.x - 3.0).abs() < 1e-3, "{p:?}");
}

#[test]
fn parameters_that_overflow_in_use_are_refused_with_the_reason() {
    use stickslip_core::ParamError;
    use stickslip_core::law::{Physical, Regularization, Regularized};
    let range = |e: ParamError| match e {
        ParamError::OutOfRange { name, min, max, .. } => (name, min, max),
        other => panic!("not a range error: {other}"),
    };
    let c = Curve::constant(0.4).unwrap();
    // c·F_n beyond range (and g_ba below any roughness).
    let e = Law::elasto_plastic(1e300, 0.5, 0.5, c.clone()).unwrap_err();
    assert_eq!(range(e.clone()), ("c", 1e-3, 1e12));
    assert!(e.to_string().contains("c"), "{e}");
    // Sliding curves reaching 1e30, coefficients too small to be a friction limit in f32.
    assert_eq!(range(Curve::constant(1e30).unwrap_err()).0, "mu");
    assert_eq!(
        range(Curve::table(vec![0.0, 1.0], vec![0.4, 1e30]).unwrap_err()).0,
        "mu"
    );
    assert_eq!(
        range(
            Curve::stribeck(
                0.5,
                1e30,
                0.01,
                stickslip_core::sliding_curve::StribeckDecay::Gaussian,
                0.0
            )
            .unwrap_err()
        )
        .0,
        "mu_k"
    );
    assert_eq!(
        range(Physical::new(1e-42, c.clone()).unwrap_err()).0,
        "mu_ba"
    );
    assert_eq!(
        range(Regularized::new(c.clone(), 1e38, Regularization::Linear).unwrap_err()).0,
        "v_reg"
    );
    // Vibration amplitudes of 1e39 N, frequencies and ratios beyond any machine.
    let source = |a, f| {
        VibrationSource::new(
            VibrationDirection::Normal,
            a,
            f,
            Waveform::Sine,
            0.0,
            VibrationMode::TimeResolved,
        )
    };
    assert_eq!(
        range(source(Amplitude::Force(1e39), 100.0).unwrap_err()).0,
        "amplitude force"
    );
    assert_eq!(
        range(source(Amplitude::Ratio(1e39), 100.0).unwrap_err()).0,
        "amplitude ratio"
    );
    assert_eq!(
        range(source(Amplitude::Ratio(0.5), 1e300).unwrap_err()).0,
        "frequency"
    );
    // The bounds themselves are accepted.
    assert!(Law::elasto_plastic(1e12, 1e3, 1e3, Curve::constant(1e3).unwrap()).is_ok());
    assert!(source(Amplitude::Force(stickslip_rapier::MAX_FORCE), 1e9).is_ok());
}
