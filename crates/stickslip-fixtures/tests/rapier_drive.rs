//! Friction under in-plane and superimposed vibration, rapier against the compliant theory
//! (Popov's spring contact, `stickslip_core::popov::{mean_friction, free_drive_velocity}`). A
//! sled on a plate that carries a vibration source, with the default `StickSlipConfig` and
//! the elasto-plastic law in the seed's sharp limit (its stiffness c F̄ is the theory's k_x):
//! dragged at imposed speeds under tangential vibration alone (and transverse), the measured
//! μ̄(v0) = −⟨F_x⟩/⟨F_z⟩ is the theory's within 3 % on a grid of amplitudes (contacts that can
//! stick and contacts that slide in place) and speeds; under elliptical vibration (normal and
//! tangential, a phase shift apart) the sled held at rest feels the theory's blocking force,
//! the speed at which the dragged sled's mean friction vanishes and the speed a free sled
//! reaches from rest with no tangential force are the theory's free drive velocity within
//! 3 %, and the direction reverses with the sign of the phase shift. Time-resolved (400 steps
//! per period) and averaged (40 steps per period) sources alike; the free sled (100 kg under
//! 9.81 N) rides the contact spring at 5 Hz, a tenth of the vibration's 50 Hz, so it is the
//! theory's quasi-static slider.
#![cfg(not(dim2))] // no 2D form yet: stickslip-fixtures2d compiles it empty

use stickslip_core::waveform::Waveform;
use stickslip_fixtures::VibratingPlate;
use stickslip_rapier::{Amplitude, VibrationComponent, VibrationDirection, VibrationMode};

const MODES: [VibrationMode; 2] = [VibrationMode::TimeResolved, VibrationMode::Averaged];

/// The speed scale of the default plate: one slip length μ0/c per period.
fn speed_scale(p: &VibratingPlate) -> f64 {
    p.mu0 / p.c * p.frequency
}

/// Periods for the spring to settle at speed `v` (3 slip lengths of travel, at least 4).
fn warm(p: &VibratingPlate, v: f64) -> usize {
    4 + (3.0 * speed_scale(p) / v.abs().max(1e-9)).ceil().min(40.0) as usize
}

/// Drags the sled at `u` speed scales each and checks μ̄ against the theory within 3 %;
/// returns the worst relative error.
fn check_drag(p: &VibratingPlate, us: &[f64], label: &str) -> f64 {
    let mut worst: f64 = 0.0;
    for &u in us {
        let v = u * speed_scale(p);
        let got = p.drag(v, warm(p, v), 4).unwrap().mu_eff;
        let theory = p.theory_mu(v).unwrap();
        let err = (got - theory) / theory;
        worst = worst.max(err.abs());
        println!(
            "{label} u {u:5.1}: rapier {got:.4} theory {theory:.4} ({:+.2} %)",
            100.0 * err
        );
        assert!(err.abs() < 0.03, "{label} u {u}: {got} vs {theory}");
    }
    worst
}

#[test]
fn in_plane_mean_friction_matches_the_theory_over_amplitudes_and_speeds() {
    let mut worst: f64 = 0.0;
    for mode in MODES {
        // Tangential ratio A/F̄: 0.2 can stick (μ_s = μ0 − 0.2, Eq. 6), 0.75 slides in place.
        for ratio in [0.2, 0.75] {
            let p = VibratingPlate::elliptical(0.0, ratio, 0.0, mode).unwrap();
            let label = format!("{mode:?} tangential {ratio}");
            worst = worst.max(check_drag(&p, &[0.3, 1.0, 3.0, 10.0], &label));
        }
    }
    // Transverse vibration (across the drag, Eq. 8 at rest): μ̄ climbs back to μ0 slowly.
    for mode in MODES {
        let mut p = VibratingPlate::elliptical(0.0, 0.3, 0.0, mode).unwrap();
        p.components = vec![
            VibrationComponent::new(
                VibrationDirection::Transverse {
                    axis: [0.0, 0.0, 1.0],
                },
                Amplitude::Ratio(0.3),
                Waveform::Sine,
                0.0,
            )
            .unwrap(),
        ];
        let label = format!("{mode:?} transverse 0.3");
        worst = worst.max(check_drag(&p, &[0.3, 1.0, 3.0], &label));
    }
    println!(
        "in-plane μ̄(v0): worst relative error {:.2} %",
        100.0 * worst
    );
}

/// The speed where the dragged sled's mean friction vanishes: secant through drags at 0.9 and
/// 1.1 times the theory's drive velocity.
fn dragged_drive_velocity(p: &VibratingPlate, v_theory: f64) -> f64 {
    let (v1, v2) = (0.9 * v_theory, 1.1 * v_theory);
    let m1 = p.drag(v1, warm(p, v1), 4).unwrap().mu_eff;
    let m2 = p.drag(v2, warm(p, v2), 4).unwrap().mu_eff;
    assert!(m1 * m2 < 0.0, "no sign change: {m1} {m2}");
    v1 - m1 * (v2 - v1) / (m2 - m1)
}

#[test]
fn elliptical_vibration_drives_the_sled_at_the_theory_s_free_drive_velocity() {
    let mut worst: f64 = 0.0;
    for mode in MODES {
        let mut free_speeds = Vec::new();
        for shift in [0.25, -0.25, 0.1, 0.4] {
            let p = VibratingPlate::elliptical(0.6, 0.75, shift, mode).unwrap();
            let v_d = p.theory_drive_velocity().unwrap();
            assert!(v_d != 0.0, "{shift}");
            // Held at rest: the blocking force.
            let block = p.drag(0.0, 6, 4).unwrap().mu_eff * p.normal_force;
            let block_theory = p.theory_blocking_force().unwrap();
            let err_b = (block - block_theory) / block_theory;
            // Dragged: the mean friction vanishes at v_d.
            let dragged = dragged_drive_velocity(&p, v_d);
            let err_d = (dragged - v_d) / v_d;
            // Free from rest, no tangential force.
            let free = p.run_free(0.0, 120, 10).unwrap().velocity;
            let err_f = (free - v_d) / v_d;
            println!(
                "{mode:?} shift {shift:+.2}: v_d theory {v_d:+.4e} m/s, dragged zero {dragged:+.4e} \
                 ({:+.2} %), free {free:+.4e} ({:+.2} %); blocking {block:+.4} N vs \
                 {block_theory:+.4} ({:+.2} %)",
                100.0 * err_d,
                100.0 * err_f,
                100.0 * err_b
            );
            for (what, e) in [("dragged", err_d), ("free", err_f), ("blocking", err_b)] {
                assert!(e.abs() < 0.03, "{mode:?} shift {shift} {what}: {e}");
                worst = worst.max(e.abs());
            }
            free_speeds.push(free);
        }
        // The direction reverses with the phase shift's sign.
        assert!(free_speeds[0] * free_speeds[1] < 0.0, "{free_speeds:?}");
    }
    println!(
        "elliptical drive: worst relative error {:.2} %",
        100.0 * worst
    );
}

#[test]
fn superimposed_sources_are_validated_and_survive_a_snapshot() {
    use stickslip_core::law::Law;
    use stickslip_fixtures::BoxOnGround;
    use stickslip_rapier::{FrictionMaterial, StickSlip, VibrationSource};
    let comp = |d, a, phase| {
        VibrationComponent::new(d, Amplitude::Ratio(a), Waveform::Sine, phase).unwrap()
    };
    let x = VibrationDirection::Tangential {
        axis: [1.0, 0.0, 0.0],
    };
    let n = VibrationDirection::Normal;
    let ok = |c: &[VibrationComponent]| {
        VibrationSource::superimposed(c, 50.0, VibrationMode::TimeResolved).is_ok()
    };
    assert!(ok(&[comp(n, 0.6, 0.0), comp(x, 0.75, 0.25)]));
    assert!(!ok(&[]), "no component");
    assert!(!ok(&[comp(n, 0.6, 0.0), comp(n, 0.1, 0.5)]), "two normals");
    assert!(
        !ok(&[comp(x, 0.6, 0.0), comp(x, 0.1, 0.5)]),
        "two tangentials"
    );
    let skew = VibrationDirection::Transverse {
        axis: [1.0, 0.0, 1.0],
    };
    assert!(
        !ok(&[comp(x, 0.6, 0.0), comp(skew, 0.1, 0.5)]),
        "axes not perpendicular"
    );
    assert!(VibrationComponent::new(n, Amplitude::Ratio(f64::NAN), Waveform::Sine, 0.0).is_err());
    assert!(
        VibrationComponent::new(n, Amplitude::Ratio(0.5), Waveform::Sine, f64::INFINITY).is_err()
    );
    let across = VibrationDirection::Transverse {
        axis: [0.0, 0.0, 2.0],
    };
    let src = VibrationSource::superimposed(
        &[
            comp(n, 0.6, 0.0),
            comp(x, 0.75, 0.25),
            comp(across, 0.1, 0.7),
        ],
        50.0,
        VibrationMode::Averaged,
    )
    .unwrap();

    let scene = BoxOnGround::default().build();
    let curve = stickslip_core::sliding_curve::Curve::constant(0.5).unwrap();
    let law = Law::elasto_plastic(1e4, 0.5, 0.5, curve).unwrap();
    let mut m = StickSlip::new(FrictionMaterial::new(law));
    m.set_vibration(scene.ground, src.clone());
    let json = serde_json::to_string(&m.snapshot()).unwrap();
    let back: stickslip_rapier::StickSlipSnapshot = serde_json::from_str(&json).unwrap();
    let restored = StickSlip::restore(&back, &scene.world.colliders, ()).unwrap();
    let got = restored.vibration(scene.ground).expect("restored source");
    assert_eq!(got.components().len(), 3);
    for (a, b) in got.components().iter().zip(src.components()) {
        assert_eq!(a.direction(), b.direction());
        assert_eq!(a.amplitude(), b.amplitude());
        assert_eq!(a.phase(), b.phase());
    }
    assert_eq!(got.mode(), VibrationMode::Averaged);
}
