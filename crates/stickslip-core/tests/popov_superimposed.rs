//! scratch
use std::time::Instant;
use stickslip_core::popov::*;
use stickslip_core::waveform::Waveform;

fn osc(a: f64, w: &Waveform, p: f64) -> Option<Oscillation> {
    Some(Oscillation::new(a, w.clone(), p).unwrap())
}

#[test]
fn scratch() {
    let c = CompliantContact::new(3.0, 2.0, 0.4, 1.0).unwrap();
    let len = c.slip_length();
    let opts = SimulationOptions::default();
    let tri = Waveform::from_table(&[0.0, 1.0, 2.0, 1.0]).unwrap();
    for w in [Waveform::Sine, Waveform::Square, tri.clone(), Waveform::SawtoothLeft] {
        for (name, ex) in [
            ("tan", Excitation { tangential: osc(0.6 * len, &w, 0.1), ..Default::default() }),
            ("tan big", Excitation { tangential: osc(2.5 * len, &w, 0.1), ..Default::default() }),
            ("trans", Excitation { transverse: osc(0.6 * len, &w, 0.1), ..Default::default() }),
            ("trans big", Excitation { transverse: osc(2.5 * len, &w, 0.1), ..Default::default() }),
            ("n+t", Excitation { normal: osc(0.5, &w, 0.0), tangential: osc(0.5 * len, &w, 0.25), ..Default::default() }),
            ("n loss+t", Excitation { normal: osc(1.3, &w, 0.0), tangential: osc(0.5 * len, &w, 0.7), ..Default::default() }),
            ("all", Excitation { normal: osc(0.5, &w, 0.0), tangential: osc(0.5 * len, &w, 0.25), transverse: osc(0.8 * len, &Waveform::Sine, 0.4) }),
        ] {
            for v in [-0.3, 0.05, 0.3, 1.0, 3.0] {
                let v0 = v * c.speed_scale(1.0);
                let t0 = Instant::now();
                let th = steady_sliding(&c, &ex, 1.0, v0);
                let dt = t0.elapsed();
                let t1 = Instant::now();
                let sim = SpringModel::compliant(&c, v0, 1.0, ex.clone()).unwrap().simulate(&opts);
                let dt2 = t1.elapsed();
                match th {
                    Ok(th) => {
                        let err = (th.mu_eff - sim.mu_eff).abs();
                        println!("{:?} {name} v={v}: theory {:.6} sim {:.6} err {:.2e} stick {:.3}/{:.3} per {} {:?} sim {:?} {}", w.kind(), th.mu_eff, sim.mu_eff, err, th.stick_fraction, sim.stick_fraction, th.periods, dt, dt2, sim.warmup_periods);
                    }
                    Err(e) => println!("{:?} {name} v={v}: ERR {e} sim {:.6}", w.kind(), sim.mu_eff),
                }
            }
        }
    }
}
