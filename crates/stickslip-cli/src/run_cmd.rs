//! `stickslip run`: runs a scenario file headless, optionally streaming to rerun (a live viewer
//! and/or an `.rrd` file), and prints a summary.
//!
//! An `.rrd` is written to a temporary file beside the target and renamed only after the run
//! and the final flush succeeded, so a failed run never leaves a partial file under the name
//! asked for.

use crate::{CliError, output};
use clap::Args;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use serde::Serialize;
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::time::Instant;
use stickslip_rerun::{LogOptions, RerunLogger, Sink};
use stickslip_scenario::{Runner, Scenario, Summary};

/// Runs shorter than this many steps get no progress bar.
const PROGRESS_MIN_STEPS: u64 = 1000;
/// Bodies listed in the summary table (all of them are in the JSON).
const TABLE_BODIES: usize = 12;

/// Arguments of `stickslip run`.
#[derive(Debug, Args)]
pub struct RunArgs {
    /// Scenario file (TOML). Without one, the built-in showcase runs (three inclined troughs:
    /// EP holding, EP conveying under ultrasonic vibration at Popov's speed, plain rapier
    /// friction) and the comparison is printed; run from a terminal without `--rrd`, it is
    /// recorded to `stickslip-showcase.rrd` for rerun.
    #[arg(value_name = "SCENARIO.toml")]
    scenario: Option<PathBuf>,
    /// Write a rerun recording to this `.rrd` file (open it with `rerun FILE`).
    #[arg(long, value_name = "FILE")]
    rrd: Option<PathBuf>,
    /// Stream live to a rerun viewer: the local one (start it with `rerun`) when ADDR is
    /// omitted, else HOST:PORT or a `rerun+http://…/proxy` URL. Put the scenario before
    /// `--connect` or use `--connect=ADDR`.
    #[arg(long, value_name = "ADDR", num_args = 0..=1, default_missing_value = "")]
    connect: Option<String>,
    /// Number of steps (default: the scenario's duration or steps).
    #[arg(long, value_name = "N")]
    steps: Option<u64>,
    /// Log every K-th step to rerun (default: the scenario's `log_every`).
    #[arg(long, value_name = "K")]
    every: Option<u64>,
    /// Only parse and validate the scenario, then print what it contains.
    #[arg(long)]
    check: bool,
    /// After the run, write a snapshot of it (world, friction state, statistics) to FILE;
    /// `--resume FILE` continues from it bit-identically.
    #[arg(long, value_name = "FILE")]
    snapshot_out: Option<PathBuf>,
    /// Continue the run saved with `--snapshot-out` (same scenario file) instead of starting
    /// at step 0; `--steps` counts the further steps (default: the scenario's remaining ones).
    #[arg(long, value_name = "FILE")]
    resume: Option<PathBuf>,
}

/// The JSON document `--json` prints.
#[derive(Debug, Serialize)]
struct RunReport<'a> {
    #[serde(flatten)]
    summary: &'a Summary,
    /// Steps logged to rerun (0 without a sink).
    logged_steps: u64,
    /// The `.rrd` written, if any.
    rrd: Option<String>,
    /// Wall-clock time of the run (s).
    wall_seconds: f64,
    /// The built-in showcase's comparison (absent for other scenarios).
    #[serde(skip_serializing_if = "Option::is_none")]
    showcase: Option<Vec<crate::showcase::Row>>,
}

/// Where the recording is written before it is renamed.
struct PendingRrd {
    tmp: PathBuf,
    target: PathBuf,
}

impl PendingRrd {
    fn new(target: &Path) -> Self {
        let dir = target
            .parent()
            .filter(|p| !p.as_os_str().is_empty())
            .unwrap_or(Path::new("."));
        let name = target
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_else(|| "recording.rrd".into());
        PendingRrd {
            tmp: dir.join(format!(".{name}.{}.partial", std::process::id())),
            target: target.to_path_buf(),
        }
    }

    fn commit(self) -> Result<(), CliError> {
        std::fs::rename(&self.tmp, &self.target).map_err(|e| {
            let _ = std::fs::remove_file(&self.tmp);
            CliError::Io(format!(
                "cannot move the recording to {}: {e}",
                self.target.display()
            ))
        })
    }

    fn abandon(self) {
        let _ = std::fs::remove_file(&self.tmp);
    }
}

/// Runs `stickslip run`.
pub fn run(args: &RunArgs, json: bool) -> Result<(), CliError> {
    // `--connect scenario.toml` swallows the scenario: take it back.
    let (scenario_path, connect) = match (&args.scenario, &args.connect) {
        (None, Some(c)) if c.ends_with(".toml") => (Some(PathBuf::from(c)), Some(String::new())),
        (s, c) => (s.clone(), c.clone()),
    };
    let mut scenario = match &scenario_path {
        Some(p) => Scenario::from_path(p)?,
        None => Scenario::builtin(),
    };
    if args.every == Some(0) {
        return Err(CliError::Argument("--every must be >= 1".into()));
    }
    if let Some(n) = args.steps {
        // The scenario's own bounds (steps, steps x objects) apply to the override.
        scenario.run.steps = Some(n);
        scenario.run.duration = None;
        scenario
            .validate()
            .map_err(|e| CliError::Argument(format!("--steps {n}: {e}")))?;
    }
    if args.check {
        return check(&scenario, json);
    }

    let scene = scenario.build()?;
    let (scenario_steps, every) = (scene.steps, args.every.unwrap_or(scene.log_every));
    let runner = match &args.resume {
        Some(path) => {
            let file = std::fs::File::open(path).map_err(|e| snapshot_error(path, e))?;
            Runner::resume(scene, file).map_err(|e| snapshot_error(path, e))?
        }
        None => Runner::new(scene),
    };
    let steps = args
        .steps
        .unwrap_or(scenario_steps.saturating_sub(runner.steps_done()));

    let showcase = crate::showcase::applies(&scenario);
    // An interactive bare run records itself, so that it can be looked at in rerun.
    let default_rrd = (showcase
        && args.rrd.is_none()
        && connect.is_none()
        && args.resume.is_none()
        && !json
        && std::io::stdout().is_terminal())
    .then(|| PathBuf::from("stickslip-showcase.rrd"));
    if let Some(addr) = &connect {
        // Fail fast (exit 2) instead of streaming into nothing.
        let addr = (!addr.is_empty()).then_some(addr.as_str());
        stickslip_rerun::check_reachable(addr, std::time::Duration::from_secs(3))?;
    }
    let mut sinks = Vec::new();
    let pending = args
        .rrd
        .as_deref()
        .or(default_rrd.as_deref())
        .map(PendingRrd::new);
    if let Some(p) = &pending {
        sinks.push(Sink::File(p.tmp.clone()));
    }
    if let Some(addr) = &connect {
        sinks.push(Sink::Grpc((!addr.is_empty()).then(|| addr.clone())));
    }
    let result = simulate(runner, steps, every, &sinks, json).map_err(|e| match (e, &connect) {
        (CliError::Rerun(stickslip_rerun::LogError::Flush(msg)), Some(addr)) => {
            let url = stickslip_rerun::grpc_url((!addr.is_empty()).then_some(addr.as_str()));
            CliError::Rerun(stickslip_rerun::LogError::Flush(format!(
                "{msg} (is a rerun viewer listening at {url}? start one with `rerun`)"
            )))
        }
        (e, _) => e,
    });
    let (summary, logged, wall, runner) = match result {
        Ok(r) => r,
        Err(e) => {
            if let Some(p) = pending {
                p.abandon();
            }
            return Err(e);
        }
    };
    if let Some(path) = &args.snapshot_out {
        write_snapshot(&runner, path)?;
    }
    let rrd = match pending {
        Some(p) => {
            let target = p.target.display().to_string();
            p.commit()?;
            Some(target)
        }
        None => None,
    };
    let report = RunReport {
        summary: &summary,
        logged_steps: logged,
        rrd,
        wall_seconds: wall,
        showcase: showcase.then(|| crate::showcase::compare(&summary)),
    };
    if json {
        output::json(&report)
    } else {
        print_table(&report);
        if let Some(rows) = &report.showcase {
            crate::showcase::print(rows, report.rrd.as_deref());
        }
        Ok(())
    }
}

/// Steps the scene, logging to `sinks`; returns the summary, the steps logged and the wall time.
/// The recording stream is flushed and dropped (which finalizes an `.rrd`) before returning.
fn simulate(
    mut runner: Runner,
    steps: u64,
    every: u64,
    sinks: &[Sink],
    json: bool,
) -> Result<(Summary, u64, f64, Runner), CliError> {
    let scene = runner.scene();
    let mut logger = if sinks.is_empty() {
        None
    } else {
        let (rec, _) = stickslip_rerun::open_all(&scene.name, sinks)?;
        let mut logger = RerunLogger::new(
            rec,
            LogOptions {
                every,
                max_contact_series: scene.max_contact_series,
                ..LogOptions::default()
            },
        );
        for b in &scene.bodies {
            logger.set_body_name(b.handle, &b.name);
        }
        Some(logger)
    };
    let bar = progress_bar(steps, json);
    let started = Instant::now();
    // A resumed run logs on from the saved step number.
    let base = runner.steps_done();
    if let Some(l) = logger.as_mut() {
        let s = runner.scene();
        l.log_step_always(base, &s.world, &s.stickslip)?;
    }
    for k in 1..=steps {
        runner.step();
        if let Some(l) = logger.as_mut() {
            let s = runner.scene();
            if k == steps {
                l.log_step_always(base + k, &s.world, &s.stickslip)?;
            } else {
                l.log_step(base + k, &s.world, &s.stickslip)?;
            }
        }
        if k % 64 == 0 {
            bar.set_position(k);
        }
    }
    let logged = logger.as_ref().map_or(0, |l| l.logged_steps());
    if let Some(l) = logger {
        l.flush()?;
        drop(l); // the last handle: finalizes the file sink (footer) and joins its thread
    }
    bar.finish_and_clear();
    let wall = started.elapsed().as_secs_f64();
    Ok((runner.summary(), logged, wall, runner))
}

fn snapshot_error(path: &Path, e: impl std::fmt::Display) -> CliError {
    CliError::Io(format!("snapshot {}: {e}", path.display()))
}

/// Writes the snapshot beside `path` first and renames it, so a failed write never leaves a
/// partial file under the name asked for.
fn write_snapshot(runner: &Runner, path: &Path) -> Result<(), CliError> {
    let pending = PendingRrd::new(path);
    let written = std::fs::File::create(&pending.tmp)
        .map_err(|e| snapshot_error(path, e))
        .and_then(|f| runner.save_snapshot(f).map_err(|e| snapshot_error(path, e)));
    match written {
        Ok(()) => pending.commit(),
        Err(e) => {
            pending.abandon();
            Err(e)
        }
    }
}

fn progress_bar(steps: u64, json: bool) -> ProgressBar {
    if json || steps < PROGRESS_MIN_STEPS || !std::io::stderr().is_terminal() {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::with_draw_target(Some(steps), ProgressDrawTarget::stderr());
    if let Ok(style) = ProgressStyle::with_template(
        "{spinner} [{elapsed_precise}] {bar:40} {pos}/{len} steps ({per_sec}, eta {eta})",
    ) {
        bar.set_style(style);
    }
    bar
}

fn check(scenario: &Scenario, json: bool) -> Result<(), CliError> {
    let scene = scenario.build()?;
    #[derive(Serialize)]
    struct Check<'a> {
        scenario: &'a str,
        valid: bool,
        bodies: usize,
        colliders: usize,
        drivers: usize,
        steps: u64,
        dt: f64,
    }
    let c = Check {
        scenario: &scenario.name,
        valid: true,
        bodies: scene.bodies.len(),
        colliders: scene.colliders.len(),
        drivers: scene.drivers.len(),
        steps: scene.steps,
        dt: scenario.world.dt,
    };
    if json {
        return output::json(&c);
    }
    output::pairs(&[
        ("scenario", format!("{} (valid)", c.scenario)),
        ("bodies", c.bodies.to_string()),
        ("colliders", c.colliders.to_string()),
        ("drivers", c.drivers.to_string()),
        ("steps", format!("{} × dt {} s", c.steps, c.dt)),
    ]);
    Ok(())
}

fn print_table(r: &RunReport<'_>) {
    let s = r.summary;
    let mut rows = vec![
        ("scenario", s.scenario.clone()),
        (
            "steps",
            format!(
                "{} (dt {:.6} s, {:.3} s simulated, {:.2} s wall)",
                s.steps, s.dt, s.sim_time, r.wall_seconds
            ),
        ),
        (
            "contacts (last step)",
            format!(
                "{} sticking, {} stick-slip, {} sliding",
                s.contacts.sticking, s.contacts.stick_slip, s.contacts.sliding
            ),
        ),
        (
            "contact-steps (run)",
            format!(
                "{} sticking, {} stick-slip, {} sliding (max {} contacts)",
                s.regime_steps.sticking,
                s.regime_steps.stick_slip,
                s.regime_steps.sliding,
                s.max_contacts
            ),
        ),
        (
            "dissipated energy",
            format!("{} J", number(s.dissipated_energy)),
        ),
        ("finite state", s.finite.to_string()),
    ];
    if let Some(path) = &r.rrd {
        rows.push((
            "recording",
            format!("{path} ({} steps logged)", r.logged_steps),
        ));
    } else if r.logged_steps > 0 {
        rows.push(("streamed", format!("{} steps logged", r.logged_steps)));
    }
    output::pairs(&rows);
    if s.bodies.is_empty() {
        return;
    }
    out!("");
    out!(
        "{:<16} {:>10} {:>12} {:>12} {:>12} {:>12}",
        "body",
        "kind",
        "dx m",
        "dy m",
        "|d| m",
        "speed m/s"
    );
    for b in s.bodies.iter().take(TABLE_BODIES) {
        out!(
            "{:<16} {:>10} {:>12.4e} {:>12.4e} {:>12.4e} {:>12.4e}",
            b.name,
            format!("{:?}", b.kind).to_lowercase(),
            b.displacement[0],
            b.displacement[1],
            b.distance,
            b.speed
        );
    }
    if s.bodies.len() > TABLE_BODIES {
        let max = s.bodies.iter().map(|b| b.distance).fold(0.0, f64::max);
        out!(
            "… {} more bodies (largest |d| of all: {max:.4e} m; --json lists every body)",
            s.bodies.len() - TABLE_BODIES
        );
    }
}

/// Fixed notation for ordinary magnitudes, scientific otherwise.
fn number(x: f64) -> String {
    if x == 0.0 || (1e-3..1e6).contains(&x.abs()) {
        format!("{x:.6}")
    } else {
        format!("{x:.4e}")
    }
}
