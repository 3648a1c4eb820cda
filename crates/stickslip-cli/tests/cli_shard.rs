//! Sharded sweeps end to end. Invariant: for any shard count N (1, 2, 7 here, and more shards
//! than points), running `stickslip sweep … --shard K/N` for K = 1..=N and then
//! `stickslip sweep merge` on the shards gives every file of the unsharded run (CSV, JSON and
//! heat-map PNGs) byte for byte, for theory-only Popov maps and for feeder maps measured in
//! rapier worlds; the shards' slices are disjoint and cover the grid. A bad `--shard K/N`, and
//! a merge of missing, duplicated, mixed-grid, mixed-count or mixed-version shards, exit with
//! code 2 and a message naming the problem and the shard file, never a panic, and write no
//! merged output.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("stickslip-shard-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

fn stickslip(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_stickslip"))
        .args(args)
        .output()
        .expect("the binary runs")
}

fn ok(args: &[&str]) -> String {
    let o = stickslip(args);
    assert!(
        o.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&o.stderr)
    );
    String::from_utf8(o.stdout).unwrap()
}

/// Exit code 2, a message containing every needle, no panic.
fn refused(args: &[&str], needles: &[&str]) -> String {
    let o = stickslip(args);
    let err = String::from_utf8_lossy(&o.stderr).to_string();
    assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
    assert!(!err.contains("panicked"), "{args:?}: {err}");
    for n in needles {
        assert!(err.contains(n), "{args:?}: `{n}` not in {err}");
    }
    err
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// The file names in `dir`, sorted.
fn names(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    v.sort();
    v
}

/// Every file of `expected` exists in `got` with the same bytes, and nothing else.
fn assert_same_files(expected: &Path, got: &Path, what: &str) {
    assert_eq!(names(expected), names(got), "{what}: file names");
    for name in names(expected) {
        let (a, b) = (
            std::fs::read(expected.join(&name)).unwrap(),
            std::fs::read(got.join(&name)).unwrap(),
        );
        assert!(a == b, "{what}: {name} differs from the unsharded run");
    }
}

/// Runs `args` whole into `base/whole`, then as `count` shards into `base/shards-N` and merges
/// them into `base/merged-N`; checks the merge against the whole run and the shards' slices.
fn shard_and_merge(args: &[&str], base: &Path, counts: &[usize], name: &str) {
    let whole = base.join("whole");
    ok(&[args, &["--out", s(&whole)]].concat());
    let rows = std::fs::read_to_string(whole.join(format!("{name}.csv")))
        .unwrap()
        .lines()
        .count()
        - 1;
    for &count in counts {
        let shards = base.join(format!("shards-{count}"));
        let mut seen = BTreeSet::new();
        let mut total_points = 0;
        for k in 1..=count {
            let spec = format!("{k}/{count}");
            let threads = if k % 2 == 0 { "2" } else { "1" };
            let out = ok(&[
                &["--json"],
                args,
                &["--out", s(&shards), "--shard", &spec, "--threads", threads],
            ]
            .concat());
            let report: serde_json::Value = serde_json::from_str(&out).unwrap();
            assert_eq!(report["shard"], spec.as_str());
            let stem = format!("{name}.shard-{k}-of-{count}");
            let manifest: serde_json::Value = serde_json::from_str(
                &std::fs::read_to_string(shards.join(format!("{stem}.json"))).unwrap(),
            )
            .unwrap();
            assert_eq!(manifest["shard"]["index"], k);
            assert_eq!(manifest["shard"]["count"], count);
            assert_eq!(manifest["total"], rows);
            let indices = manifest["indices"].as_array().unwrap();
            assert_eq!(report["points"], indices.len());
            for i in indices {
                assert!(seen.insert(i.as_u64().unwrap()), "{stem}: point {i} twice");
            }
            let csv = std::fs::read_to_string(shards.join(format!("{stem}.csv"))).unwrap();
            assert_eq!(csv.lines().count() - 1, indices.len(), "{stem}.csv rows");
            total_points += indices.len();
        }
        assert_eq!(total_points, rows, "N = {count}: the shards cover the grid");
        assert_eq!(seen.len(), rows);
        let merged = base.join(format!("merged-{count}"));
        let out = ok(&["--json", "sweep", "merge", s(&shards), "--out", s(&merged)]);
        let report: serde_json::Value = serde_json::from_str(&out).unwrap();
        assert_eq!(report["points"], rows);
        assert_eq!(report["shards"].as_array().unwrap().len(), count);
        assert_same_files(&whole, &merged, &format!("{name}, N = {count}"));
    }
}

#[test]
fn popov_shards_merge_to_the_unsharded_files() {
    // 2 waveforms × 5 β × 3 α = 30 points of theory (17-digit values, all kept exactly).
    let args = [
        "sweep",
        "popov",
        "--theory-only",
        "--waveforms",
        "sine,sawtooth-right",
        "--beta",
        "0.5:12:5",
        "--alpha",
        "0.2:0.8:3",
    ];
    let base = tmp("popov");
    shard_and_merge(&args, &base, &[1, 2, 7, 31], "popov");
    // Merging named files (in any order) works like merging their directory.
    let shards = base.join("shards-2");
    let merged = base.join("merged-files");
    ok(&[
        "sweep",
        "merge",
        s(&shards.join("popov.shard-2-of-2.json")),
        s(&shards.join("popov.shard-1-of-2.json")),
        "--out",
        s(&merged),
    ]);
    assert_same_files(&base.join("whole"), &merged, "popov, named files");
    let _ = std::fs::remove_dir_all(&base);
}

#[test]
fn feeder_shards_measured_in_rapier_merge_to_the_unsharded_files() {
    // 2 amplitudes × 2 angles = 4 rapier worlds (plain friction, 1/3000 s, 2 + 2 periods).
    let args = [
        "sweep",
        "feeder",
        "--amplitude",
        "1:1.5:2",
        "--frequency",
        "25",
        "--angle",
        "20:30:2",
        "--law",
        "plain",
        "--periods",
        "2:2",
    ];
    let base = tmp("feeder");
    shard_and_merge(&args, &base, &[1, 2, 7], "feeder");
    let _ = std::fs::remove_dir_all(&base);
}

#[test]
fn bad_shard_specs_are_clear_errors() {
    let out = tmp("bad-spec");
    for (spec, needle) in [
        ("0/3", "1-based"),
        ("4/3", "1..=3"),
        ("3", "K/N"),
        ("a/3", "K/N"),
        ("1/0", "N = 0"),
        ("1/2/3", "K/N"),
        ("1/99999999999999999999999", "K/N"),
        ("1/20001", "N = 20001"),
    ] {
        refused(
            &[
                "sweep",
                "popov",
                "--theory-only",
                "--shard",
                spec,
                "--out",
                s(&out),
            ],
            &["--shard", needle],
        );
    }
    assert!(!out.exists(), "a refused shard wrote nothing");
}

#[test]
fn bad_merges_are_clear_errors_naming_the_shard() {
    let base = tmp("bad-merge");
    let grid = [
        "sweep",
        "popov",
        "--theory-only",
        "--waveforms",
        "sine",
        "--beta",
        "1:4:4",
    ];
    let shards = base.join("shards");
    for k in 1..=3 {
        ok(&[
            &grid[..],
            &["--shard", &format!("{k}/3"), "--out", s(&shards)],
        ]
        .concat());
    }
    let file = |k: usize| shards.join(format!("popov.shard-{k}-of-3.json"));
    let merged = base.join("merged");
    let merge = |inputs: &[&Path], needles: &[&str]| {
        let mut args = vec!["sweep", "merge", "--out", s(&merged)];
        args.extend(inputs.iter().map(|p| s(p)));
        refused(&args, needles)
    };

    // Missing: the message lists the tasks to rerun and a file that is absent.
    merge(
        &[&file(1), &file(3)],
        &["missing 1 of 3", "--array=2", "popov.shard-2-of-3.json"],
    );
    // Duplicated: the same shard twice, named.
    merge(
        &[&file(1), &file(2), &file(3), &file(2)],
        &["duplicated", s(&file(2))],
    );
    // Mixed grids: a shard of another β grid.
    let other = base.join("other");
    ok(&[
        "sweep",
        "popov",
        "--theory-only",
        "--waveforms",
        "sine",
        "--beta",
        "1:4:5",
        "--shard",
        "3/3",
        "--out",
        s(&other),
    ]);
    let foreign = other.join("popov.shard-3-of-3.json");
    merge(&[&file(1), &file(2), &foreign], &["grid", s(&foreign)]);
    // Mixed kinds: a feeder shard among Popov shards.
    ok(&[
        "sweep",
        "feeder",
        "--amplitude",
        "1",
        "--frequency",
        "25",
        "--angle",
        "25",
        "--law",
        "plain",
        "--periods",
        "1:1",
        "--shard",
        "1/1",
        "--out",
        s(&other),
    ]);
    let feeder = other.join("feeder.shard-1-of-1.json");
    merge(&[&file(1), &feeder], &["kind feeder", s(&feeder)]);
    // Mixed shard counts.
    ok(&[&grid[..], &["--shard", "2/4", "--out", s(&other)]].concat());
    let four = other.join("popov.shard-2-of-4.json");
    merge(&[&file(1), &four], &["shard count 4", s(&four)]);
    // Mixed versions: a shard written by another stickslip.
    let old = base.join("old");
    std::fs::create_dir_all(&old).unwrap();
    let text = std::fs::read_to_string(file(3)).unwrap();
    let version = format!("\"tool_version\": \"{}\"", env!("CARGO_PKG_VERSION"));
    assert!(text.contains(&version));
    let old3 = old.join("popov.shard-3-of-3.json");
    std::fs::write(&old3, text.replace(&version, "\"tool_version\": \"0.0.1\"")).unwrap();
    merge(
        &[&file(1), &file(2), &old3],
        &["stickslip 0.0.1", "mixed versions", s(&old3)],
    );
    // Not shard files at all; a directory without shards.
    let junk = old.join("junk.shard-1-of-1.json");
    std::fs::write(&junk, "{\"format\": \"something else\"}").unwrap();
    merge(&[&junk], &["not a stickslip shard file", s(&junk)]);
    std::fs::write(&junk, "[1, 2").unwrap();
    merge(&[&junk], &["not a stickslip shard file", s(&junk)]);
    let empty = base.join("empty");
    std::fs::create_dir_all(&empty).unwrap();
    merge(&[&empty], &["no shard files", s(&empty)]);
    merge(
        &[&base.join("absent.json")],
        &["cannot read", "absent.json"],
    );
    // No inputs at all: clap's usage error.
    refused(&["sweep", "merge"], &["FILES|DIR"]);

    assert!(!merged.exists(), "a refused merge wrote nothing");
    // The three good shards still merge.
    ok(&["sweep", "merge", s(&shards), "--out", s(&merged)]);
    let _ = std::fs::remove_dir_all(&base);
}
