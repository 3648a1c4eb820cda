//! `stickslip sweep`: Popov and feeder maps over independent rapier worlds, in parallel.

use crate::{CliError, output};
use clap::{Args, Subcommand, ValueEnum};
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use stickslip_core::waveform::WaveformKind;
use stickslip_figures::sweep::feeder::{
    AMPLITUDE_LIMITS, ANGLE_LIMITS, FREQUENCY_LIMITS, FeederSweep,
};
use stickslip_figures::sweep::output::{write_feeder, write_popov};
use stickslip_figures::sweep::popov::{ALPHA_LIMITS, BETA_LIMITS, Drive, PopovSweep};
use stickslip_figures::sweep::{MAX_THREADS, Range};

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

fn report(files: &[PathBuf], dir: &Path, json: bool) -> Result<(), CliError> {
    if json {
        output::json(&serde_json::json!({ "out": dir, "files": files }))?;
    } else {
        for f in files {
            out!("{}", f.display());
        }
    }
    Ok(())
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
            let total = sweep.validate()?;
            let threads = threads(a.common.threads)?;
            let bar = progress(total, json);
            let points = sweep.run(threads, &|| bar.inc(1))?;
            bar.finish_and_clear();
            let files = write_popov(&a.common.out, &sweep, &points)?;
            report(&files, &a.common.out, json)
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
            let total = sweep.validate()?;
            let threads = threads(a.common.threads)?;
            let bar = progress(total, json);
            let points = sweep.run(threads, &|| bar.inc(1))?;
            bar.finish_and_clear();
            let files = write_feeder(&a.common.out, &sweep, &points)?;
            report(&files, &a.common.out, json)
        }
    }
}
