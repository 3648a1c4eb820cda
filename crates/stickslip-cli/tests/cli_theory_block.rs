//! `stickslip theory` and `stickslip block` end to end. Invariants: the JSON of `theory psi`
//! equals the seed's closed forms (Eq. 34–36) and `theory static` Eq. 4/6/8; `theory mu-eff`
//! is μ0 (1 − α Ψ); `block` reproduces the seed's Example 1 behaviour (EP sticks in phase I
//! within g_ba, Phys and EP end within 1 % of each other); bad arguments (unknown waveform,
//! μ_ba > μ_max, malformed force profile, negative stiffness) exit with code 2 and a message,
//! never a panic.

use serde_json::Value;
use std::process::{Command, Output};

fn run(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_stickslip"))
        .args(args)
        .output()
        .expect("the binary runs")
}

fn json(args: &[&str]) -> Value {
    let mut all = vec!["--json"];
    all.extend_from_slice(args);
    let out = run(&all);
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("valid JSON")
}

fn num(v: &Value, key: &str) -> f64 {
    v[key]
        .as_f64()
        .unwrap_or_else(|| panic!("{key} missing in {v}"))
}

#[test]
fn theory_matches_the_closed_forms() {
    for (w, beta, expect) in [
        ("sawtooth-right", "0.8", 1.0 - 0.8 / 2.0),
        ("sawtooth-left", "3", 2.0 / (2.0 + 3.0)),
        ("square", "2", 1.0 - 2.0 / 8.0),
        ("square", "6", 2.0 / 6.0),
    ] {
        let v = json(&["theory", "psi", "--waveform", w, "--beta", beta]);
        assert!((num(&v, "psi") - expect).abs() < 1e-9, "{w} {beta}: {v}");
    }
    let v = json(&[
        "theory",
        "mu-eff",
        "--waveform",
        "square",
        "--alpha",
        "0.5",
        "--beta",
        "2",
        "--mu0",
        "0.4",
    ]);
    assert!((num(&v, "mu_eff") - 0.4 * (1.0 - 0.5 * 0.75)).abs() < 1e-9);
    for (dir, r, expect) in [
        ("normal", "0.4", 0.5 * (1.0 - 0.4)),
        ("tangential", "0.2", 0.5 - 0.2),
        ("transverse", "0.3", (0.25f64 - 0.09).sqrt()),
    ] {
        let v = json(&[
            "theory",
            "static",
            "--direction",
            dir,
            "--amplitude-ratio",
            r,
            "--mu0",
            "0.5",
        ]);
        assert!((num(&v, "mu_s") - expect).abs() < 1e-12, "{dir}: {v}");
    }
}

#[test]
fn block_runs_the_seeds_example_1() {
    let ep = json(&["block", "--law", "ep"]);
    let phys = json(&["block", "--law", "phys", "--integrator", "implicit"]);
    let g_ba = num(&ep, "break_away_displacement");
    let x1 = num(&ep["phases"][0], "x");
    assert!(
        x1.abs() <= g_ba && x1 > 0.5 * g_ba,
        "phase I: {x1} vs g_ba {g_ba}"
    );
    let (xe, xp) = (
        num(&ep, "final_displacement"),
        num(&phys, "final_displacement"),
    );
    assert!(((xe - xp) / xp).abs() < 0.01, "EP {xe} vs Phys {xp}");
    assert!(num(&ep["stats"], "accepted_steps") > 0.0);
}

#[test]
fn bad_arguments_fail_cleanly() {
    for args in [
        vec!["theory", "psi", "--waveform", "triangle", "--beta", "1"],
        vec![
            "theory",
            "mu-eff",
            "--waveform",
            "sine",
            "--alpha",
            "1.5",
            "--beta",
            "1",
            "--mu0",
            "0.5",
        ],
        vec!["block", "--mu-ba", "0.5", "--mu-max", "0.4"],
        vec!["block", "--c=-10"],
        vec!["block", "--force-profile", "0:1,oops"],
        vec!["block", "--force-profile", "1:0,0:1"],
    ] {
        let out = run(&args);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{args:?} panicked: {err}");
        assert!(err.contains("error"), "{args:?}: no message: {err}");
    }
}

#[test]
fn theory_drive_reverses_with_the_phase_shift() {
    // Elliptical vibration drives the compliant contact: the free drive velocity and the
    // blocking force have opposite signs and both flip with the phase shift; oblique linear
    // vibration (shift 0) drives too, and half a period later the other way.
    let v = json(&[
        "theory",
        "drive",
        "--alpha",
        "0.6",
        "--tangential",
        "1.5",
        "--mu0",
        "0.5",
        "--phase-shift",
        "0.25",
        "--phase-shift",
        "-0.25",
        "--phase-shift",
        "0",
        "--phase-shift",
        "0.5",
    ]);
    let points = v["points"].as_array().expect("points");
    assert_eq!(points.len(), 4);
    let (vd, block) = (
        num(&points[0], "drive_velocity"),
        num(&points[0], "blocking"),
    );
    assert!(vd > 0.0 && block < 0.0, "{v}");
    assert!(
        (num(&points[1], "drive_velocity") + vd).abs() < 1e-9 * vd,
        "{v}"
    );
    assert!((num(&points[1], "blocking") + block).abs() < 1e-9, "{v}");
    let oblique = num(&points[2], "drive_velocity");
    assert!(oblique != 0.0, "{v}");
    assert!(
        (num(&points[3], "drive_velocity") + oblique).abs() < 1e-9 * oblique.abs(),
        "{v}"
    );
    // μ̄ at rest is the blocking force over F̄ (the band is a single point when it drives).
    assert!((num(&points[0], "mu_eff") - block).abs() < 1e-9, "{v}");
}
