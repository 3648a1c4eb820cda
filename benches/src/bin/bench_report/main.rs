//! Writes `BENCHMARKS.md` from a real run: what stickslip costs against plain rapier friction,
//! how accurate each law is against analytic/reference values, and the seed's comparison of
//! integration time and error of EP versus Regul (Fig. 1D and 2B).
//!
//! Sections:
//! - **Cost** (from `benches/step_cost.rs`): criterion's step times from `--criterion DIR` and
//!   the bench's extra pass (contacts, allocations per step, live heap, interleaved step times)
//!   from `--cost-json FILE`, as ratios against plain rapier with the targets beside them.
//! - **Accuracy** (measured here, in rapier worlds built like `tests/rapier_*.rs`): creep on an
//!   incline at 0.95 of break-away and the sliding acceleration above it, the stick-slip period on
//!   a belt, Popov's μ̄ across β, and the seed's Example 1, for plain rapier and every law.
//! - **Seed comparison** (measured here, with the core's adaptive integrators): the single block
//!   (`stickslip_theory::block`) and the 250-contact chain (`stickslip_theory::chain`).
//!
//! Run by `scripts/bench_report.sh`; by hand:
//! `cargo run --release -p stickslip-benches --bin bench_report -- --cost-json cost.json --criterion DIR`.
//! `--smoke` runs every measurement once on tiny sizes (a CI check, not a report).

mod accuracy;
mod cost;
mod seed;
mod table;

use std::fmt::Write as _;
use std::path::PathBuf;
use std::process::Command;
use std::time::Instant;

/// Command-line options.
#[derive(Debug, Default)]
struct Options {
    smoke: bool,
    out: Option<PathBuf>,
    cost_json: Option<PathBuf>,
    criterion: Option<PathBuf>,
    skip: Vec<String>,
    notes: Vec<String>,
    threads_json: Option<PathBuf>,
    profile: Option<PathBuf>,
}

fn parse() -> Result<Options, String> {
    let mut o = Options::default();
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        let mut value = |name: &str| args.next().ok_or(format!("{name} needs a value"));
        match a.as_str() {
            "--smoke" => o.smoke = true,
            "--out" => o.out = Some(value("--out")?.into()),
            "--cost-json" => o.cost_json = Some(value("--cost-json")?.into()),
            "--criterion" => o.criterion = Some(value("--criterion")?.into()),
            "--skip" => o
                .skip
                .extend(value("--skip")?.split(',').map(|s| s.trim().to_string())),
            "--note" => o.notes.push(value("--note")?),
            "--threads-json" => o.threads_json = Some(value("--threads-json")?.into()),
            "--profile" => o.profile = Some(value("--profile")?.into()),
            "--help" | "-h" => {
                return Err(
                    "usage: bench_report [--smoke] [--out FILE] [--cost-json FILE] \
                     [--criterion DIR] [--threads-json FILE] [--profile FILE] \
                     [--skip cost,accuracy,seed] [--note TEXT]..."
                        .into(),
                );
            }
            other => return Err(format!("unknown argument `{other}` (see --help)")),
        }
    }
    Ok(o)
}

fn command_output(cmd: &str, args: &[&str]) -> Option<String> {
    let out = Command::new(cmd).args(args).output().ok()?;
    out.status
        .success()
        .then(|| String::from_utf8_lossy(&out.stdout).trim().to_string())
}

/// Version of a package in the workspace's Cargo.lock.
fn locked_version(package: &str) -> String {
    let lock = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../Cargo.lock"))
        .unwrap_or_default();
    // With several versions locked (rapier3d 0.36 and bevy_rapier's 0.35), the one this
    // package depends on is named with its version in its own dependency list.
    let own = lock
        .split("[[package]]")
        .find(|block| block.contains("name = \"stickslip-benches\""))
        .and_then(|block| {
            block.lines().find_map(|l| {
                l.trim()
                    .trim_matches(|c| c == '"' || c == ',')
                    .strip_prefix(&format!("{package} "))
                    .map(str::to_string)
            })
        });
    if let Some(v) = own {
        return v;
    }
    let mut lines = lock.lines();
    while let Some(l) = lines.next() {
        if l == format!("name = \"{package}\"")
            && let Some(v) = lines.next()
        {
            return v
                .trim_start_matches("version = ")
                .trim_matches('"')
                .to_string();
        }
    }
    "?".into()
}

fn machine(md: &mut String, opts: &Options) {
    let cpuinfo = std::fs::read_to_string("/proc/cpuinfo").unwrap_or_default();
    let model = cpuinfo
        .lines()
        .find(|l| l.starts_with("model name"))
        .and_then(|l| l.split(':').nth(1))
        .map(|s| s.trim().to_string())
        .unwrap_or_else(|| "?".into());
    let logical = cpuinfo
        .lines()
        .filter(|l| l.starts_with("processor"))
        .count();
    let available = std::thread::available_parallelism().map_or(0, |n| n.get());
    let mhz = cpuinfo
        .lines()
        .find(|l| l.starts_with("cpu MHz"))
        .and_then(|l| l.split(':').nth(1))
        .map(|s| s.trim().to_string())
        .unwrap_or_else(|| "?".into());
    let load = std::fs::read_to_string("/proc/loadavg").unwrap_or_default();
    let mem = std::fs::read_to_string("/proc/meminfo")
        .unwrap_or_default()
        .lines()
        .find(|l| l.starts_with("MemTotal"))
        .map(|l| l.trim_start_matches("MemTotal:").trim().to_string())
        .unwrap_or_default();
    let rustc = command_output("rustc", &["--version"]).unwrap_or_else(|| "?".into());
    let head = command_output("git", &["rev-parse", "--short=12", "HEAD"]).unwrap_or_default();
    let dirty = command_output("git", &["status", "--porcelain", "--untracked-files=no"])
        .is_some_and(|s| !s.is_empty());
    let _ = writeln!(md, "## Machine and versions\n");
    let rows = vec![
        vec!["CPU".into(), format!("{model} ({mhz} MHz)")],
        vec![
            "cores".into(),
            format!("{logical} logical in /proc/cpuinfo, {available} available to the process"),
        ],
        vec!["memory".into(), mem],
        vec![
            "load average at report start (1, 5, 15 min)".into(),
            load.split_whitespace()
                .take(3)
                .collect::<Vec<_>>()
                .join(", "),
        ],
        vec!["rustc".into(), rustc],
        vec![
            "rapier3d".into(),
            format!(
                "{} (features: default{}; single-threaded steps)",
                locked_version("rapier3d"),
                if cfg!(feature = "parallel") {
                    ", parallel"
                } else {
                    ""
                }
            ),
        ],
        vec!["criterion".into(), locked_version("criterion").to_string()],
        vec![
            "differential-equations".into(),
            locked_version("differential-equations"),
        ],
        vec![
            "stickslip".into(),
            format!(
                "git {head}{}",
                if dirty {
                    " with uncommitted changes to tracked files"
                } else {
                    ""
                }
            ),
        ],
        vec![
            "profile".into(),
            if cfg!(debug_assertions) {
                "debug (numbers are not representative)".into()
            } else {
                "release".into()
            },
        ],
    ];
    md.push_str(&table::render(&["", ""], &rows));
    for n in &opts.notes {
        let _ = writeln!(md, "- {n}");
    }
    md.push('\n');
}

/// Runs the selected sections and returns the markdown.
fn run(opts: &Options) -> String {
    let started = Instant::now();
    let mut md = String::new();
    let _ = writeln!(
        md,
        "# stickslip benchmarks\n\n\
         Generated by `scripts/bench_report.sh` (criterion benches in `benches/benches/step_cost.rs`, \
         measurements in `benches/src/bin/bench_report/`) from one run on the machine below. Targets \
         are reported, never asserted; every missed target is named with its measured figure \
         in the summary.{}\n",
        if opts.smoke {
            "\n\n**Smoke run: tiny sizes, one repetition: these numbers mean nothing.**"
        } else {
            ""
        }
    );
    machine(&mut md, opts);
    let mut summary = table::Summary::default();
    let mut body = String::new();
    let skip = |s: &str| opts.skip.iter().any(|k| k == s);
    if !skip("cost") {
        let t = Instant::now();
        match cost::section(&mut body, &mut summary, opts) {
            Ok(()) => eprintln!("cost section: {:.1} s", t.elapsed().as_secs_f64()),
            Err(e) => {
                eprintln!("cost section failed: {e}");
                let _ = writeln!(body, "## Cost\n\nNot available: {e}\n");
            }
        }
    }
    if !skip("cost") {
        cost::threads_section(&mut body, &mut summary, opts);
        if let Some(path) = &opts.profile {
            match std::fs::read_to_string(path) {
                Ok(text) => {
                    body.push_str(&text);
                    body.push('\n');
                }
                Err(e) => eprintln!("profile notes {}: {e}", path.display()),
            }
        }
    }
    if !skip("accuracy") {
        let t = Instant::now();
        accuracy::section(&mut body, &mut summary, opts.smoke);
        let _ = writeln!(
            body,
            "_Accuracy section measured in {:.0} s._\n",
            t.elapsed().as_secs_f64()
        );
        eprintln!("accuracy section: {:.1} s", t.elapsed().as_secs_f64());
    }
    if !skip("seed") {
        let t = Instant::now();
        seed::section(&mut body, &mut summary, opts.smoke);
        let _ = writeln!(
            body,
            "_Seed comparison measured in {:.0} s._\n",
            t.elapsed().as_secs_f64()
        );
        eprintln!("seed section: {:.1} s", t.elapsed().as_secs_f64());
    }
    md.push_str(&summary.render());
    md.push_str(&body);
    let _ = writeln!(
        md,
        "_Report binary ran {:.0} s._",
        started.elapsed().as_secs_f64()
    );
    md
}

fn main() {
    let opts = match parse() {
        Ok(o) => o,
        Err(e) => {
            eprintln!("{e}");
            std::process::exit(2);
        }
    };
    let md = run(&opts);
    match &opts.out {
        Some(path) => {
            if let Err(e) = std::fs::write(path, &md) {
                eprintln!("cannot write {}: {e}", path.display());
                std::process::exit(1);
            }
            eprintln!("wrote {}", path.display());
        }
        None => print!("{md}"),
    }
}

#[cfg(test)]
mod tests {
    /// The CI smoke check (`cargo test -p stickslip-benches --bin bench_report`): every accuracy and seed
    /// measurement runs once on tiny sizes, and the cost section reads the smoke bench's JSON
    /// when `STICKSLIP_BENCH_OUT` names one that exists.
    #[test]
    fn smoke_report_runs() {
        let cost_json = std::env::var_os("STICKSLIP_BENCH_OUT")
            .map(std::path::PathBuf::from)
            .filter(|p| p.exists());
        let opts = super::Options {
            smoke: true,
            skip: if cost_json.is_none() {
                vec!["cost".into()]
            } else {
                vec![]
            },
            cost_json,
            ..super::Options::default()
        };
        let md = super::run(&opts);
        for heading in [
            "## Targets at a glance",
            "## Accuracy in rapier worlds",
            "### Single block",
            "### Chain of 250 frictional contacts",
        ] {
            assert!(md.contains(heading), "missing {heading}");
        }
    }
}
