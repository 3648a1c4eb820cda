//! Every scenario shipped in `scenarios/` parses, builds and runs, and shows the physics it is
//! there for, checked on a short run each:
//! - `example1_block`: phase I sticks within g_ba = μ_ba/c; at the end of phase III the block's
//!   displacement is within 3 % of the core's exact switched (Phys) reference;
//! - `incline`: at 0.95 of the break-away angle the EP box stays within g_ba while the
//!   regularized box creeps more than 50× as far;
//! - `belt_stick_slip`: the block first sticks to the belt (moves with it at v_b, spring force
//!   k·x = friction), breaks away at k·x = μ_ba N, and the stick-slip cycle that follows has the
//!   analytic period T = 2Δ/v_b + (π + 2 atan(v_b/(ωΔ)))/ω within 3 %;
//! - `popov_plate_sweep`: holding force is μ0 (1 − α) (Popov Eq. 4), and the steady sliding
//!   coefficient rises with drag speed as μ0 (1 − α Ψ(β)) of the core theory (within 5 %);
//! - `vibrating_conveyor`: with the vibration on the parts flow downhill, without it they stay;
//! - `row_250`: ≥ 250 stickslip contacts, states tracked one-to-one, nothing explodes;
//! - `elliptical_drive` (superimposed `components`): each free sled drifts at the free drive
//!   velocity of Popov's spring contact for its plate's ellipse (within 3 %), the two in
//!   opposite directions.
//!
//! Every file also round-trips through `to_toml_string`, and every run keeps all poses finite.
//! A scenario file without a check here fails the test, so new scenarios come with an invariant.

use stickslip_core::law::{Law, Regime};
use stickslip_scenario::{Runner, Scenario, Scene};

fn scenarios_dir() -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenarios")
}

fn load(name: &str) -> Scenario {
    Scenario::from_path(scenarios_dir().join(format!("{name}.toml")))
        .unwrap_or_else(|e| panic!("{name}: {e}"))
}

fn body(scene: &Scene, name: &str) -> rapier3d::prelude::RigidBodyHandle {
    scene
        .bodies
        .iter()
        .find(|b| b.name == name)
        .unwrap_or_else(|| panic!("no body {name}"))
        .handle
}

fn x(runner: &Runner, name: &str) -> f64 {
    let s = runner.scene();
    s.world.bodies[body(s, name)].translation().x as f64
}

fn start_x(runner: &Runner, name: &str) -> f64 {
    runner
        .scene()
        .bodies
        .iter()
        .find(|b| b.name == name)
        .unwrap()
        .start[0]
}

fn assert_finite(runner: &Runner) {
    let summary = runner.summary();
    assert!(summary.finite, "{}: non-finite state", summary.scenario);
}

/// The friction force on `name`'s body along x and the normal force, from its contact report.
fn contact_of(runner: &Runner, name: &str) -> Option<(f64, f64, Regime)> {
    let s = runner.scene();
    let h = body(s, name);
    s.stickslip.reports().unwrap().iter().find_map(|r| {
        let b2 = s.world.colliders[r.collider2].parent();
        let b1 = s.world.colliders[r.collider1].parent();
        let sign = if b2 == Some(h) {
            1.0
        } else if b1 == Some(h) {
            -1.0
        } else {
            return None;
        };
        Some((sign * r.friction_force[0] as f64, r.normal_force, r.regime))
    })
}

#[test]
fn every_shipped_scenario_has_a_check() {
    let checked = [
        "example1_block",
        "incline",
        "belt_stick_slip",
        "popov_plate_sweep",
        "vibrating_conveyor",
        "row_250",
        "elliptical_drive",
        // The built-in one: its physics (EP holds, vibration conveys at Popov's speed, plain
        // holds) is checked by the CLI's main-job test, crates/stickslip-cli/tests/cli_run.rs.
        "showcase",
    ];
    let mut found = Vec::new();
    for entry in std::fs::read_dir(scenarios_dir()).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "toml") {
            let stem = path.file_stem().unwrap().to_string_lossy().into_owned();
            assert!(checked.contains(&stem.as_str()), "no check for {stem}");
            // Each round-trips through TOML, builds and survives a few steps.
            let scenario = load(&stem);
            let text = scenario.to_toml_string().unwrap();
            let back = Scenario::from_toml_str(&text).unwrap();
            assert_eq!(back.to_toml_string().unwrap(), text, "{stem} round trip");
            let scene = scenario.build().unwrap();
            assert!(scene.steps >= 1);
            let mut r = Runner::new(scene);
            r.run(3);
            assert_finite(&r);
            found.push(stem);
        }
    }
    assert_eq!(found.len(), checked.len(), "found {found:?}");
}

#[test]
fn builtin_is_the_showcase_file() {
    let builtin = Scenario::builtin();
    assert_eq!(builtin.name, load("showcase").name);
}

#[test]
fn example1_block_sticks_then_matches_the_switched_reference() {
    use stickslip_theory::block::{Block, ForceProfile, Integrator, Tolerances, simulate};
    let scenario = load("example1_block");
    let Law::ElastoPlastic(ep) = &scenario.materials["ep"] else {
        panic!("EP expected")
    };
    let g_ba = ep.break_away_displacement();
    let mut r = Runner::new(scenario.build().unwrap());
    let steps = r.scene().steps;
    let mut max_phase1 = 0.0f64;
    let mut regimes = [0usize; 3];
    let mut t = 0.0;
    while r.steps_done() < steps {
        r.step();
        t = r.time();
        let d = (x(&r, "block") - start_x(&r, "block")).abs();
        if t <= 1.0 {
            max_phase1 = max_phase1.max(d);
        }
        if let Some((_, _, regime)) = contact_of(&r, "block") {
            regimes[regime as usize] += 1;
        }
    }
    assert_finite(&r);
    println!("phase I max |x| = {max_phase1:.3e} m (g_ba {g_ba:.1e}), regimes {regimes:?}");
    assert!(max_phase1 <= g_ba, "crept {max_phase1} > g_ba {g_ba}");
    assert!(
        regimes.iter().all(|&n| n > 0),
        "sticking, stick-slip and sliding all occur: {regimes:?}"
    );

    // The core's exact switched reference with the same block and force profile.
    let profile = ForceProfile::example1(0.3 * 9.81, 0.95, 1.5).unwrap();
    let phys = Law::Physical(
        stickslip_core::law::Physical::new(
            0.3,
            stickslip_core::sliding_curve::Curve::constant(0.32).unwrap(),
        )
        .unwrap(),
    );
    let reference = simulate(
        &Block::new(1.0, 9.81, phys).unwrap(),
        &profile,
        Integrator::Implicit,
        Tolerances::default(),
        &[3.0],
    )
    .unwrap();
    let x_ref = reference.phases[0].x;
    let x_end = x(&r, "block") - start_x(&r, "block");
    println!("x(3 s) = {x_end:.5} m, Phys reference {x_ref:.5} m, t = {t:.4}");
    assert!(
        ((x_end - x_ref) / x_ref).abs() < 0.03,
        "x {x_end} vs reference {x_ref}"
    );
}

#[test]
fn incline_ep_sticks_and_regul_creeps() {
    let scenario = load("incline");
    let Law::ElastoPlastic(ep) = &scenario.materials["ep"] else {
        panic!("EP expected")
    };
    let g_ba = ep.break_away_displacement();
    let mut r = Runner::new(scenario.build().unwrap());
    r.run(60); // settle 1 s
    let slope_x = |r: &Runner, name: &str| {
        // Displacement along the slope direction t = (cos θ, sin θ, 0).
        let theta = 25.408f64.to_radians();
        let s = r.scene();
        let p = s.world.bodies[body(s, name)].translation();
        p.x as f64 * theta.cos() + p.y as f64 * theta.sin()
    };
    let names = ["ep", "regul", "coulomb", "rapier"];
    let before: Vec<f64> = names.iter().map(|n| slope_x(&r, n)).collect();
    r.run(120); // 2 s more
    let moved: Vec<f64> = names
        .iter()
        .zip(&before)
        .map(|(n, b)| slope_x(&r, n) - b)
        .collect();
    println!("moved over 2 s (ep, regul, coulomb, rapier): {moved:?}, g_ba {g_ba:.1e}");
    assert_finite(&r);
    assert!(moved[0].abs() <= g_ba, "EP moved {}", moved[0]);
    assert!(
        moved[1].abs() > 50.0 * moved[0].abs().max(g_ba / 10.0),
        "Regul should creep: {}",
        moved[1]
    );
    assert!(moved[1] < 0.0, "creep goes downhill (−x along the slope)");
}

#[test]
fn belt_block_sticks_then_breaks_away() {
    let scenario = load("belt_stick_slip");
    let v_b = 0.1;
    let (k, m, g, mu_ba) = (100.0, 1.0, 9.81, 0.5);
    let mut r = Runner::new(scenario.build().unwrap());
    r.run(100); // 0.2 s: riding on the belt
    let t = r.time();
    let x_block = x(&r, "block") - start_x(&r, "block");
    let (f_fric, f_n, regime) = contact_of(&r, "block").expect("contact");
    println!(
        "t {t:.3}: x {x_block:.5} (belt {:.5}), friction {f_fric:.3} N, k x {:.3} N, N {f_n:.3}, {regime:?}",
        v_b * t,
        k * x_block
    );
    // It rides with the belt (a few steps' lag while the contact forms at t = 0).
    let s = r.scene();
    let v = s.world.bodies[body(s, "block")].linvel().x as f64;
    assert!((v - v_b).abs() < 0.01 * v_b, "moves with the belt: v {v}");
    assert!((x_block - v_b * t).abs() < 0.1 * v_b * t, "x {x_block}");
    assert_eq!(regime, Regime::Sticking);
    assert!((f_n - m * g).abs() < 0.02 * m * g, "normal force {f_n}");
    assert!(
        (f_fric - k * x_block).abs() < 0.05 * k * x_block,
        "friction carries the spring"
    );
    // Break-away at k x = μ_ba N (x_ba = 0.049 m), then slip at μ_k, re-stick, and so on: a
    // limit cycle with period T = 2Δ/v_b + (π + 2 atan(v_b/(ωΔ)))/ω.
    let x_ba = mu_ba * m * g / k;
    let (omega, delta) = ((k / m).sqrt(), (mu_ba - 0.3) * m * g / k);
    let period =
        2.0 * delta / v_b + (std::f64::consts::PI + 2.0 * (v_b / (omega * delta)).atan()) / omega;
    let mut x_break = None;
    let mut mu_hold = 0.0f64;
    let mut sticking = true;
    let mut restick_times = Vec::new();
    let mut x_min = f64::INFINITY;
    while r.time() < 5.0 - 1e-9 {
        r.step();
        let (f, n, regime) = contact_of(&r, "block").expect("contact");
        let xb = x(&r, "block") - start_x(&r, "block");
        let now_sticking = regime == Regime::Sticking;
        if x_break.is_none() {
            mu_hold = mu_hold.max(f.abs() / n);
            if f.abs() / n > 0.999 * mu_ba {
                x_break = Some(xb);
            }
        }
        // A re-stick starts a cycle (a re-stick right after a brief slip is the same one).
        if !sticking && now_sticking && restick_times.last().is_none_or(|&t| r.time() - t > 0.1) {
            restick_times.push(r.time());
        }
        if x_break.is_some() {
            x_min = x_min.min(xb);
        }
        sticking = now_sticking;
    }
    let x_break = x_break.expect("breaks away");
    let periods: Vec<f64> = restick_times.windows(2).map(|w| w[1] - w[0]).collect();
    let mean = periods.iter().sum::<f64>() / periods.len() as f64;
    println!(
        "break-away at x {x_break:.5} (μ_ba N/k {x_ba:.5}), slipped back to {x_min:.5}, re-sticks at {restick_times:.3?}, period {mean:.4} s (analytic {period:.4} s)"
    );
    assert!(
        (x_break - x_ba).abs() < 0.01 * x_ba,
        "breaks away at μ_ba N / k"
    );
    assert!(
        mu_hold < 1.001 * mu_ba,
        "holds with at most μ_ba: {mu_hold}"
    );
    assert!(x_min < x_ba - 0.03, "slips back after break-away");
    assert!(periods.len() >= 4, "several cycles in 5 s");
    assert!(
        ((mean - period) / period).abs() < 0.03,
        "stick-slip period {mean} vs {period}"
    );
    assert_finite(&r);
}

#[test]
fn popov_sweep_holds_at_reduced_static_friction_and_mu_rises_with_speed() {
    use stickslip_core::popov;
    use stickslip_core::waveform::Waveform;
    let scenario = load("popov_plate_sweep");
    let (mu0, alpha, f, c) = (0.5, 0.5, 20000.0, 1e5);
    let mut r = Runner::new(scenario.build().unwrap());
    let names = ["v0_010", "v0_050", "v0_150", "v0_300", "v0_600"];
    let speeds = [0.01, 0.05, 0.15, 0.3, 0.6];
    // Break-away of the slowest box: the spring force at the last holding step.
    let mut hold_max = 0.0f64;
    let mut mus: Vec<Vec<f64>> = vec![Vec::new(); names.len()];
    while r.time() < 3.0 - 1e-9 {
        r.step();
        if let Some((fx, n, regime)) = contact_of(&r, "v0_010")
            && regime == Regime::Sticking
            && n > 0.0
        {
            hold_max = hold_max.max(fx.abs() / n);
        }
        if r.time() > 2.0 {
            for (k, name) in names.iter().enumerate() {
                if let Some((fx, n, _)) = contact_of(&r, name) {
                    mus[k].push(fx.abs() / n);
                }
            }
        }
    }
    assert_finite(&r);
    println!(
        "largest holding coefficient {hold_max:.4}, Popov static μ0 (1 − α) = {:.4}",
        mu0 * (1.0 - alpha)
    );
    assert!(
        hold_max <= mu0 * (1.0 - alpha) * 1.03,
        "holds no more than μ0 (1 − α)"
    );
    assert!(hold_max >= mu0 * (1.0 - alpha) * 0.9, "and up to it");
    let mut last = 0.0;
    for (k, v0) in speeds.iter().enumerate() {
        let mean = mus[k].iter().sum::<f64>() / mus[k].len() as f64;
        let beta = c * v0 / (mu0 * alpha * f);
        let theory = mu0 * (1.0 - alpha * popov::psi(&Waveform::Sine, beta).unwrap());
        println!("v0 {v0}: β {beta:.2}, μ̄ {mean:.4}, theory {theory:.4}");
        assert!(
            ((mean - theory) / theory).abs() < 0.05,
            "v0 {v0}: μ̄ {mean} vs {theory}"
        );
        assert!(mean >= last - 1e-3, "μ̄ rises with speed");
        last = mean;
    }
}

#[test]
fn conveyor_flows_with_vibration_and_stands_still_without() {
    let scenario = load("vibrating_conveyor");
    let downhill = |r: &Runner| -> Vec<f64> {
        let theta = (-16.699f64).to_radians();
        let s = r.scene();
        s.bodies
            .iter()
            .filter(|b| b.group == "box" || b.group == "pin")
            .map(|b| {
                let p = s.world.bodies[b.handle].translation();
                (p.x as f64 - b.start[0]) * theta.cos() + (p.y as f64 - b.start[1]) * theta.sin()
            })
            .collect()
    };
    let mut on = Runner::new(scenario.build().unwrap());
    let mut off = Runner::new(scenario.build().unwrap());
    let trough: Vec<_> = off
        .scene()
        .colliders
        .iter()
        .filter(|c| c.vibration.is_some())
        .map(|c| c.handle)
        .collect();
    assert_eq!(trough.len(), 1);
    for h in trough {
        off.scene_mut().stickslip.remove_vibration(h);
    }
    on.run(120);
    off.run(120);
    let (d_on, d_off) = (downhill(&on), downhill(&off));
    println!("after 1 s: with vibration {d_on:?}\n           without {d_off:?}");
    assert_eq!(d_on.len(), 5);
    assert!(d_on.iter().all(|&d| d > 0.01), "all parts flow downhill");
    assert!(
        d_off.iter().all(|&d| d.abs() < 1e-3),
        "without vibration they stay"
    );
    assert_finite(&on);
    assert_finite(&off);
}

#[test]
fn row_250_tracks_every_contact() {
    let scenario = load("row_250");
    let mut r = Runner::new(scenario.build().unwrap());
    assert_eq!(r.scene().bodies.len(), 251);
    let mut regimes_seen = [false; 3];
    for _ in 0..150 {
        r.step();
        let n = r.scene().stickslip.reports().unwrap().len();
        assert_eq!(n, 250, "one contact per box at step {}", r.steps_done());
        for rep in r.scene().stickslip.reports().unwrap() {
            regimes_seen[rep.regime as usize] = true;
        }
        let live = r.scene_mut().stickslip.active_contacts();
        assert_eq!(live, 250, "one friction state per contact");
    }
    let summary = r.summary();
    assert!(summary.finite);
    assert_eq!(summary.max_contacts, 250);
    assert!(regimes_seen[Regime::Sticking as usize]);
    // No box left the belt plane or flew off.
    for b in &summary.bodies {
        if b.name.starts_with("box_") {
            assert!(
                b.displacement[1].abs() < 0.005,
                "{}: dy {}",
                b.name,
                b.displacement[1]
            );
            assert!(b.distance < 0.2, "{}: |d| {}", b.name, b.distance);
        }
    }
    println!(
        "row-250 after {} steps: regimes seen {regimes_seen:?}, energy {:.4} J",
        summary.steps, summary.dissipated_energy
    );
}

#[test]
fn elliptical_drive_moves_the_sleds_at_the_theorys_speed() {
    use stickslip_fixtures::VibratingPlate;
    use stickslip_rapier::VibrationMode;
    let mut r = Runner::new(load("elliptical_drive").build().unwrap());
    // 120 periods of 400 steps from rest, then the mean speed over 10 periods (0.2 s).
    r.run(120 * 400);
    let x0 = [x(&r, "sled_a"), x(&r, "sled_b")];
    r.run(10 * 400);
    for (i, (name, shift)) in [("sled_a", 0.25), ("sled_b", -0.25)]
        .into_iter()
        .enumerate()
    {
        let theory = VibratingPlate::elliptical(0.6, 0.75, shift, VibrationMode::TimeResolved)
            .unwrap()
            .theory_drive_velocity()
            .unwrap();
        let measured = (x(&r, name) - x0[i]) / 0.2;
        println!("{name}: {measured:+.4e} m/s, theory {theory:+.4e} m/s");
        assert!(theory.abs() > 1e-3, "the ellipse drives");
        assert!(
            (measured - theory).abs() <= 0.03 * theory.abs(),
            "{name}: measured {measured} m/s, theory {theory} m/s"
        );
    }
    assert_finite(&r);
}
