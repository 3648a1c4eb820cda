//! The regime a contact reports is steady when the motion is: a cube sliding down a slope
//! (tan θ = 1.4 μ_s) reports sliding at every step, one resting on it (tan θ = 0.5 μ_s)
//! sticking at every step, after 0.2 s of settling and for 2 s — on a cuboid ground and on a
//! triangle mesh (a clustered patch), at 60 Hz and 240 Hz, for EP with μ_s = μ_k (a zero-width
//! switch band) and μ_s > μ_k, Phys and Coulomb, and sliding also for Regul. Before, a steady
//! slide at μ_ba = μ_max read sticking every other step (its state one ulp inside the band).
//! In 3D and in 2D (stickslip-fixtures2d: the cuboid ground).

mod ordinary;

use ordinary::{Friction, Run, all_laws, ep};
use stickslip_core::law::Regime;
use stickslip_fixtures::ordinary::{Ground, box_on_slope};

const MU: f64 = 0.5;

fn laws() -> Vec<(f64, Friction)> {
    let mut v: Vec<(f64, Friction)> = all_laws(MU).into_iter().map(|f| (MU, f)).collect();
    v.push((0.6, Friction::Law("ep 0.6/0.4", ep(0.6, 0.4))));
    v
}

/// Steps (of 2 s after 0.2 s) whose reports are not all `expect`, and how many steps had one.
fn off_steps(ground: Ground, tan: f64, mu: f64, dt: f64, f: &Friction, expect: Regime) -> usize {
    let mut run = Run::new(box_on_slope(ground, tan, mu as f32, dt), f);
    run.run_for(0.2);
    let n = (2.0 / dt).round() as usize;
    let mut off = 0;
    for _ in 0..n {
        run.step();
        let reports = run.modifier.as_ref().unwrap().reports().unwrap();
        assert!(!reports.is_empty(), "no contact reported");
        if reports.iter().any(|r| r.regime != expect) {
            off += 1;
        }
    }
    off
}

#[test]
fn a_steady_slide_reports_sliding_and_a_rest_sticking_at_every_step() {
    for dt in [1.0 / 60.0, 1.0 / 240.0] {
        #[cfg(not(dim2))]
        let grounds = [Ground::Cuboid, Ground::TriMesh];
        #[cfg(dim2)]
        let grounds = [Ground::Cuboid];
        for ground in grounds {
            for (mu_s, f) in laws() {
                let sliding = off_steps(ground, 1.4 * mu_s, mu_s, dt, &f, Regime::Sliding);
                let resting = if matches!(f, Friction::Law("regul", _)) {
                    0
                } else {
                    off_steps(ground, 0.5 * mu_s, mu_s, dt, &f, Regime::Sticking)
                };
                println!(
                    "{ground:?} {:.0} Hz {}: {sliding} steps not sliding, {resting} not sticking",
                    1.0 / dt,
                    f.name()
                );
                assert_eq!(
                    (sliding, resting),
                    (0, 0),
                    "{ground:?} {} at {dt}",
                    f.name()
                );
            }
        }
    }
}
