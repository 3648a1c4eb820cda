//! `stickslip run --snapshot-out` / `--resume`: a run of 2N steps ends exactly where a run of N
//! steps, saved and resumed for N more, ends — the `--json` summaries (every body's
//! displacement and velocity, contact and regime counts, dissipated energy, step count and
//! simulated time) are identical to the last digit of serde_json's shortest round-trip
//! printing, i.e. bit for bit. Without `--steps` a resumed run completes the scenario's own
//! duration. A snapshot of another scenario, a garbage file and a missing file are clean
//! errors (exit code 2, a message, no panic), and a failed write leaves no file behind.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_stickslip"))
}

fn scenario(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../scenarios")
        .join(format!("{name}.toml"))
}

fn tmpdir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("stickslip-snap-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn run(cmd: &mut Command) -> Output {
    let out = cmd.output().expect("runs");
    if !out.status.success() {
        println!("stdout:\n{}", String::from_utf8_lossy(&out.stdout));
        println!("stderr:\n{}", String::from_utf8_lossy(&out.stderr));
    }
    out
}

/// The JSON summary without the wall-clock time.
fn summary(out: &Output) -> serde_json::Value {
    assert!(out.status.success(), "exit {:?}", out.status.code());
    let mut v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    v.as_object_mut().unwrap().remove("wall_seconds");
    v
}

fn split_run_matches_whole(name: &str, n: u64) {
    let dir = tmpdir(name);
    let snap = dir.join("half.snap");
    let whole = summary(&run(bin()
        .args(["run", "--json", "--steps", &(2 * n).to_string()])
        .arg(scenario(name))));
    let first = summary(&run(bin()
        .args(["run", "--json", "--steps", &n.to_string(), "--snapshot-out"])
        .arg(&snap)
        .arg(scenario(name))));
    assert!(snap.is_file());
    let resumed = summary(&run(bin()
        .args(["run", "--json", "--steps", &n.to_string(), "--resume"])
        .arg(&snap)
        .arg(scenario(name))));
    assert_eq!(whole["steps"], 2 * n);
    assert_eq!(first["steps"], n);
    // The first half really differs from the end (the comparison below can fail).
    assert_ne!(first["bodies"], whole["bodies"], "{name}: nothing moved");
    assert_eq!(
        resumed, whole,
        "{name}: resumed run differs from the whole run"
    );
    // No temporary file left beside the snapshot.
    let names: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(names.len(), 1, "{names:?}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn vibrating_conveyor_resumes_bit_identically() {
    split_run_matches_whole("vibrating_conveyor", 300);
}

#[test]
fn belt_stick_slip_resumes_bit_identically() {
    split_run_matches_whole("belt_stick_slip", 600);
}

#[test]
fn a_resumed_run_completes_the_scenario_duration() {
    let dir = tmpdir("default");
    let snap = dir.join("part.snap");
    let name = "incline";
    let whole = summary(&run(bin().args(["run", "--json"]).arg(scenario(name))));
    summary(&run(bin()
        .args(["run", "--json", "--steps", "250", "--snapshot-out"])
        .arg(&snap)
        .arg(scenario(name))));
    let rest = summary(&run(bin()
        .args(["run", "--json", "--resume"])
        .arg(&snap)
        .arg(scenario(name))));
    assert_eq!(rest, whole);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn bad_snapshots_are_clean_errors() {
    let dir = tmpdir("bad");
    let snap = dir.join("incline.snap");
    summary(&run(bin()
        .args(["run", "--json", "--steps", "20", "--snapshot-out"])
        .arg(&snap)
        .arg(scenario("incline"))));
    let bytes = std::fs::read(&snap).unwrap();
    let garbage = dir.join("garbage.snap");
    std::fs::write(&garbage, b"not a snapshot at all").unwrap();
    let truncated = dir.join("truncated.snap");
    std::fs::write(&truncated, &bytes[..bytes.len() / 2]).unwrap();
    let cases = [
        (snap.clone(), "vibrating_conveyor", "scenario"),
        (garbage, "incline", "not a stickslip snapshot"),
        (truncated, "incline", "truncated"),
        (dir.join("missing.snap"), "incline", "missing.snap"),
    ];
    for (file, name, message) in cases {
        let out = run(bin()
            .args(["run", "--steps", "5", "--resume"])
            .arg(&file)
            .arg(scenario(name)));
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{}: {stderr}", file.display());
        assert!(stderr.contains(message), "{}: {stderr}", file.display());
        assert!(!stderr.contains("panicked"), "{stderr}");
    }
    // An unwritable snapshot path: an error, and nothing left behind.
    let target = dir.join("no-such-dir").join("x.snap");
    let out = run(bin()
        .args(["run", "--steps", "5", "--snapshot-out"])
        .arg(&target)
        .arg(scenario("incline")));
    assert_eq!(out.status.code(), Some(2));
    assert!(!target.exists());
    let _ = std::fs::remove_dir_all(&dir);
}
