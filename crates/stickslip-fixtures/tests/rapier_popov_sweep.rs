//! Popov's sliding friction under a normal vibration source, swept over the parameters a user
//! meets, with the default `StickSlipConfig`. A sled pressed by F̄ onto a plate that carries a
//! normal vibration source (amplitude α F̄, frequency f, waveform w) is dragged at v0; its
//! contact uses the elasto-plastic law in the seed's sharp limit (μ_ba = μ_max = μ0, flat
//! curve), whose tangential stiffness c·F̄ is Popov's contact spring. Invariant: the measured
//! μ̄ = ⟨F_x⟩/⟨F_z⟩ equals μ0 (1 − α Ψ_w(β)), β = c v0/(μ0 α f), within 3 % for c from 1e3 to
//! 1e6 1/m, f from 2 Hz to 2 kHz, F̄ from 1 to 100 N, sled momenta 100…10 000 times the
//! friction impulse of a step (the sled is velocity-driven), all four
//! closed-form waveforms with β on both sides of β_c (sine: 0.5…12), drag speeds from about
//! 1e-6 to 1 m/s, time-resolved at 50 and 100 steps per period and in averaged mode.
//! In 3D and in 2D (stickslip-fixtures2d).

use stickslip_core::waveform::Waveform;
use stickslip_fixtures::{PopovDrag, PopovDrive};
use stickslip_rapier::VibrationMode;

fn betas(w: &Waveform) -> [f64; 4] {
    let bc = w.beta_c();
    if bc.is_finite() {
        [0.25 * bc, 0.6 * bc, 0.9 * bc, 1.5 * bc]
    } else {
        [0.5, 2.0, 5.0, 12.0]
    }
}

#[test]
fn popov_mu_bar_across_stiffness_frequency_load_and_mass() {
    let waveforms = [
        Waveform::Sine,
        Waveform::SawtoothRight,
        Waveform::SawtoothLeft,
        Waveform::Square,
    ];
    let drives = [
        (PopovDrive::Source(VibrationMode::TimeResolved), 50),
        (PopovDrive::Source(VibrationMode::TimeResolved), 100),
        (PopovDrive::Source(VibrationMode::Averaged), 10),
    ];
    let (mut worst, mut cases) = (0.0f64, 0);
    let (mut v_min, mut v_max) = (f64::INFINITY, 0.0f64);
    for (i, c) in [1e3, 1e4, 1e5, 1e6].into_iter().enumerate() {
        for (j, f) in [2.0f64, 20.0, 200.0, 2000.0].into_iter().enumerate() {
            let k = 4 * i + j;
            let w = waveforms[k % 4].clone();
            for (d, &(drive, spp)) in drives.iter().enumerate() {
                // One β below β_c and one above (or a low and a high one for the sine).
                for beta in [betas(&w)[(k + d) % 2], betas(&w)[2 + (k + d) % 2]] {
                    // Averaged mode need not resolve the vibration, but rapier's own step
                    // stays at or below 1/240 s.
                    let spp = spp.max((240.0 / f).ceil() as usize);
                    let dt = 1.0 / (f * spp as f64);
                    let normal_force = [1.0, 9.81, 100.0][(k + d) % 3];
                    let v0 = beta * 0.5 * 0.5 * f / c;
                    // The sled is velocity-driven: its momentum per step must dwarf the
                    // friction impulse μ0 F̄ dt, by a factor 100…10 000.
                    let scale = [100.0, 1000.0, 10_000.0][(k + 2 * d) % 3];
                    let setup = PopovDrag {
                        c,
                        frequency: f,
                        normal_force,
                        sled_mass: (scale * 0.5 * normal_force * dt / v0).max(10.0) as f32,
                        steps_per_period: spp,
                        ..PopovDrag::new(w.clone(), drive)
                    };
                    assert_eq!((setup.mu0, setup.alpha), (0.5, 0.5));
                    v_min = v_min.min(v0);
                    v_max = v_max.max(v0);
                    let theory = setup.theory(beta);
                    let got = setup.measure(beta).unwrap();
                    let err = (got - theory) / theory;
                    worst = worst.max(err.abs());
                    cases += 1;
                    assert!(
                        err.abs() < 0.03,
                        "c {c} f {f} {w:?} {drive:?} {spp}/period F {} m {} beta {beta:.3} \
                         v0 {v0:.2e}: {got:.4} vs {theory:.4} ({:+.2} %)",
                        setup.normal_force,
                        setup.sled_mass,
                        100.0 * err
                    );
                }
            }
        }
    }
    println!(
        "{cases} cases, drag speeds {v_min:.1e}…{v_max:.1e} m/s, worst error {:.2} %",
        100.0 * worst
    );
}
