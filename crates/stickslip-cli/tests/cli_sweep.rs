//! `stickslip sweep` end to end. Invariants: a sweep's numbers (CSV and JSON) are bit-for-bit
//! the same on 1 and on 2 worker threads (every point is its own world); a small Popov sweep
//! measured in rapier meets the theory μ0 (1 − α Ψ_w(β)) within the physics tests' 3 %
//! (`crates/stickslip-fixtures/tests/rapier_popov.rs`) and a small feeder sweep with plain rapier at 1/30 000 s meets
//! the rigid-body reference within 3 % (`crates/stickslip-fixtures/tests/rapier_feeder.rs`); both write a heat-map PNG
//! of the expected size; bad ranges and options exit with code 2 and a message naming the
//! option, never a panic and never a huge allocation.

use std::path::PathBuf;
use std::process::{Command, Output};

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("stickslip-sweep-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

fn run(args: &[&str], out: &std::path::Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_stickslip"))
        .args(args)
        .arg("--out")
        .arg(out)
        .output()
        .expect("the binary runs")
}

fn ok(args: &[&str], out: &std::path::Path) {
    let o = run(args, out);
    assert!(
        o.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&o.stderr)
    );
}

fn png_size(path: &std::path::Path) -> (u32, u32) {
    let img = image::open(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    (img.width(), img.height())
}

#[test]
fn popov_sweep_is_thread_independent_and_matches_theory() {
    let args = [
        "sweep",
        "popov",
        "--waveforms",
        "sine,square",
        "--beta",
        "2:8:2",
        "--alpha",
        "0.3:0.6:2",
    ];
    let (d1, d2) = (tmp("popov1"), tmp("popov2"));
    ok(&[&args[..], &["--threads", "1"]].concat(), &d1);
    ok(&[&args[..], &["--threads", "2"]].concat(), &d2);
    for f in ["popov.csv", "popov.json"] {
        let (a, b) = (
            std::fs::read(d1.join(f)).unwrap(),
            std::fs::read(d2.join(f)).unwrap(),
        );
        assert_eq!(a, b, "{f} differs between 1 and 2 threads");
    }
    let csv = std::fs::read_to_string(d1.join("popov.csv")).unwrap();
    let mut worst: f64 = 0.0;
    let rows: Vec<&str> = csv.lines().skip(1).collect();
    assert_eq!(rows.len(), 8);
    for row in rows {
        let c: Vec<&str> = row.split(',').collect();
        let (theory, rapier): (f64, f64) = (c[3].parse().unwrap(), c[4].parse().unwrap());
        let err = (rapier - theory) / theory;
        worst = worst.max(err.abs());
        assert!(err.abs() < 0.03, "{row}");
    }
    println!("popov sweep: worst relative error {:.2} %", 100.0 * worst);
    for w in ["sine", "square"] {
        assert_eq!(png_size(&d1.join(format!("popov_{w}.png"))), (900, 600));
    }
    let _ = std::fs::remove_dir_all(&d1);
    let _ = std::fs::remove_dir_all(&d2);
}

#[test]
fn feeder_sweep_is_thread_independent_and_matches_the_reference() {
    let args = [
        "sweep",
        "feeder",
        "--amplitude",
        "1:1.5:2",
        "--frequency",
        "25",
        "--angle",
        "25",
        "--law",
        "plain",
        "--dt",
        "3.3333333333333335e-5",
    ];
    let (d1, d2) = (tmp("feeder1"), tmp("feeder2"));
    ok(&[&args[..], &["--threads", "1"]].concat(), &d1);
    ok(&[&args[..], &["--threads", "2"]].concat(), &d2);
    let (a, b) = (
        std::fs::read(d1.join("feeder.csv")).unwrap(),
        std::fs::read(d2.join("feeder.csv")).unwrap(),
    );
    assert_eq!(a, b, "feeder.csv differs between 1 and 2 threads");
    let csv = String::from_utf8(a).unwrap();
    for row in csv.lines().skip(1) {
        let c: Vec<f64> = row.split(',').map(|s| s.parse().unwrap()).collect();
        println!("feeder {row}");
        assert!(c[6].abs() < 0.03, "{row}");
    }
    assert_eq!(png_size(&d1.join("feeder_angle_25.png")), (900, 600));
    let _ = std::fs::remove_dir_all(&d1);
    let _ = std::fs::remove_dir_all(&d2);
}

#[test]
fn bad_ranges_and_options_are_clear_errors() {
    let d = tmp("bad");
    let cases: &[(&[&str], &str)] = &[
        (&["sweep", "popov", "--beta", "5:1:3"], "--beta"),
        (&["sweep", "popov", "--beta", "1:2:0"], "--beta"),
        (&["sweep", "popov", "--beta", "a:2:3"], "not a number"),
        (&["sweep", "popov", "--beta", "1:2"], "LO:HI:N"),
        (
            &["sweep", "popov", "--beta", "1:2:99999999999999999999"],
            "count",
        ),
        (&["sweep", "popov", "--beta", "0:2:3"], "--beta"),
        (&["sweep", "popov", "--alpha", "0.5:1.5:3"], "--alpha"),
        (&["sweep", "popov", "--beta", "nan:2:3"], "finite"),
        (
            &[
                "sweep",
                "popov",
                "--beta",
                "0.1:10:1000",
                "--alpha",
                "0.1:1:1000",
            ],
            "limit",
        ),
        (&["sweep", "popov", "--waveforms", "sine,banana"], "banana"),
        (&["sweep", "popov", "--waveforms", "sine,sine"], "twice"),
        (&["sweep", "popov", "--threads", "0"], "--threads"),
        (&["sweep", "feeder", "--amplitude=-1:2:3"], "--amplitude"),
        (
            &["sweep", "feeder", "--frequency", "20:1e6:3"],
            "--frequency",
        ),
        (&["sweep", "feeder", "--angle", "0:120:3"], "--angle"),
        (&["sweep", "feeder", "--dt", "0.01"], "--dt"),
        (&["sweep", "feeder", "--dt=-1"], "--dt"),
        (&["sweep", "feeder", "--periods", "20"], "--periods"),
        (&["sweep", "feeder", "--periods", "0:20"], "--periods"),
        (&["sweep", "feeder", "--mu", "inf"], "--mu"),
    ];
    for (args, needle) in cases {
        let o = run(args, &d);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(needle), "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{args:?}: {err}");
    }
    assert!(!d.exists(), "a refused sweep wrote nothing");
}
