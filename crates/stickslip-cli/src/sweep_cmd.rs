//! `stickslip sweep`: Popov and feeder maps over independent rapier worlds, in parallel; one
//! shard of such a map (`--shard K/N`, task K of N of a job array), and `sweep merge`, which
//! puts the shards back together into the unsharded output.

use crate::{CliError, output};
use clap::{Args, Subcommand, ValueEnum};
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use stickslip_core::waveform::WaveformKind;
use stickslip_figures::sweep::feeder::{
    AMPLITUDE_LIMITS, ANGLE_LIMITS, FREQUENCY_LIMITS, FeederSweep,
};
use stickslip_figures::sweep::merge::{merge, shard_files};
use stickslip_figures::sweep::popov::{ALPHA_LIMITS, BETA_LIMITS, Drive, PopovSweep};
use stickslip_figures::sweep::shard_file::{Sharded, write_shard};
use stickslip_figures::sweep::{MAX_THREADS, Range, Shard};

/// Arguments of `stickslip sweep`.
#[derive(Debug, Args)]
pub struct SweepArgs {
    #[command(subcommand)]
    kind: SweepKind,
}

#[derive(Debug, Subcommand)]
enum SweepKind {
    /// Popov's μ̄ over β × α per waveform: theory (Eq. 33) and rapier.
    Popov(PopovArgs),
    /// Vibratory-feeder transport speed over amplitude × frequency × throw angle in rapier,
    /// beside the rigid-body reference.
    Feeder(FeederArgs),
    /// Put the shards of a sweep run with --shard K/N back together: the CSV, JSON and heat
    /// maps of the unsharded run, byte for byte.
    Merge(MergeArgs),
}

#[derive(Debug, Args)]
struct MergeArgs {
    /// Shard files (NAME.shard-K-of-N.json) or directories holding them: all N shards of one
    /// sweep, written by this version.
    #[arg(required = true, value_name = "FILES|DIR")]
    inputs: Vec<PathBuf>,
    /// Directory for the merged CSV, JSON and heat maps (created if missing).
    #[arg(long, default_value = "sweep")]
    out: PathBuf,
}

/// Options every sweep has.
#[derive(Debug, Args)]
struct Common {
    /// Worker threads (default: every core). Results do not depend on it.
    #[arg(long)]
    threads: Option<usize>,
    /// Directory for CSV, JSON and heat maps (created if missing).
    #[arg(long, default_value = "sweep")]
    out: PathBuf,
    /// Compute only task K of N (1-based: K in 1..=N, e.g. $SLURM_ARRAY_TASK_ID with
    /// --array=1-N): a fixed slice of the grid, written as NAME.shard-K-of-N.csv and .json
    /// into --out; `stickslip sweep merge` puts the N shards together.
    #[arg(long, value_name = "K/N")]
    shard: Option<Shard>,
}

#[derive(Debug, Clone, Copy, ValueEnum)]
enum DriveName {
    /// Time-resolved normal vibration source (400 steps per period).
    Resolved,
    /// Averaged vibration source (40 steps per period).
    Averaged,
    /// A real oscillating force on the sled.
    Load,
}

#[derive(Debug, Args)]
struct PopovArgs {
    /// Comma-separated waveforms: sine, sawtooth-right, sawtooth-left, square, impulse.
    #[arg(long, default_value = "sine,sawtooth-right,sawtooth-left,square")]
    waveforms: String,
    /// β grid LO:HI:N.
    #[arg(long, default_value = "0.5:12:8")]
    beta: String,
    /// α grid LO:HI:N (amplitude ratio, ≤ 1).
    #[arg(long, default_value = "0.2:0.8:4")]
    alpha: String,
    /// Theory only, no rapier worlds.
    #[arg(long)]
    theory_only: bool,
    /// How rapier modulates the normal force.
    #[arg(long, value_enum, default_value = "resolved")]
    drive: DriveName,
    #[command(flatten)]
    common: Common,
}

#[derive(Debug, Clone, Copy, ValueEnum)]
enum FeederLaw {
    /// stickslip's elasto-plastic contact (μ_ba = μ_max = μ, stiffness --c).
    Ep,
    /// Plain rapier Coulomb friction.
    Plain,
}

#[derive(Debug, Args)]
struct FeederArgs {
    /// Amplitude grid LO:HI:N (mm).
    #[arg(long, default_value = "0.5:2:4")]
    amplitude: String,
    /// Frequency grid LO:HI:N (Hz).
    #[arg(long, default_value = "20:40:3")]
    frequency: String,
    /// Throw-angle grid LO:HI:N (degrees).
    #[arg(long, default_value = "15:35:3")]
    angle: String,
    /// Friction coefficient μ.
    #[arg(long, default_value_t = 0.5)]
    mu: f64,
    /// rapier's time step (s).
    #[arg(long, default_value_t = 1.0 / 3000.0)]
    dt: f64,
    /// Friction at the trough.
    #[arg(long, value_enum, default_value = "ep")]
    law: FeederLaw,
    /// EP stiffness c (1/m).
    #[arg(long, default_value_t = 1e5)]
    c: f64,
    /// Periods to settle and to measure, SETTLE:MEASURE.
    #[arg(long, default_value = "20:20")]
    periods: String,
    #[command(flatten)]
    common: Common,
}

fn threads(requested: Option<usize>) -> Result<usize, CliError> {
    let n = requested.unwrap_or_else(|| {
        std::thread::available_parallelism()
            .map(|n| n.get())
            .unwrap_or(1)
            .min(MAX_THREADS)
    });
    if n == 0 || n > MAX_THREADS {
        return Err(CliError::Argument(format!(
            "--threads {n}: must be in 1..={MAX_THREADS}"
        )));
    }
    Ok(n)
}

fn progress(total: usize, json: bool) -> ProgressBar {
    if json || !std::io::stderr().is_terminal() {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::with_draw_target(Some(total as u64), ProgressDrawTarget::stderr());
    if let Ok(style) = ProgressStyle::with_template(
        "{spinner} [{elapsed_precise}] {bar:40} {pos}/{len} points (eta {eta})",
    ) {
        bar.set_style(style);
    }
    bar
}

fn report(
    files: &[PathBuf],
    dir: &Path,
    json: bool,
    extra: serde_json::Value,
) -> Result<(), CliError> {
    if json {
        let mut doc = serde_json::json!({ "out": dir, "files": files });
        if let (Some(doc), serde_json::Value::Object(extra)) = (doc.as_object_mut(), extra) {
            doc.extend(extra);
        }
        output::json(&doc)?;
    } else {
        for f in files {
            out!("{}", f.display());
        }
    }
    Ok(())
}

/// Runs `sweep` (the whole grid, or the slice of `--shard`) and writes its output.
fn execute<S: Sharded>(sweep: &S, common: &Common, json: bool) -> Result<(), CliError> {
    let total = sweep.total()?;
    let threads = threads(common.threads)?;
    let indices = match common.shard {
        Some(shard) => shard.indices(total),
        None => (0..total).collect(),
    };
    let bar = progress(indices.len(), json);
    let points = sweep.run_indices(&indices, threads, &|| bar.inc(1))?;
    bar.finish_and_clear();
    match common.shard {
        Some(shard) => {
            let files = write_shard(&common.out, sweep, shard, &points)?;
            let extra = serde_json::json!({ "shard": shard.to_string(), "points": points.len() });
            report(&files, &common.out, json, extra)
        }
        None => {
            let files = sweep.write(&common.out, &points)?;
            report(&files, &common.out, json, serde_json::Value::Null)
        }
    }
}

/// Runs `stickslip sweep merge`.
fn run_merge(args: &MergeArgs, json: bool) -> Result<(), CliError> {
    let refuse =
        |e: stickslip_figures::sweep::merge::MergeError| CliError::Io(format!("cannot merge: {e}"));
    let files = shard_files(&args.inputs).map_err(refuse)?;
    let merged = merge(&files).map_err(refuse)?;
    let written = merged.write(&args.out)?;
    let extra = serde_json::json!({ "shards": files, "points": merged.len() });
    report(&written, &args.out, json, extra)
}

/// Runs `stickslip sweep`.
pub fn run(args: &SweepArgs, json: bool) -> Result<(), CliError> {
    match &args.kind {
        SweepKind::Popov(a) => {
            let mut waveforms = Vec::new();
            for name in a.waveforms.split(',') {
                let name = name.trim();
                waveforms.push(
                    name.parse::<WaveformKind>()
                        .map_err(|e| CliError::Argument(format!("--waveforms: {e}")))?,
                );
            }
            let sweep = PopovSweep {
                waveforms,
                beta: Range::parse("--beta", &a.beta, BETA_LIMITS.0, BETA_LIMITS.1)?,
                alpha: Range::parse("--alpha", &a.alpha, ALPHA_LIMITS.0, ALPHA_LIMITS.1)?,
                rapier: !a.theory_only,
                drive: match a.drive {
                    DriveName::Resolved => Drive::Resolved,
                    DriveName::Averaged => Drive::Averaged,
                    DriveName::Load => Drive::Load,
                },
            };
            execute(&sweep, &a.common, json)
        }
        SweepKind::Feeder(a) => {
            let (settle, measure) = a
                .periods
                .split_once(':')
                .and_then(|(s, m)| Some((s.trim().parse().ok()?, m.trim().parse().ok()?)))
                .ok_or_else(|| {
                    CliError::Argument(format!(
                        "--periods `{}`: expected SETTLE:MEASURE (whole numbers)",
                        a.periods
                    ))
                })?;
            let sweep = FeederSweep {
                amplitude: Range::parse(
                    "--amplitude",
                    &a.amplitude,
                    AMPLITUDE_LIMITS.0,
                    AMPLITUDE_LIMITS.1,
                )?,
                frequency: Range::parse(
                    "--frequency",
                    &a.frequency,
                    FREQUENCY_LIMITS.0,
                    FREQUENCY_LIMITS.1,
                )?,
                angle: Range::parse("--angle", &a.angle, ANGLE_LIMITS.0, ANGLE_LIMITS.1)?,
                mu: a.mu,
                dt: a.dt,
                ep: match a.law {
                    FeederLaw::Ep => Some(a.c),
                    FeederLaw::Plain => None,
                },
                settle,
                measure,
            };
            execute(&sweep, &a.common, json)
        }
        SweepKind::Merge(a) => run_merge(a, json),
    }
}
