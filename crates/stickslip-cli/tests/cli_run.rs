//! `stickslip run` end to end: the JSON summary reports the steps and contacts simulated, the
//! `.rrd` it writes decodes (with rerun's reader) to one pose row per logged step and a
//! dissipated-energy series ending at the summary's value, no temporary file is left behind,
//! a failing run (malformed scenario, unwritable path) exits with code 2, names the field and
//! line, and leaves no `.rrd`. With the PyPI `rerun` CLI (path in `STICKSLIP_RERUN_CLI`, set by
//! `.ci/run`), rerun's own `rrd verify`/`rrd print` accept the file and a live stream reaches a
//! receiving `rerun --test-receive`; without it those two tests print that they skipped. A live
//! stream to an address where no viewer listens exits 2 within seconds, before simulating.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::time::{Duration, Instant};
use stickslip_rerun::{inspect, paths};

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_stickslip"))
}

fn scenario(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../scenarios")
        .join(format!("{name}.toml"))
}

fn tmpdir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("stickslip-cli-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn run(cmd: &mut Command) -> Output {
    let out = cmd.output().expect("runs");
    println!("stdout:\n{}", String::from_utf8_lossy(&out.stdout));
    println!("stderr:\n{}", String::from_utf8_lossy(&out.stderr));
    out
}

fn files(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

fn write_belt_rrd(dir: &Path) -> (PathBuf, serde_json::Value) {
    let rrd = dir.join("belt.rrd");
    let out = run(bin()
        .arg("run")
        .arg(scenario("belt_stick_slip"))
        .args(["--steps", "200", "--every", "10", "--json", "--rrd"])
        .arg(&rrd));
    assert!(out.status.success());
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    (rrd, json)
}

#[test]
fn run_writes_an_rrd_that_matches_the_summary() {
    let dir = tmpdir("rrd");
    let (rrd, json) = write_belt_rrd(&dir);
    assert_eq!(json["scenario"], "belt-stick-slip");
    assert_eq!(json["steps"], 200);
    assert_eq!(json["logged_steps"], 21);
    assert_eq!(json["max_contacts"], 1);
    assert_eq!(json["finite"], true);
    assert_eq!(files(&dir), vec!["belt.rrd"], "no temporary file left");

    let contents = inspect::read_rrd(&rrd).unwrap();
    let block = contents.entity(&paths::body("block")).unwrap();
    assert_eq!(block.steps, (0..=200).step_by(10).collect::<Vec<i64>>());
    let energy = &contents
        .entity(&paths::world_series("dissipated_energy"))
        .unwrap()
        .scalars;
    let e = json["dissipated_energy"].as_f64().unwrap();
    assert!((energy.last().unwrap() - e).abs() <= 1e-9 * e.max(1.0));
    let sim_time = json["sim_time"].as_f64().unwrap();
    assert!((block.sim_times.last().unwrap() - sim_time).abs() < 1e-6);
    // Contact-steps in the JSON add up to one contact per step.
    let rs = &json["regime_steps"];
    let total = rs["sticking"].as_u64().unwrap()
        + rs["stick_slip"].as_u64().unwrap()
        + rs["sliding"].as_u64().unwrap();
    assert!((199..=200).contains(&total), "{total}");
    std::fs::remove_dir_all(&dir).ok();
}

/// The main job: a bare `stickslip run` runs the built-in showcase and compares its three
/// troughs — EP holds (no creep), EP under ultrasonic normal vibration conveys at Popov's
/// speed (Eq. 33 solved for μ̄ = tan θ, within 5 % as the bevy conveyor test), plain rapier
/// friction holds — and names the comparison and how to open a recording.
#[test]
fn bare_run_is_the_showcase_and_compares_it_with_the_theory() {
    let out = run(bin().args(["run", "--json"]));
    assert!(out.status.success());
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(json["scenario"], "showcase");
    assert_eq!(json["logged_steps"], 0);
    assert!(
        json["rrd"].is_null(),
        "nothing recorded unless run from a terminal"
    );
    let rows = json["showcase"].as_array().unwrap();
    let row = |t: &str| rows.iter().find(|r| r["trough"] == t).unwrap().clone();
    let speed = |t: &str| row(t)["speed"].as_f64().unwrap();
    // Holding: g_ba = μ_ba / c = 5 µm is all a box may move; at rest its speed is ~0.
    assert!(speed("ep_still").abs() < 1e-4, "{}", speed("ep_still"));
    assert!(speed("plain").abs() < 1e-3, "{}", speed("plain"));
    let theory = row("ep_vibrated")["theory"].as_f64().unwrap();
    assert!(theory > 0.01, "{theory}");
    let v = speed("ep_vibrated");
    assert!((v - theory).abs() < 0.05 * theory, "{v} vs {theory}");
    // The table names the comparison and the way to record and open the run.
    let out = run(bin().args(["run", "--steps", "50"]));
    assert!(out.status.success());
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("showcase"));
    assert!(text.contains("what the three troughs did"), "{text}");
    assert!(text.contains("Popov Eq. 33"), "{text}");
    assert!(text.contains("rerun showcase.rrd"), "{text}");
}

#[test]
fn check_validates_without_running() {
    let out = run(bin()
        .args(["run", "--check", "--json"])
        .arg(scenario("row_250")));
    assert!(out.status.success());
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(json["bodies"], 251);
    assert_eq!(json["drivers"], 251);
}

#[test]
fn malformed_scenario_fails_with_field_and_line_and_writes_nothing() {
    let dir = tmpdir("bad");
    let bad = dir.join("bad.toml");
    std::fs::write(
        &bad,
        "name = \"bad\"\n[world]\ndt = 0.01\n[[body]]\nname = \"b\"\nmass = 3.0\n",
    )
    .unwrap();
    let rrd = dir.join("out.rrd");
    let out = run(bin().arg("run").arg(&bad).arg("--rrd").arg(&rrd));
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("bad.toml:6"), "{err}");
    assert!(err.contains("mass"), "{err}");
    assert_eq!(files(&dir), vec!["bad.toml"], "no .rrd, no temporary file");

    // A validation error (NaN) names the field.
    std::fs::write(&bad, "name = \"bad\"\n[world]\ndt = nan\n").unwrap();
    let out = run(bin().arg("run").arg(&bad).arg("--rrd").arg(&rrd));
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("world.dt"));
    assert_eq!(files(&dir), vec!["bad.toml"]);
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn unwritable_rrd_path_fails_cleanly() {
    let out = run(bin().args([
        "run",
        "--steps",
        "10",
        "--rrd",
        "/nonexistent-dir/stickslip/out.rrd",
    ]));
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("rerun"));
    assert!(!Path::new("/nonexistent-dir").exists());
}

/// The PyPI `rerun` binary, or `None` after printing that the test skips.
fn rerun_cli(test: &str) -> Option<PathBuf> {
    match std::env::var_os("STICKSLIP_RERUN_CLI") {
        Some(p) => Some(PathBuf::from(p)),
        None => {
            println!(
                "SKIPPED {test}: STICKSLIP_RERUN_CLI is not set (`.ci/run` installs PyPI \
                 rerun-sdk==0.36.3 and sets it)"
            );
            eprintln!("SKIPPED {test}: STICKSLIP_RERUN_CLI not set");
            None
        }
    }
}

#[test]
fn rerun_cli_accepts_the_rrd() {
    let Some(rerun) = rerun_cli("rerun_cli_accepts_the_rrd") else {
        return;
    };
    let dir = tmpdir("verify");
    let (rrd, _) = write_belt_rrd(&dir);
    let out = run(Command::new(&rerun).args(["rrd", "verify"]).arg(&rrd));
    assert!(out.status.success(), "rerun rrd verify failed");
    // `-vv`: chunk headers, including the index (timeline) columns.
    let out = run(Command::new(&rerun).args(["rrd", "print", "-vv"]).arg(&rrd));
    assert!(out.status.success(), "rerun rrd print failed");
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    for needle in [
        "world/bodies/block",
        "series/world/dissipated_energy",
        "index_name: sim_time",
        "index_name: step",
        "Points3D:class_ids",
    ] {
        assert!(text.contains(needle), "`rerun rrd print` lacks {needle}");
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn live_stream_reaches_a_receiving_viewer() {
    let Some(rerun) = rerun_cli("live_stream_reaches_a_receiving_viewer") else {
        return;
    };
    let port = {
        let l = std::net::TcpListener::bind("127.0.0.1:0").unwrap();
        l.local_addr().unwrap().port()
    };
    let mut receiver = Command::new(&rerun)
        .args(["--test-receive", "--bind", "127.0.0.1", "--port"])
        .arg(port.to_string())
        .spawn()
        .expect("starts rerun --test-receive");
    // Wait until it listens.
    let deadline = Instant::now() + Duration::from_secs(30);
    while std::net::TcpStream::connect(("127.0.0.1", port)).is_err() {
        assert!(
            Instant::now() < deadline,
            "receiver did not start listening"
        );
        std::thread::sleep(Duration::from_millis(100));
    }
    let out = run(bin()
        .arg("run")
        .arg(scenario("belt_stick_slip"))
        .args(["--steps", "100", "--every", "10", "--json", "--connect"])
        .arg(format!("127.0.0.1:{port}")));
    assert!(out.status.success(), "stickslip run --connect failed");
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(json["logged_steps"], 11);
    // The receiver exits 0 once it got a complete recording; bound it in time.
    let deadline = Instant::now() + Duration::from_secs(60);
    let status = loop {
        if let Some(s) = receiver.try_wait().unwrap() {
            break s;
        }
        if Instant::now() > deadline {
            receiver.kill().ok();
            panic!("rerun --test-receive did not finish within 60 s");
        }
        std::thread::sleep(Duration::from_millis(100));
    };
    assert!(status.success(), "receiver: {status}");
}

#[test]
fn live_stream_to_an_unreachable_viewer_fails_fast() {
    // A port nobody listens on: bind one, then free it.
    let port = {
        let l = std::net::TcpListener::bind("127.0.0.1:0").unwrap();
        l.local_addr().unwrap().port()
    };
    let start = Instant::now();
    let out = run(bin()
        .arg("run")
        .arg(scenario("belt_stick_slip"))
        .args(["--steps", "100", "--json", "--connect"])
        .arg(format!("127.0.0.1:{port}")));
    let took = start.elapsed();
    assert_eq!(out.status.code(), Some(2), "exit code");
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("no rerun viewer is listening") && err.contains(&port.to_string()),
        "{err}"
    );
    assert!(out.stdout.is_empty(), "nothing simulated: {:?}", out.stdout);
    assert!(took < Duration::from_secs(20), "took {took:?}");
}
