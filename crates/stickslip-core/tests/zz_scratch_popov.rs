use stickslip_core::popov::*;
use stickslip_core::waveform::Waveform;
use std::f64::consts::TAU;
fn env(w: &Waveform, beta: f64, n: usize) -> f64 {
    let h = 1.0 / n as f64;
    let mut f = w.value(0.0);
    let mut sum = 0.0;
    for i in 1..=2 * n {
        let wi = w.value(i as f64 * h);
        f = wi.min(f + beta * h);
        if i > n { sum += wi - f; }
    }
    sum / n as f64
}
#[test]
fn scratch() {
    for r in [0.9, 0.99, 0.999, 0.9999, 0.99999] {
        let b = r * TAU;
        eprintln!("sine r={r}: psi={:e} env={:e} eq38={:e}", psi(&Waveform::Sine, b).unwrap(), env(&Waveform::Sine, b, 200000), psi_sine_eq38(b));
    }
    let t = std::time::Instant::now();
    let mut s = 0.0;
    for i in 0..1000 { s += psi(&Waveform::Sine, i as f64 * 0.006).unwrap(); }
    eprintln!("1000 sine psi: {:?} {s}", t.elapsed());
    let w = Waveform::from_fn(|x| (2.0 * TAU * x).sin() + 0.4 * (TAU * x + 0.3).sin()).unwrap();
    let t = std::time::Instant::now();
    for i in 0..1000 { s += psi(&w, i as f64 * 0.01).unwrap(); }
    eprintln!("1000 custom psi: {:?} {s}", t.elapsed());
    // spring model unit-test numbers
    let sine = |a| Oscillation::new(a, Waveform::Sine, 0.0).unwrap();
    let m = |v0, ex| SpringModel::new(1.0, 1.0, 0.5, 1.0, v0, 1.0, ex).unwrap();
    let o = SimulationOptions::default();
    let t = std::time::Instant::now();
    for v0 in [1e-4, 1e-3, 1e-2, 0.1, 0.5, 1.0, 10.0] {
        eprintln!("tangential a=0.2 v0={v0}: {:?}", m(v0, Excitation::tangential(sine(0.2))).simulate(&o));
        eprintln!("transverse a=0.3 v0={v0}: {:?}", m(v0, Excitation::transverse(sine(0.3))).simulate(&o));
    }
    eprintln!("sims {:?}", t.elapsed());
    eprintln!("eq6 {} eq8 {}", mu_s_tangential(0.5, 0.2).unwrap(), mu_s_transverse(0.5,0.3).unwrap());
}
