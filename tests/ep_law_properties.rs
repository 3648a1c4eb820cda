//! The elasto-plastic law's step (seed Eq. 4–7, isotropic in the tangent plane, state = spring
//! force). Invariants checked over random parameters (c in [1e2, 1e7] 1/m, dt up to 1/30 s,
//! random slip histories and loads): |μ⃗| never exceeds μ_max beyond rounding and is never NaN;
//! a block under an oscillating force below break-away does not drift (its mean displacement
//! stays within g_ba = μ_ba/c); the dissipated energy is non-negative over any closed slip
//! cycle; the vector law along a line reproduces a fine-step integration of the 1D Eq. 4b;
//! with a constant normal force the state is exactly the seed's μ (independent of F_n); and
//! with a modulated normal force F̄(1 + α w) the contact dragged at v0 reproduces Popov's
//! μ̄ = μ0 (1 − α Ψ_w(β)) with β = c v0/(μ0 α f).

use proptest::prelude::*;
use stickslip::core::law::{ElastoPlastic, FrictionLaw, FrictionState, StepInput};
use stickslip::core::popov;
use stickslip::core::sliding_curve::{Curve, SlidingCurve, StribeckDecay};
use stickslip::core::vec2::{norm, scale};
use stickslip::core::waveform::Waveform;

fn law(c: f64, mu_ba: f64, gap: f64, curve_kind: u8, v_s: f64) -> ElastoPlastic {
    let mu_max = mu_ba + gap;
    let curve = match curve_kind {
        0 => Curve::constant(mu_max).unwrap(),
        1 => Curve::stribeck(mu_max, 0.5 * mu_ba, v_s, StribeckDecay::Gaussian, 0.0).unwrap(),
        _ => Curve::stribeck(mu_max, 1.5 * mu_max, v_s, StribeckDecay::Exponential, 0.1).unwrap(),
    };
    ElastoPlastic::new(c, mu_ba, mu_max, curve).unwrap()
}

prop_compose! {
    fn any_law()(log_c in 2.0f64..7.0, mu_ba in 0.05f64..1.0, gap in 0.0f64..0.3,
                 kind in 0u8..3, v_s in 1e-4f64..1.0) -> ElastoPlastic {
        law(10f64.powf(log_c), mu_ba, gap, kind, v_s)
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn state_stays_bounded_and_finite(
        l in any_law(),
        dt in 1e-5f64..(1.0 / 30.0),
        slips in prop::collection::vec((-10.0f64..10.0, -10.0f64..10.0, 0.01f64..1e4), 1..200),
    ) {
        // |μ| is bounded by μ_max, or by the sliding curve where it rises above μ_max.
        let mut s = FrictionState::default();
        let mut bound = l.mu_max();
        for (vx, vy, f_n) in slips {
            bound = bound.max(l.curve().mu(vx.hypot(vy)));
            let out = l.step(&mut s, &StepInput::new([vx * dt, vy * dt], dt, f_n));
            let mu = norm(out.mu);
            prop_assert!(mu.is_finite() && s.force.iter().all(|x| x.is_finite()));
            prop_assert!(mu <= bound * (1.0 + 1e-9) + 1e-12, "|mu| = {mu} > {bound}");
            prop_assert!(norm(s.force) <= bound * f_n * (1.0 + 1e-9) + 1e-12);
            prop_assert!(out.limit >= l.mu_ba() && out.limit.is_finite());
        }
    }

    #[test]
    fn closed_slip_cycles_never_return_energy(
        l in any_law(),
        dt in 1e-5f64..(1.0 / 30.0),
        f_n in 0.1f64..1e3,
        path in prop::collection::vec((-1.0f64..1.0, -1.0f64..1.0), 1..60),
        amp in 1e-7f64..1e-2,
    ) {
        // A slip path and its exact reverse: the contact returns to where it started.
        let mut s = FrictionState::default();
        let mut dissipated = 0.0;
        let steps: Vec<[f64; 2]> = path.iter().map(|&(x, y)| [x * amp, y * amp]).collect();
        let back: Vec<[f64; 2]> = steps.iter().rev().map(|g| scale(*g, -1.0)).collect();
        for g in steps.iter().chain(back.iter()) {
            let out = l.step(&mut s, &StepInput::new(*g, dt, f_n));
            dissipated += out.dissipated;
            // Plastic work is never negative at any instant, beyond rounding.
            prop_assert!(dissipated >= -1e-9 * f_n * amp * l.mu_max(), "dissipated {dissipated}");
        }
    }

    #[test]
    fn oscillating_load_below_break_away_does_not_drift(
        l in any_law(),
        dt in 1e-4f64..(1.0 / 30.0),
        mass in 0.01f64..100.0,
        load in 0.05f64..0.85,
        slow in 0.001f64..0.1,
        one_sided in any::<bool>(),
    ) {
        // The law's sticking branch is an undamped spring (ω_n = √(c g)): a load below
        // break-away must be applied slower than ω_n, or resonance would carry the block past
        // g_ba — that is dynamics, not drift. Implicit coupling: each step solves
        // m (v' − v)/dt = F(t) − F_n μ(v' dt) for v', a monotone scalar equation, so the
        // block-plus-law system is stable for any c and dt.
        let g = 9.81;
        let f_n = mass * g;
        let amp = load * l.mu_ba() * f_n;
        let freq = slow * (l.c() * g).sqrt() / (2.0 * std::f64::consts::PI);
        let mut s = FrictionState::default();
        let (mut x, mut v) = (0.0f64, 0.0f64);
        let (mut sum_x, mut n) = (0.0, 0usize);
        let steps = ((5.0 / freq) / dt).ceil().min(4000.0) as usize;
        for k in 0..steps {
            let phase = 2.0 * std::f64::consts::PI * freq * (k as f64 + 1.0) * dt;
            // Either a load cycling 0 → amp → 0, or an alternating ±amp.
            let f = if one_sided { amp * 0.5 * (1.0 - phase.cos()) } else { amp * phase.sin() };
            let residual = |vn: f64| {
                let mut trial = s;
                let out = l.step(&mut trial, &StepInput::new([vn * dt, 0.0], dt, f_n));
                mass * (vn - v) / dt - f - out.force[0]
            };
            let mut conv = roots::SimpleConvergency { eps: 1e-15, max_iter: 200 };
            let span = (v.abs() + (f.abs() + l.mu_max() * f_n) * dt / mass) * 2.0 + 1e-12;
            let vn = roots::find_root_brent(v - span, v + span, residual, &mut conv).unwrap_or(0.0);
            l.step(&mut s, &StepInput::new([vn * dt, 0.0], dt, f_n));
            v = vn;
            x += v * dt;
            prop_assert!(x.is_finite());
            sum_x += x;
            n += 1;
        }
        let g_ba = l.break_away_displacement();
        prop_assert!((sum_x / n as f64).abs() <= g_ba, "mean x {} > g_ba {g_ba}", sum_x / n as f64);
        prop_assert!(x.abs() <= g_ba, "final x {x} > g_ba {g_ba}");
    }

    #[test]
    fn constant_normal_force_gives_the_seeds_mu_for_any_load(
        l in any_law(),
        dt in 1e-5f64..(1.0 / 30.0),
        f1 in 0.01f64..1e4,
        f2 in 0.01f64..1e4,
        slips in prop::collection::vec(-1.0f64..1.0, 1..100),
    ) {
        let (mut a, mut b) = (FrictionState::default(), FrictionState::default());
        for v in slips {
            let ma = l.step(&mut a, &StepInput::new([v * dt, 0.0], dt, f1)).mu[0];
            let mb = l.step(&mut b, &StepInput::new([v * dt, 0.0], dt, f2)).mu[0];
            prop_assert!((ma - mb).abs() <= 1e-9 * l.mu_max());
        }
    }
}

/// Fine-step RK4 of the 1D seed ODE along the slip path (s = arc length).
fn reference_1d(l: &ElastoPlastic, mu0: f64, slip: f64, speed: f64) -> f64 {
    let n = 200_000;
    let h = slip / n as f64;
    let v = speed * slip.signum();
    // dμ/ds = (dμ/dt)/|v|
    let f = |mu: f64| l.rate(mu, v) / speed;
    let mut mu = mu0;
    for _ in 0..n {
        let k1 = f(mu);
        let k2 = f(mu + 0.5 * h.abs() * k1);
        let k3 = f(mu + 0.5 * h.abs() * k2);
        let k4 = f(mu + h.abs() * k3);
        mu += h.abs() / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    }
    mu
}

#[test]
fn vector_law_along_a_line_matches_the_1d_seed_ode() {
    let cases: [(f64, f64, f64, f64, f64); 5] = [
        (1e4, 0.3, 0.35, 0.0, 1e-4f64),
        (1e4, 0.3, 0.35, 0.2, 2e-4),
        (1e5, 0.3, 0.4, -0.33, 3e-5),
        (1e3, 0.5, 0.6, 0.59, -2e-3),
        (1e6, 0.2, 0.25, 0.1, 1e-6),
    ];
    let angle = 0.7f64;
    let e = [angle.cos(), angle.sin()];
    for (c, ba, max, mu0, slip) in cases {
        let l = ElastoPlastic::new(c, ba, max, Curve::constant(max).unwrap()).unwrap();
        let dt = 1e-3;
        let speed = (slip / dt).abs();
        let f_n = 10.0;
        let mut s = FrictionState {
            force: scale(e, mu0 * f_n),
        };
        let out = l.step(&mut s, &StepInput::new(scale(e, slip), dt, f_n));
        let expect = reference_1d(&l, mu0, slip, speed);
        let got = out.mu[0] * e[0] + out.mu[1] * e[1];
        // Perpendicular part stays zero: the law is isotropic.
        assert!((out.mu[0] * e[1] - out.mu[1] * e[0]).abs() < 1e-12);
        assert!(
            (got - expect).abs() < 2e-3 * max,
            "c {c} mu0 {mu0} slip {slip}: {got} vs {expect}"
        );
    }
}

/// μ̄ of a contact dragged at v0 under F̄ (1 + α w(f t)), from the law's force state.
fn dragged_mu_bar(w: &Waveform, alpha: f64, beta: f64) -> f64 {
    let (mu0, c, f_mean, f) = (0.5, 1e4, 100.0, 10.0);
    let l = ElastoPlastic::new(c, mu0, mu0, Curve::constant(mu0).unwrap()).unwrap();
    let v0 = beta * mu0 * alpha * f / c;
    let steps_per_period = 4000;
    let dt = 1.0 / (f * steps_per_period as f64);
    // In the periodic state the contact slips where F_n is smallest, so the spring force there
    // is μ0 F̄ (1 − α): start from it instead of waiting ~(1−α)/(αβ) periods of loading.
    let mut s = FrictionState {
        force: [mu0 * f_mean * (1.0 - alpha), 0.0],
    };
    let (mut sum_f, mut sum_n) = (0.0, 0.0);
    for k in 0..(12 * steps_per_period) {
        let t = (k as f64 + 0.5) * dt;
        let f_n = f_mean * (1.0 + alpha * w.value(f * t)).max(0.0);
        let input = StepInput {
            slip: [v0 * dt, 0.0],
            dt,
            normal_force: f_n,
            stiffness_normal_force: f_mean,
        };
        let out = l.step(&mut s, &input);
        if k >= 2 * steps_per_period {
            sum_f += -out.force[0];
            sum_n += f_n;
        }
    }
    sum_f / sum_n
}

#[test]
fn modulated_normal_force_reproduces_popov() {
    let alpha = 0.5;
    for w in [
        Waveform::Sine,
        Waveform::SawtoothRight,
        Waveform::SawtoothLeft,
        Waveform::Square,
    ] {
        let bc = w.beta_c();
        let betas = if bc.is_finite() {
            vec![0.1 * bc, 0.4 * bc, 0.8 * bc, 1.5 * bc]
        } else {
            vec![0.2, 1.0, 3.0, 6.0]
        };
        for beta in betas {
            let psi = popov::psi(&w, beta).unwrap();
            let theory = 0.5 * (1.0 - alpha * psi);
            let got = dragged_mu_bar(&w, alpha, beta);
            println!("{w:?} beta {beta:.3}: law {got:.5} theory {theory:.5}");
            assert!(
                ((got - theory) / theory).abs() < 0.01,
                "{w:?} beta {beta}: law {got} vs theory {theory}"
            );
        }
    }
}
