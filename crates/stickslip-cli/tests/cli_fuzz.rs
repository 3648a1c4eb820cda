//! No argument vector crashes, hangs or lies: random command lines for every subcommand
//! (`theory psi|mu-eff|static`, `block` with any subset of its options, `run` with shipped,
//! missing or no scenarios, garbage), their numbers drawn from plausible values mixed with
//! hostile ones (NaN, ±∞, 1e±300, subnormals, negative and huge integers, words), end within
//! the time limit with exit code 0 (and output free of NaN and infinities, valid JSON with
//! `--json`) or 2 with a message on stderr — never a panic (101) or a signal. Deterministic
//! (fixed seed; `PROPTEST_CASES` / `PROPTEST_RNG_SEED` override).

#[path = "../../../tests/support/deterministic.rs"]
mod support;

use proptest::prelude::*;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};
use support::deterministic;

const NUMBERS: &[&str] = &[
    "nan",
    "inf",
    "-inf",
    "1e300",
    "-1e300",
    "1e39",
    "0",
    "-0",
    "5e-324",
    "-1",
    "1e7",
    "18446744073709551616",
    "abc",
    "",
    "0.3",
    "0.32",
    "1",
    "2",
    "9.81",
    "1e4",
    "0.01",
    "0.5",
    "1e-8",
    "100",
];
const WAVEFORMS: &[&str] = &[
    "sine",
    "square",
    "sawtooth-right",
    "sawtooth-left",
    "tri",
    "x",
];
const DIRECTIONS: &[&str] = &["normal", "tangential", "transverse", "up"];
const LAWS: &[&str] = &["ep", "phys", "regul", "coulomb", "magic"];
const INTEGRATORS: &[&str] = &["explicit", "dormand-prince", "implicit", "euler"];
const SCENARIOS: &[&str] = &[
    "../../scenarios/belt_stick_slip.toml",
    "../../scenarios/incline.toml",
    "/nonexistent.toml",
    "Cargo.toml",
];
const BLOCK_OPTIONS: &[&str] = &[
    "--mass",
    "--gravity",
    "--mu-ba",
    "--mu-max",
    "--c",
    "--viscous",
    "--v-reg",
    "--hold",
    "--push",
    "--rtol",
    "--atol",
];

fn pick(list: &'static [&'static str]) -> impl Strategy<Value = String> {
    prop::sample::select(list).prop_map(str::to_string)
}

fn number() -> impl Strategy<Value = String> {
    pick(NUMBERS)
}

/// One command line (without the program name).
fn command_line() -> impl Strategy<Value = Vec<String>> {
    let psi = (pick(WAVEFORMS), number()).prop_map(|(w, b)| {
        vec![
            "theory".into(),
            "psi".into(),
            "--waveform".into(),
            w,
            "--beta".into(),
            b,
        ]
    });
    let mu_eff = (pick(WAVEFORMS), number(), number(), number()).prop_map(|(w, a, b, m)| {
        [
            "theory",
            "mu-eff",
            "--waveform",
            &w,
            "--alpha",
            &a,
            "--beta",
            &b,
            "--mu0",
            &m,
        ]
        .map(String::from)
        .to_vec()
    });
    let stat = (pick(DIRECTIONS), number(), number()).prop_map(|(d, a, m)| {
        [
            "theory",
            "static",
            "--direction",
            &d,
            "--amplitude-ratio",
            &a,
            "--mu0",
            &m,
        ]
        .map(String::from)
        .to_vec()
    });
    let block = (
        pick(LAWS),
        pick(INTEGRATORS),
        prop::collection::vec((pick(BLOCK_OPTIONS), number()), 0..4),
        prop::option::of((number(), number())),
        prop::option::of((number(), number())),
    )
        .prop_map(|(law, integrator, options, stribeck, profile)| {
            let mut v: Vec<String> = ["block", "--law", &law, "--integrator", &integrator]
                .map(String::from)
                .to_vec();
            for (o, n) in options {
                v.push(o);
                v.push(n);
            }
            if let Some((k, s)) = stribeck {
                v.push("--stribeck".into());
                v.push(format!("{k},{s}"));
            }
            if let Some((t, f)) = profile {
                v.push("--force-profile".into());
                v.push(format!("0:0,{t}:{f}"));
            }
            v
        });
    let run = (
        prop::option::of(pick(SCENARIOS)),
        prop::option::of(pick(&["0", "1", "5", "-3", "1e3", "1000000000", "x"])),
        prop::option::of(pick(&["0", "1", "7", "-1"])),
        any::<bool>(),
    )
        .prop_map(|(scenario, steps, every, check)| {
            let mut v = vec!["run".to_string()];
            v.extend(scenario);
            // Short runs only: a long one is a legitimate request, not a hang.
            v.push("--steps".into());
            v.push(steps.unwrap_or_else(|| "20".into()));
            if let Some(k) = every {
                v.push("--every".into());
                v.push(k);
            }
            if check {
                v.push("--check".into());
            }
            v
        });
    let garbage = prop::collection::vec(
        pick(&[
            "theory", "block", "run", "--json", "--", "-x", "psi", "--steps", "nan",
        ]),
        0..5,
    );
    (
        any::<bool>(),
        prop_oneof![psi, mu_eff, stat, block, run, garbage],
    )
        .prop_map(|(json, mut args)| {
            if json {
                args.insert(0, "--json".into());
            }
            args
        })
}

struct Outcome {
    code: Option<i32>,
    stdout: String,
    stderr: String,
    seconds: f64,
}

/// Runs the CLI; a run beyond `limit` is killed and reported without a code.
fn run(args: &[String], limit: Duration) -> Outcome {
    let started = Instant::now();
    let mut child = Command::new(env!("CARGO_BIN_EXE_stickslip"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary starts");
    let (out, err) = (child.stdout.take().unwrap(), child.stderr.take().unwrap());
    let read = |mut r: Box<dyn std::io::Read + Send>| {
        std::thread::spawn(move || {
            let mut s = String::new();
            let _ = r.read_to_string(&mut s);
            s
        })
    };
    let (out, err) = (read(Box::new(out)), read(Box::new(err)));
    let code = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status.code();
        }
        if started.elapsed() > limit {
            let _ = child.kill();
            let _ = child.wait();
            break None;
        }
        std::thread::sleep(Duration::from_millis(5));
    };
    Outcome {
        code,
        stdout: out.join().unwrap(),
        stderr: err.join().unwrap(),
        seconds: started.elapsed().as_secs_f64(),
    }
}

proptest! {
    #![proptest_config(deterministic(48))]

    #[test]
    fn any_command_line_ends_cleanly(args in command_line()) {
        let o = run(&args, Duration::from_secs(120));
        prop_assert!(
            o.code.is_some(),
            "{args:?}: killed after {:.0} s (hang or signal)\n{}",
            o.seconds,
            o.stderr
        );
        let code = o.code.unwrap();
        prop_assert!(code == 0 || code == 2, "{args:?}: exit {code}\n{}", o.stderr);
        if code == 2 {
            prop_assert!(!o.stderr.trim().is_empty(), "{args:?}: exit 2 without a message");
        } else {
            let lower = o.stdout.to_lowercase();
            prop_assert!(
                !lower.contains("nan") && !lower.split(|c: char| !c.is_alphabetic()).any(|w| w == "inf"),
                "{args:?}: non-finite output\n{}",
                o.stdout
            );
            if args.iter().any(|a| a == "--json") && args.first().is_some_and(|a| a == "--json") {
                prop_assert!(
                    serde_json::from_str::<serde_json::Value>(&o.stdout).is_ok(),
                    "{args:?}: invalid JSON\n{}",
                    o.stdout
                );
            }
        }
    }
}
