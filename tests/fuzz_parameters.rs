//! Any parameters the constructors accept give finite physics: random friction laws (EP,
//! Phys, Regul, Coulomb with any sliding curve) and vibration sources (any direction, mode,
//! amplitude, frequency), their numbers drawn from plausible ranges mixed with hostile ones
//! (NaN, ±∞, 0, subnormals, ±1e±300), either fail to construct with a typed error or run a
//! box pushed across a ground in a rapier world for 40 steps with every body state, contact
//! report and world total finite. Deterministic (fixed seed, see `support/deterministic.rs`).

#[path = "support/deterministic.rs"]
mod support;

use proptest::prelude::*;
use rapier3d::prelude::*;
use stickslip::core::ParamError;
use stickslip::core::law::{Law, Physical, Regularization, Regularized};
use stickslip::core::sliding_curve::{Curve, StribeckDecay};
use stickslip::core::waveform::Waveform;
use stickslip::rapier::{
    Amplitude, FrictionMaterial, StickSlip, VibrationDirection, VibrationMode, VibrationSource,
};
use stickslip_fixtures::BoxOnGround;
use support::deterministic;

/// A number a user might pass: mostly plausible (±3 decades around `typical`), sometimes
/// hostile (one in five; about half of the cases get past the constructors and run).
fn number(typical: f64) -> impl Strategy<Value = f64> {
    prop_oneof![
        12 => (-3.0f64..3.0).prop_map(move |e| typical * 10f64.powf(e)),
        1 => (-300i32..300, 1.0f64..10.0).prop_map(|(e, m)| m * 10f64.powi(e)),
        1 => (-300i32..300, 1.0f64..10.0).prop_map(|(e, m)| -m * 10f64.powi(e)),
        1 => prop::sample::select(vec![
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            0.0,
            -0.0,
            f64::MAX,
            f64::MIN_POSITIVE,
            5e-324,
            1e39,
            1e30,
        ]),
    ]
}

fn curve() -> impl Strategy<Value = Result<Curve, ParamError>> {
    prop_oneof![
        number(0.4).prop_map(Curve::constant),
        (
            number(0.6),
            number(0.4),
            number(0.01),
            any::<bool>(),
            number(0.01)
        )
            .prop_map(|(s, k, v, gauss, visc)| {
                let decay = if gauss {
                    StribeckDecay::Gaussian
                } else {
                    StribeckDecay::Exponential
                };
                Curve::stribeck(s, k, v, decay, visc)
            }),
        prop::collection::vec((number(0.1), number(0.4)), 1..5).prop_map(|samples| {
            let mut speeds = vec![0.0];
            let mut mus = vec![samples[0].1];
            for (dv, mu) in &samples[1..] {
                speeds.push(speeds.last().unwrap() + dv);
                mus.push(*mu);
            }
            Curve::table(speeds, mus)
        }),
    ]
}

fn law() -> impl Strategy<Value = Result<Law, ParamError>> {
    prop_oneof![
        (number(1e5), number(0.5), number(0.55), curve())
            .prop_map(|(c, ba, max, curve)| Law::elasto_plastic(c, ba, max, curve?)),
        (number(0.5), curve()).prop_map(|(ba, curve)| Physical::new(ba, curve?).map(Law::Physical)),
        (number(1e-3), curve()).prop_map(|(v, curve)| {
            Regularized::new(curve?, v, Regularization::default()).map(Law::Regularized)
        }),
        number(0.5).prop_map(|mu| stickslip::core::law::Coulomb::new(mu).map(Law::Coulomb)),
    ]
}

fn vibration() -> impl Strategy<Value = Option<Result<VibrationSource, ParamError>>> {
    let source = (
        0usize..3,
        any::<bool>(),
        number(0.5),
        number(500.0),
        number(100.0),
        number(0.25),
        any::<bool>(),
        prop::option::of(number(1e5)),
    )
        .prop_map(|(dir, ratio, a_ratio, a_force, f, phase, averaged, k_t)| {
            let direction = match dir {
                0 => VibrationDirection::Normal,
                1 => VibrationDirection::Tangential {
                    axis: [1.0, 0.0, 0.0],
                },
                _ => VibrationDirection::Transverse {
                    axis: [0.0, 0.0, 1.0],
                },
            };
            let amplitude = if ratio {
                Amplitude::Ratio(a_ratio)
            } else {
                Amplitude::Force(a_force)
            };
            let mode = if averaged {
                VibrationMode::Averaged
            } else {
                VibrationMode::TimeResolved
            };
            let s = VibrationSource::new(direction, amplitude, f, Waveform::Sine, phase, mode)?;
            match k_t {
                Some(k) => s.with_tangential_stiffness(k),
                None => Ok(s),
            }
        });
    prop::option::of(source)
}

fn finite3(v: Vector) -> bool {
    v.x.is_finite() && v.y.is_finite() && v.z.is_finite()
}

proptest! {
    #![proptest_config(deterministic(384))]

    #[test]
    fn accepted_parameters_give_finite_physics(
        law in law(),
        vibration in vibration(),
        push in 0.0f32..2.0,
        mass in 0.1f32..1000.0,
        dt in prop::sample::select(vec![1e-4f32, 1.0 / 600.0, 1.0 / 60.0, 0.05]),
    ) {
        // A typed error is a fine answer to bad parameters.
        let Ok(law) = law else { return Ok(()) };
        let vibration = match vibration {
            Some(Ok(v)) => Some(v),
            Some(Err(_)) => return Ok(()),
            None => None,
        };
        let mut scene = BoxOnGround { mass, dt, ..BoxOnGround::default() }.build();
        let mut m = StickSlip::new(FrictionMaterial::new(law.clone())).with_read_back(stickslip::rapier::ReadBack::Contacts);
        m.attach(&mut scene.world.colliders, scene.ground, None);
        if let Some(v) = &vibration {
            m.set_vibration(scene.ground, v.clone());
        }
        let weight = mass * 9.81;
        scene.world.bodies[scene.body].add_force(Vector::new(push * weight, 0.0, 0.0), true);
        for step in 0..40 {
            m.step(&mut scene.world);
            let b = &scene.world.bodies[scene.body];
            prop_assert!(
                finite3(b.translation()) && finite3(b.linvel()) && finite3(b.angvel()),
                "step {step}: body state {:?} {:?} with {law:?}, {vibration:?}",
                b.translation(), b.linvel()
            );
            for r in m.reports().unwrap() {
                let values = [r.mu, r.limit, r.normal_force, r.dissipated_power];
                prop_assert!(
                    values.iter().all(|x| x.is_finite())
                        && r.friction_force.iter().all(|x| x.is_finite())
                        && r.slip_velocity.iter().all(|x| x.is_finite()),
                    "step {step}: report {r:?} with {law:?}, {vibration:?}"
                );
            }
            let t = m.totals().unwrap();
            prop_assert!(
                t.dissipated_power.is_finite() && t.dissipated_energy.is_finite(),
                "step {step}: totals {t:?} with {law:?}, {vibration:?}"
            );
        }
    }
}
