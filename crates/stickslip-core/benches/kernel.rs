//! The engine-free contact kernel alone (`contact::step_contact`): the time of one contact
//! step, per class of contact, on input sequences a closed loop generates.
//!
//! Each class runs the kernel against a stand-in for the solver for a few hundred steps
//! (the solver's verdict: friction at the limit the kernel gave while the contact slips,
//! inside it while it holds), and records every step's state and input. The bench then
//! replays the recorded steps: each iteration copies a recorded state and steps it with its
//! recorded input, so every class is timed in the states it really passes through.
//!
//! Classes (the bench law of `benches/`: c = 1e4 /m, μ_ba 0.5, μ_max 0.55, flat curve 0.55,
//! 10 N, 60 Hz, unless said):
//! - `hold`: a loaded contact held at 0.6 of its capacity, no slip;
//! - `slide`: a steady slide at 0.1 m/s (30 relaxation lengths m/c per step: the law's
//!   exact α = 1 solution);
//! - `creep`: a steady slide at 5 mm/s (1.5 relaxation lengths per step: the state stays
//!   just below the band's top);
//! - `approach`: the creep with a normal force that changes by ±2 % every step (the
//!   state starts each step inside the band, below its top);
//! - `enter`: break-away over and over: 8 steps held, then 8 steps slipping at 1 mm/s;
//! - `reverse`: a slide at 5 mm/s that reverses every 4 steps;
//! - `turn`: a slide at 5 mm/s whose direction turns by 30° every step;
//! - `turn_sharp`: the same with a sharp band (μ_ba = μ_max = 0.5, the scenes' default);
//! - `vibrating`: a slide at 0.1 m/s on a source of normal vibration (ratio 0.5, 20 Hz,
//!   time-resolved);
//! - `all`: every class's steps in one sequence.
//!
//! `STICKSLIP_BENCH_QUICK=1` (the CI smoke run) records fewer steps.
use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use std::hint::black_box;
use stickslip_core::contact::{
    Amplitude, ContactInput, ContactState, TangentBasis, VibrationDirection, VibrationMode,
    VibrationSource, step_contact,
};
use stickslip_core::law::Law;
use stickslip_core::sliding_curve::Curve;
use stickslip_core::waveform::Waveform;

const DT: f64 = 1.0 / 60.0;
const F_N: f64 = 10.0;

/// One recorded step: the state before it and the inputs that vary.
#[derive(Clone, Copy)]
struct Recorded {
    state: ContactState,
    normal_force: f64,
    measured_mu: [f64; 2],
    slip: [f64; 2],
    time: f64,
}

/// A class: its law, source and recorded steps.
struct Class {
    name: &'static str,
    law: Law,
    source: Option<VibrationSource>,
    steps: Vec<Recorded>,
}

fn basis() -> TangentBasis {
    TangentBasis::plane([0.0, 0.0, 1.0], [1.0, 0.0, 0.0])
}

fn input<'a>(
    law: &'a Law,
    source: Option<&'a VibrationSource>,
    basis: &'a TangentBasis,
    r: &Recorded,
) -> ContactInput<'a> {
    ContactInput::new(law, basis, DT)
        .with_solve(r.normal_force, r.measured_mu, r.slip)
        .with_source(source, 1.0)
        .at_time(r.time)
        .with_inv_mass(1.0)
        .with_stiffness_time(0.1)
}

/// Runs `n` steps of a contact against the solver stand-in: `slip(k)` is the slip velocity
/// of step k (zero: the contact holds, at `held` of its capacity), `load(k)` its normal force.
fn record(
    law: &Law,
    source: Option<&VibrationSource>,
    n: usize,
    slip: impl Fn(usize) -> [f64; 2],
    load: impl Fn(usize) -> f64,
) -> Vec<Recorded> {
    let basis = basis();
    let mut state = ContactState::default();
    let mut steps = Vec::with_capacity(n);
    // Warm up: the contact forms, then the recorded steps start.
    for k in 0..n + 16 {
        let g = slip(k);
        let speed = g[0].hypot(g[1]);
        let limit = state.limit as f64;
        let measured_mu = if speed > 0.0 {
            // Slipping: the solver's friction sits at the limit, against the slip.
            [limit * g[0] / speed, limit * g[1] / speed]
        } else {
            [0.6 * limit, 0.0]
        };
        let r = Recorded {
            state,
            normal_force: load(k),
            measured_mu,
            slip: g,
            time: k as f64 * DT,
        };
        step_contact(&mut state, &input(law, source, &basis, &r));
        if k >= 16 {
            steps.push(r);
        }
    }
    steps
}

fn ep(mu_ba: f64, mu_max: f64) -> Law {
    Law::elasto_plastic(1e4, mu_ba, mu_max, Curve::constant(mu_max).unwrap()).unwrap()
}

fn classes(n: usize) -> Vec<Class> {
    let law = ep(0.5, 0.55);
    let sharp = ep(0.5, 0.5);
    let along = |v: f64| move |_: usize| [v, 0.0];
    let turning = |k: usize| {
        let a = k as f64 * 30f64.to_radians();
        [5e-3 * a.cos(), 5e-3 * a.sin()]
    };
    let vib = VibrationSource::new(
        VibrationDirection::Normal,
        Amplitude::Ratio(0.5),
        20.0,
        Waveform::Sine,
        0.0,
        VibrationMode::TimeResolved,
    )
    .unwrap();
    let steady = |_: usize| F_N;
    let class = |name, law: &Law, source: Option<VibrationSource>, steps| Class {
        name,
        law: law.clone(),
        source,
        steps,
    };
    vec![
        class(
            "hold",
            &law,
            None,
            record(&law, None, n, |_| [0.0; 2], steady),
        ),
        class(
            "slide",
            &law,
            None,
            record(&law, None, n, along(0.1), steady),
        ),
        class(
            "creep",
            &law,
            None,
            record(&law, None, n, along(5e-3), steady),
        ),
        class(
            "approach",
            &law,
            None,
            record(&law, None, n, along(5e-3), |k| {
                F_N * if k % 2 == 0 { 1.02 } else { 0.98 }
            }),
        ),
        class(
            "enter",
            &law,
            None,
            record(
                &law,
                None,
                n,
                |k| if k % 16 < 8 { [0.0; 2] } else { [1e-3, 0.0] },
                steady,
            ),
        ),
        class(
            "reverse",
            &law,
            None,
            record(
                &law,
                None,
                n,
                |k| [if k % 8 < 4 { 5e-3 } else { -5e-3 }, 0.0],
                steady,
            ),
        ),
        class("turn", &law, None, record(&law, None, n, turning, steady)),
        class(
            "turn_sharp",
            &sharp,
            None,
            record(&sharp, None, n, turning, steady),
        ),
        class(
            "vibrating",
            &law,
            Some(vib.clone()),
            record(&law, Some(&vib), n, along(0.1), steady),
        ),
    ]
}

fn kernel(c: &mut Criterion) {
    let quick = std::env::var_os("STICKSLIP_BENCH_QUICK").is_some();
    let n = if quick { 32 } else { 512 };
    let classes = classes(n);
    let basis = basis();
    let mut group = c.benchmark_group("kernel");
    for class in &classes {
        let law = &class.law;
        let source = class.source.as_ref();
        let inputs: Vec<(ContactState, ContactInput)> = class
            .steps
            .iter()
            .map(|r| (r.state, input(law, source, &basis, r)))
            .collect();
        group.throughput(Throughput::Elements(inputs.len() as u64));
        group.bench_function(BenchmarkId::new("step", class.name), |b| {
            b.iter(|| {
                for (state, input) in &inputs {
                    let mut s = *state;
                    black_box(step_contact(&mut s, black_box(input)));
                }
            })
        });
    }
    // Every class's steps in one sequence.
    let all: Vec<(ContactState, ContactInput)> = classes
        .iter()
        .flat_map(|class| {
            let (law, source, basis) = (&class.law, class.source.as_ref(), &basis);
            class
                .steps
                .iter()
                .map(move |r| (r.state, input(law, source, basis, r)))
        })
        .collect();
    group.throughput(Throughput::Elements(all.len() as u64));
    group.bench_function(BenchmarkId::new("step", "all"), |b| {
        b.iter(|| {
            for (state, input) in &all {
                let mut s = *state;
                black_box(step_contact(&mut s, black_box(input)));
            }
        })
    });
    group.finish();
}

criterion_group!(benches, kernel);
criterion_main!(benches);
