//! A cube on a sloped ground of every shape rapier offers for a floor — a cuboid, a triangle
//! mesh and a heightfield (both `FIX_INTERNAL_EDGES`) and a compound of tiles, the last three
//! reaching the hook as several manifolds that rapier clusters before the solve — with
//! stickslip attached (default configuration) beside rapier's own friction in the same test.
//! The baseline is rapier with a contact hook that changes nothing: rapier never recycles a
//! hooked pair's contacts, and on the compound that alone makes the cube catch on the tiles'
//! edges (rapier has no internal-edge fix for compounds); plain rapier is printed beside it.
//! Invariants, for EP, Phys and Coulomb at 60 Hz and 240 Hz: below break-away
//! (tan θ = 0.95 μ) the cube creeps no more than the law's elastic range g_ba = μ/c plus the
//! baseline's own creep over 10 s; above it (tan θ = 1.4 μ) it slides across the ground's
//! cells with the baseline's acceleration within 0.5 % of g (sin θ − μ cos θ), and on the
//! cuboid, the mesh and the heightfield the baseline itself is within 1 % of that closed form.
//! A cube put down at rest on the slope at 0.9 of break-away, also with μ_k < μ_s, moves no
//! more from where it was put than under the baseline plus g_ba (rapier's contact forming lets
//! it slip some 10–100 µm in its first two steps, far beyond g_ba: the law must not take that
//! for break-away and slide off at μ_k).
#![cfg(not(dim2))] // no 2D form yet: stickslip-fixtures2d compiles it empty

mod ordinary;

use ordinary::{C, Friction, Run, all_laws, ep, rel};
use stickslip_fixtures::ordinary::{Ground, box_on_slope};

const G: f64 = 9.81;
const MU: f64 = 0.5;
const GROUNDS: [Ground; 4] = [
    Ground::Cuboid,
    Ground::TriMesh,
    Ground::HeightField,
    Ground::Compound,
];

/// The laws that hold (Regul creeps below ġ_t0 by design), after plain rapier.
fn frictions() -> Vec<Friction> {
    let mut f = vec![Friction::Plain];
    f.extend(
        all_laws(MU)
            .into_iter()
            .filter(|f| !matches!(f, Friction::Law("regul", _))),
    );
    f
}

/// Displacement along the slope over 10 s after 0.5 s of settling (m).
fn creep(ground: Ground, dt: f64, friction: &Friction) -> f64 {
    let mut run = Run::new(box_on_slope(ground, 0.95 * MU, MU as f32, dt), friction);
    run.run_for(0.5);
    let x0 = run.body(0).translation().x as f64;
    run.run_for(10.0);
    run.body(0).translation().x as f64 - x0
}

/// Acceleration along the slope from 0.5 s to 1.5 s (m/s²): the cube crosses several cells.
fn slide(ground: Ground, dt: f64, friction: &Friction) -> f64 {
    let mut run = Run::new(box_on_slope(ground, 1.4 * MU, MU as f32, dt), friction);
    run.run_for(0.5);
    let v0 = run.body(0).linvel().x as f64;
    run.run_for(1.0);
    run.body(0).linvel().x as f64 - v0
}

#[test]
fn a_cube_holds_below_break_away_on_every_ground() {
    let g_ba = MU / C;
    for dt in [1.0 / 60.0, 1.0 / 240.0] {
        for ground in GROUNDS {
            let plain = creep(ground, dt, &Friction::Plain);
            let hooked = creep(ground, dt, &Friction::Hooked);
            for f in frictions().iter().skip(1) {
                let x = creep(ground, dt, f);
                println!(
                    "{ground:?} {:.0} Hz {}: creep {x:.2e} m (no-op hook {hooked:.2e}, plain {plain:.2e}, g_ba {g_ba:.0e})",
                    1.0 / dt,
                    f.name()
                );
                assert!(
                    x.abs() <= g_ba + plain.abs(),
                    "{ground:?} at {:.0} Hz, {}: crept {x:e} m, plain rapier {plain:e}",
                    1.0 / dt,
                    f.name()
                );
            }
        }
    }
}

#[test]
fn a_cube_slides_with_the_kinetic_acceleration_on_every_ground() {
    let theta = (1.4 * MU).atan();
    let expect = G * (theta.sin() - MU * theta.cos());
    for dt in [1.0 / 60.0, 1.0 / 240.0] {
        for ground in GROUNDS {
            let plain = rel(slide(ground, dt, &Friction::Plain), expect);
            let hooked = rel(slide(ground, dt, &Friction::Hooked), expect);
            if ground != Ground::Compound {
                assert!(hooked.abs() <= 0.01, "{ground:?}: no-op hook {hooked:+e}");
            }
            for f in frictions().iter().skip(1) {
                let e = rel(slide(ground, dt, f), expect);
                println!(
                    "{ground:?} {:.0} Hz {}: acceleration {:+.3} % (no-op hook {:+.3} %, plain {:+.3} %)",
                    1.0 / dt,
                    f.name(),
                    100.0 * e,
                    100.0 * hooked,
                    100.0 * plain
                );
                assert!(
                    (e - hooked).abs() <= 0.005,
                    "{ground:?} at {:.0} Hz, {}: {e:+e}, no-op hook {hooked:+e}",
                    1.0 / dt,
                    f.name()
                );
            }
        }
    }
}

#[test]
fn a_cube_put_down_below_break_away_stays_where_it_was_put() {
    let g_ba = MU / C;
    let mut laws = frictions().split_off(1);
    laws.push(Friction::Law("ep 0.5/0.4", ep(MU, 0.4)));
    for dt in [1.0 / 60.0, 1.0 / 120.0, 1.0 / 240.0] {
        for ground in GROUNDS {
            let moved = |f: &Friction| {
                let mut run = Run::new(box_on_slope(ground, 0.9 * MU, MU as f32, dt), f);
                let x0 = run.body(0).translation().x as f64;
                run.run_for(3.0);
                run.body(0).translation().x as f64 - x0
            };
            let hooked = moved(&Friction::Hooked);
            let plain = moved(&Friction::Plain);
            for f in &laws {
                let x = moved(f);
                println!(
                    "{ground:?} {:.0} Hz {}: moved {x:.2e} m since put down (plain {plain:.2e}, no-op hook {hooked:.2e})",
                    1.0 / dt,
                    f.name()
                );
                assert!(
                    (x - plain).abs() <= g_ba,
                    "{ground:?} at {:.0} Hz, {}: moved {x:e} m, plain rapier {plain:e}",
                    1.0 / dt,
                    f.name()
                );
            }
        }
    }
}
