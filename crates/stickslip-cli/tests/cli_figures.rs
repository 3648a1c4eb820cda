//! `stickslip figures --quick` end to end. Invariants: it writes every figure of the user guide as a PNG
//! that decodes (the `image` crate) to its expected size and is not blank (many distinct
//! pixels, a spread of brightness), an SVG beside each, and `figures.json`, whose
//! rapier-measured points meet the physics tests' references: Popov μ̄ within 3 % of
//! μ0 (1 − α Ψ_w(β)) (`crates/stickslip-fixtures/tests/rapier_popov.rs`), the feeder's plain-rapier speed at 1/30 000 s
//! within 3 % of the rigid-body reference and EP within 3 % of plain rapier at 1/3000 s
//! (`crates/stickslip-fixtures/tests/rapier_feeder.rs`), on the incline EP within g_ba and Regul creeping at
//! ġ_t0 tan θ/μ_ve within 2 % (`crates/stickslip-fixtures/tests/rapier_incline.rs`), and Example 1 in rapier with EP
//! sticking within g_ba in phase I and ending within 2 % of the core's Phys
//! (`crates/stickslip-fixtures/tests/rapier_example1.rs`). A directory that cannot be created is a clear error.

use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Command;

const FIGURES: [(&str, u32, u32); 8] = [
    ("switch_function", 900, 600),
    ("sliding_curves", 900, 600),
    ("example1", 1200, 1200),
    ("example1_timings", 900, 600),
    ("popov_fig4", 900, 600),
    ("static_friction", 900, 600),
    ("incline_creep", 900, 600),
    ("feeder_speed", 900, 600),
];

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("stickslip-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

/// Decodes `path` and checks its size and that it is not blank.
pub fn check_png(path: &Path, w: u32, h: u32) {
    let img = image::open(path)
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()))
        .to_rgb8();
    assert_eq!(img.dimensions(), (w, h), "{}", path.display());
    let lum: Vec<f64> = img
        .pixels()
        .map(|p| (p[0] as f64 + p[1] as f64 + p[2] as f64) / 3.0)
        .collect();
    let mean = lum.iter().sum::<f64>() / lum.len() as f64;
    let var = lum.iter().map(|l| (l - mean).powi(2)).sum::<f64>() / lum.len() as f64;
    let mut colors: Vec<[u8; 3]> = img.pixels().map(|p| p.0).collect();
    colors.sort_unstable();
    colors.dedup();
    println!(
        "{}: {w}x{h}, luminance std {:.1}, {} colours",
        path.display(),
        var.sqrt(),
        colors.len()
    );
    assert!(var.sqrt() > 10.0, "{} looks blank", path.display());
    assert!(colors.len() > 20, "{} has too few colours", path.display());
}

fn f(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

#[test]
fn quick_figures_are_valid_pngs_and_their_rapier_points_meet_the_references() {
    let dir = tmp("figures");
    let out = Command::new(env!("CARGO_BIN_EXE_stickslip"))
        .args(["figures", "--quick", "--out"])
        .arg(&dir)
        .output()
        .expect("the binary runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    for (name, w, h) in FIGURES {
        check_png(&dir.join(format!("{name}.png")), w, h);
        let svg = std::fs::read_to_string(dir.join(format!("{name}.svg"))).unwrap();
        assert!(svg.contains("<svg") && svg.len() > 1000, "{name}.svg");
    }
    let j: Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("figures.json")).unwrap()).unwrap();

    // Popov Fig. 4 points (crates/stickslip-fixtures/tests/rapier_popov.rs: 3 %).
    let mut worst: f64 = 0.0;
    let mut n = 0;
    for curve in j["popov"].as_array().unwrap() {
        for p in curve[1].as_array().unwrap() {
            let err = (f(&p["rapier"]) - f(&p["theory"])) / f(&p["theory"]);
            worst = worst.max(err.abs());
            n += 1;
            assert!(err.abs() < 0.03, "{} {p}", curve[0]);
        }
    }
    assert_eq!(n, 8, "two points per waveform");
    println!("popov: {n} points, worst {:.2} %", 100.0 * worst);

    // Feeder (crates/stickslip-fixtures/tests/rapier_feeder.rs: plain at 1/30000 s vs reference, EP vs plain, 3 %).
    let feeder = j["feeder"].as_array().unwrap();
    assert_eq!(feeder.len(), 2);
    for p in feeder {
        let (r, plain, ep, coarse) = (
            f(&p["reference"]),
            f(&p["plain_fine"]),
            f(&p["ep_coarse"]),
            f(&p["plain_coarse"]),
        );
        println!(
            "feeder Γ {:.2}: reference {r:.5}, plain 1/30000 {plain:.5}; 1/3000: EP {ep:.5}, \
             plain {coarse:.5}",
            f(&p["throw_number"])
        );
        assert!(((plain - r) / r).abs() < 0.03, "{p}");
        assert!(((ep - coarse) / coarse).abs() < 0.03, "{p}");
    }

    // Incline (crates/stickslip-fixtures/tests/rapier_incline.rs).
    let secs = f(&j["incline_seconds"]);
    let g_ba = 0.5 / 1e4;
    for m in j["incline"].as_array().unwrap() {
        let (label, final_x, max_x) = (m[0].as_str().unwrap(), f(&m[2]), f(&m[3]));
        println!("incline {label}: final {final_x:.3e} m, max {max_x:.3e} m");
        if label.starts_with("EP") {
            assert!(max_x <= g_ba, "{m}");
        }
        if let Some(v) = m[1].as_f64() {
            let expect = v * (0.95 * 0.5) / 0.55 * secs;
            if v >= 0.01 {
                assert!(
                    ((final_x - expect) / expect).abs() < 0.02,
                    "{m} vs {expect}"
                );
            }
        }
    }

    // Example 1 (crates/stickslip-fixtures/tests/rapier_example1.rs).
    let ex = j["example1"].as_array().unwrap();
    let phys = ex.iter().find(|e| e[0] == "Phys").unwrap();
    let ep = ex.iter().find(|e| e[0] == "EP").unwrap();
    let x_ref = f(&phys[1]);
    let (x_rapier, phase1) = (f(&ep[2]), f(&ep[3]));
    println!("example1: rapier EP {x_rapier:.5} m vs Phys {x_ref:.5} m, phase I max {phase1:.2e}");
    assert!(((x_rapier - x_ref) / x_ref).abs() < 0.02);
    assert!(phase1 <= 0.3 / 1e4);
    assert!(!j["timings"].as_array().unwrap().is_empty());
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn an_output_path_that_is_a_file_is_a_clear_error() {
    let file = tmp("figures-file");
    std::fs::write(&file, "not a directory").unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_stickslip"))
        .args(["figures", "--quick", "--out"])
        .arg(file.join("sub"))
        .output()
        .expect("the binary runs");
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("cannot write"), "{err}");
    assert!(!err.contains("panicked"), "{err}");
    let _ = std::fs::remove_file(&file);
}
