//! Bad input in a running rapier world, 3D and 2D (stickslip-fixtures2d), never panics,
//! allocates by an untrusted number or poisons the friction state. Invariants (regressions of
//! reported failures):
//! - a `StickSlip::step` whose dt is not a time step (NaN, ±∞, negative, 0, beyond `MAX_DT`,
//!   below `MIN_DT`) is skipped: the bodies, the modifier's whole saved state (its snapshot
//!   bytes), its clock, totals and reports are bit for bit what they were; `begin_step` /
//!   `end_step` around such a dt leave the time, the dissipated energy and the last step's
//!   reports and totals alone, and the world continues bit for bit as if they had never
//!   been called;
//! - `attach`, `set_material`, `set_vibration`, `detach` with a handle that is not in the
//!   collider set (`ColliderHandle::invalid()`, a forged index, a removed collider's stale
//!   handle) are no-ops; what cannot be answered is a typed error (`NotReadBack` for reports
//!   and totals that are not read back, `SnapshotError` for bytes that are not a snapshot);
//! - NaN, infinite or absurd (f32::MAX) velocities injected into a body never reach the
//!   friction state: its contact is reported `reset`, every report and total stays finite,
//!   the modifier's state still passes `StickSlip::restore`'s validation (which requires
//!   finite state), and the other bodies' contacts carry on;
//! - parameters that would overflow (or underflow) in a step — c·F_n beyond range, force
//!   amplitudes of 1e39 N, sliding curves reaching 1e30 — are refused by the constructors with
//!   the parameter's name and its admissible range.

use stickslip_core::law::Law;
use stickslip_core::sliding_curve::Curve;
use stickslip_core::waveform::Waveform;
use stickslip_fixtures::dim::{spin, world_bits};
use stickslip_fixtures::{BoxOnGround, BoxScene, cuboid3, v3};
use stickslip_rapier::rapier::prelude::*;
use stickslip_rapier::snapshot::SnapshotError;
use stickslip_rapier::{
    Amplitude, FrictionMaterial, MAX_DT, MIN_DT, NotReadBack, ReadBack, StickSlip,
    VibrationDirection, VibrationMode, VibrationSource, WorldSnapshot, valid_dt,
};

fn material() -> FrictionMaterial {
    FrictionMaterial::new(
        Law::elasto_plastic(1e5, 0.5, 0.5, Curve::constant(0.4).unwrap()).unwrap(),
    )
}

fn source() -> VibrationSource {
    VibrationSource::new(
        VibrationDirection::Normal,
        Amplitude::Ratio(0.3),
        50.0,
        Waveform::Sine,
        0.0,
        VibrationMode::Averaged,
    )
    .unwrap()
}

const BAD_DTS: [f32; 8] = [
    f32::NAN,
    f32::INFINITY,
    f32::NEG_INFINITY,
    -1.0 / 60.0,
    0.0,
    2.0 * MAX_DT as f32,
    1e-12,
    f32::MAX,
];

fn modifier_bytes(m: &StickSlip) -> Vec<u8> {
    let mut bytes = Vec::new();
    m.snapshot().save(&mut bytes).unwrap();
    bytes
}

/// A box sliding down an incline (tan θ 0.8, above break-away): contacts with live state.
fn sliding_scene() -> (BoxScene, StickSlip) {
    let mut scene = BoxOnGround {
        incline: 0.8f64.atan(),
        ..BoxOnGround::default()
    }
    .build();
    let law = Law::elasto_plastic(1e4, 0.5, 0.55, Curve::constant(0.4).unwrap()).unwrap();
    let mut m = StickSlip::new(FrictionMaterial::new(law)).with_read_back(ReadBack::Contacts);
    m.attach(&mut scene.world.colliders, scene.ground, None);
    m.attach(&mut scene.world.colliders, scene.box_collider, None);
    (scene, m)
}

#[test]
fn steps_with_an_invalid_dt_are_skipped_without_any_change() {
    for dt in BAD_DTS {
        assert!(!valid_dt(dt as f64), "{dt} is a time step");
    }
    assert!(valid_dt(MIN_DT) && valid_dt(MAX_DT) && valid_dt(1.0 / 60.0));
    let (mut scene, mut m) = sliding_scene();
    for _ in 0..30 {
        m.step(&mut scene.world);
    }
    let good = scene.world.integration_parameters.dt;
    let (bodies, state) = (world_bits(&scene.world), modifier_bytes(&m));
    let (time, totals, reports) = (m.time(), m.totals().unwrap(), m.reports().unwrap().to_vec());
    assert_eq!(reports.len(), 1);
    for bad in BAD_DTS {
        scene.world.integration_parameters.dt = bad;
        m.step(&mut scene.world);
        assert_eq!(world_bits(&scene.world), bodies, "dt {bad}: rapier stepped");
        assert!(
            modifier_bytes(&m) == state,
            "dt {bad}: the modifier's state changed"
        );
        assert_eq!(m.time().to_bits(), time.to_bits(), "dt {bad}");
        assert_eq!(m.totals().unwrap(), totals, "dt {bad}");
        assert_eq!(m.reports().unwrap(), reports.as_slice(), "dt {bad}");
    }
    scene.world.integration_parameters.dt = good;
    let x = scene.x();
    for _ in 0..10 {
        m.step(&mut scene.world);
    }
    assert!(
        scene.x() > x,
        "the box stopped sliding after the skipped steps"
    );
    assert!(m.time() > time && m.totals().unwrap().dissipated_energy.is_finite());
}

#[test]
fn begin_and_end_step_around_an_invalid_dt_change_nothing_that_follows() {
    let (mut control, mut m_control) = sliding_scene();
    let (mut scene, mut m) = sliding_scene();
    for _ in 0..30 {
        m_control.step(&mut control.world);
        m.step(&mut scene.world);
    }
    let (time, energy) = (m.time(), m.totals().unwrap().dissipated_energy);
    for bad in BAD_DTS {
        let mut params = scene.world.integration_parameters;
        params.dt = bad;
        m.begin_step(&params, &scene.world.bodies, &mut scene.world.colliders);
        // (rapier itself is not stepped with the bad dt here: that is the caller's.)
        m.end_step(
            &scene.world.narrow_phase,
            &scene.world.bodies,
            &mut scene.world.colliders,
        );
        assert_eq!(m.time().to_bits(), time.to_bits(), "dt {bad}");
        assert_eq!(
            m.totals().unwrap().dissipated_energy.to_bits(),
            energy.to_bits(),
            "dt {bad}"
        );
    }
    for k in 0..120 {
        m_control.step(&mut control.world);
        m.step(&mut scene.world);
        assert_eq!(
            world_bits(&scene.world),
            world_bits(&control.world),
            "step {k} after the skipped steps"
        );
        assert_eq!(m.reports().unwrap(), m_control.reports().unwrap());
    }
}

#[test]
fn begin_and_end_step_around_an_invalid_dt_keep_the_reports_and_totals() {
    let (mut scene, mut m) = sliding_scene();
    for _ in 0..30 {
        m.step(&mut scene.world);
    }
    let (totals, reports) = (m.totals().unwrap(), m.reports().unwrap().to_vec());
    let mut params = scene.world.integration_parameters;
    params.dt = f32::NAN;
    m.begin_step(&params, &scene.world.bodies, &mut scene.world.colliders);
    m.end_step(
        &scene.world.narrow_phase,
        &scene.world.bodies,
        &mut scene.world.colliders,
    );
    assert_eq!(m.totals().unwrap(), totals);
    assert_eq!(m.reports().unwrap(), reports.as_slice());
}

#[test]
fn handles_outside_the_collider_set_are_no_ops_and_errors_are_typed() {
    let mut scene = BoxOnGround::default().build();
    let mut m = StickSlip::new(material());
    // A collider inserted and removed: its handle is stale.
    let gone = scene.world.insert_collider(cuboid3(0.1, 0.1, 0.1).0, None);
    scene.world.remove_collider(gone);
    let forged = ColliderHandle::from_raw_parts(u32::MAX - 1, 7);
    for h in [ColliderHandle::invalid(), forged, gone] {
        m.attach(&mut scene.world.colliders, h, Some(material()));
        m.set_material(h, material());
        m.set_vibration(h, source());
        m.detach(&mut scene.world.colliders, h);
        assert!(!m.is_attached(h), "{h:?} attached");
        assert!(m.vibration(h).is_none(), "{h:?} has a source");
        assert!(m.pair_law(&scene.world.colliders, h, h).is_none());
    }
    // Nothing was read back: typed errors, not empty answers.
    m.attach(&mut scene.world.colliders, scene.ground, None);
    for _ in 0..10 {
        m.step(&mut scene.world);
    }
    assert_eq!(m.active_contacts(), 1);
    assert_eq!(
        m.reports().unwrap_err(),
        NotReadBack {
            needed: ReadBack::Contacts,
            set: ReadBack::Off
        }
    );
    assert_eq!(m.totals().unwrap_err().needed, ReadBack::Totals);
    // Bytes that are not a snapshot.
    assert!(matches!(
        WorldSnapshot::load(&b"STKSLIQ\0 garbage"[..]),
        Err(SnapshotError::NotASnapshot)
    ));
    assert!(matches!(
        WorldSnapshot::load(&[][..]),
        Err(SnapshotError::NotASnapshot)
    ));
    // A snapshot restored against a collider set without its colliders drops their tables.
    let empty = ColliderSet::new();
    let restored = StickSlip::restore(&m.snapshot(), &empty, ()).unwrap();
    assert!(!restored.is_attached(scene.ground));
}

#[test]
fn nan_and_absurd_velocities_never_reach_the_friction_state() {
    let mut world = PhysicsWorld::default();
    world.insert_collider(cuboid3(20.0, 0.1, 20.0).0, None);
    let mut boxes = Vec::new();
    for i in 0..2 {
        let (b, _) = world.insert(
            RigidBodyBuilder::dynamic()
                .translation(v3(3.0 * i as f32, 0.3, 0.0))
                .can_sleep(false),
            cuboid3(0.2, 0.2, 0.2).0.density(1000.0),
        );
        boxes.push(b);
    }
    let mut m = StickSlip::new(material()).with_read_back(ReadBack::Contacts);
    // Every collider attached: a quiet box given a velocity between steps is hooked at once.
    let all: Vec<ColliderHandle> = world.colliders.iter().map(|(h, _)| h).collect();
    for h in &all {
        m.attach(&mut world.colliders, *h, None);
    }
    m.set_vibration(all[0], source());
    for _ in 0..20 {
        m.step(&mut world);
    }
    let mut seen_reset = false;
    // A finite but absurd velocity first (impulses overflow f32), then NaN and ∞, then a
    // NaN spin.
    for (v, w) in [
        (v3(-f32::MAX, 0.0, 0.0), 0.0),
        (v3(f32::NAN, f32::INFINITY, f32::INFINITY), 0.0),
        (v3(0.0, 0.0, 0.0), f32::NAN),
    ] {
        let b = &mut world.bodies[boxes[0]];
        b.set_linvel(v, true);
        b.set_angvel(spin(w), true);
        for _ in 0..5 {
            m.step(&mut world);
            for r in m.reports().unwrap() {
                let numbers = [r.mu, r.limit, r.normal_force, r.dissipated_power];
                assert!(numbers.iter().all(|x| x.is_finite()), "{r:?}");
                assert!(r.friction_force.iter().all(|x| x.is_finite()), "{r:?}");
                assert!(r.slip_velocity.iter().all(|x| x.is_finite()), "{r:?}");
                assert!(r.point.iter().all(|x| x.is_finite()), "{r:?}");
                seen_reset |= r.reset;
            }
            let t = m.totals().unwrap();
            assert!(
                t.dissipated_energy.is_finite()
                    && t.friction_force.is_finite()
                    && t.normal_force.is_finite(),
                "{t:?}"
            );
            // The state is finite: restore validates it.
            StickSlip::restore(&m.snapshot(), &world.colliders, ())
                .expect("the friction state became non-finite");
        }
    }
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
