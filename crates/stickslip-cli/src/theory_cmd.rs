//! `stickslip theory`: Popov's vibration theory from the command line.

use crate::{CliError, output};
use clap::{Args, Subcommand, ValueEnum};
use serde::Serialize;
use stickslip_core::waveform::{Waveform, WaveformKind};
use stickslip_theory::popov;

/// Arguments of `stickslip theory`.
#[derive(Debug, Args)]
pub struct TheoryArgs {
    #[command(subcommand)]
    command: TheoryCommand,
}

#[derive(Debug, Subcommand)]
enum TheoryCommand {
    /// Ψ_w(β) (Eq. 25/31, numeric) with the closed form (Eq. 34–36) where one exists.
    Psi {
        /// Waveform.
        #[arg(long, value_parser = parse_waveform)]
        waveform: WaveformKind,
        /// Dimensionless velocity β (Eq. 17).
        #[arg(long)]
        beta: f64,
    },
    /// μ̄ = μ0 (1 − α Ψ_w(β)) (Eq. 33).
    MuEff {
        /// Waveform.
        #[arg(long, value_parser = parse_waveform)]
        waveform: WaveformKind,
        /// Amplitude ratio α = A_z/ū_z (Eq. 16), in [0, 1].
        #[arg(long)]
        alpha: f64,
        /// Dimensionless velocity β.
        #[arg(long)]
        beta: f64,
        /// Coefficient of friction without vibration.
        #[arg(long)]
        mu0: f64,
    },
    /// Elliptical drive over the phase shift (compliant theory): normal amplitude α and a
    /// tangential one in slip lengths μ0 k_z ū_z / k_x, the tangential one a phase shift later.
    /// Prints the static band, the blocking force (over F̄), μ̄ at `--speed` and the free drive
    /// velocity (over slip length × frequency) per phase shift.
    Drive {
        /// Normal amplitude α = A_z/ū_z.
        #[arg(long)]
        alpha: f64,
        /// Tangential amplitude in slip lengths.
        #[arg(long)]
        tangential: f64,
        /// Coefficient of friction without vibration.
        #[arg(long)]
        mu0: f64,
        /// Waveform of both oscillations.
        #[arg(long, value_parser = parse_waveform, default_value = "sine")]
        waveform: WaveformKind,
        /// Drag speed (slip lengths per period) at which μ̄ is reported.
        #[arg(long, default_value_t = 0.0)]
        speed: f64,
        /// Phase shifts (periods), repeatable; default: 17 from −0.5 to 0.5.
        #[arg(long = "phase-shift", allow_hyphen_values = true)]
        phase_shift: Vec<f64>,
    },
    /// Static coefficient under oscillation (Eq. 4, 6, 8).
    Static {
        /// Direction of the oscillation.
        #[arg(long, value_enum)]
        direction: Direction,
        /// Amplitude over mean normal force, A/F_z.
        #[arg(long)]
        amplitude_ratio: f64,
        /// Coefficient of friction without vibration.
        #[arg(long)]
        mu0: f64,
    },
}

/// Oscillation direction.
#[derive(Debug, Clone, Copy, ValueEnum, Serialize)]
#[serde(rename_all = "kebab-case")]
enum Direction {
    /// Along the normal (Eq. 4).
    Normal,
    /// Along the sliding direction (Eq. 6).
    Tangential,
    /// In-plane, across the sliding direction (Eq. 8).
    Transverse,
}

fn parse_waveform(s: &str) -> Result<WaveformKind, String> {
    s.parse::<WaveformKind>().map_err(|e| e.to_string())
}

#[derive(Serialize)]
struct PsiReport {
    waveform: String,
    beta: f64,
    /// β_c, or `None` for waveforms without a critical velocity (square: Ψ > 0 for all β).
    beta_c: Option<f64>,
    psi: f64,
    psi_closed_form: Option<f64>,
}

#[derive(Serialize)]
struct MuEffReport {
    waveform: String,
    alpha: f64,
    beta: f64,
    mu0: f64,
    psi: f64,
    mu_eff: f64,
}

#[derive(Serialize)]
struct DriveReport {
    waveform: String,
    alpha: f64,
    tangential: f64,
    mu0: f64,
    speed: f64,
    points: Vec<popov::DrivePoint>,
}

/// Most phase shifts one `theory drive` evaluates.
const MAX_SHIFTS: usize = 1000;

#[derive(Serialize)]
struct StaticReport {
    direction: Direction,
    amplitude_ratio: f64,
    mu0: f64,
    mu_s: f64,
}

fn psi_of(kind: WaveformKind, beta: f64) -> Result<(Waveform, f64), CliError> {
    let w = Waveform::from(kind);
    let psi = popov::psi(&w, beta)?;
    Ok((w, psi))
}

/// Runs `stickslip theory`.
pub fn run(args: &TheoryArgs, json: bool) -> Result<(), CliError> {
    match &args.command {
        TheoryCommand::Psi { waveform, beta } => {
            let (w, psi) = psi_of(*waveform, *beta)?;
            let r = PsiReport {
                waveform: waveform.to_string(),
                beta: *beta,
                beta_c: Some(w.beta_c()).filter(|b| b.is_finite()),
                psi,
                psi_closed_form: popov::psi_closed_form(&w, *beta),
            };
            if json {
                return output::json(&r);
            }
            let mut rows = vec![
                ("waveform", r.waveform.clone()),
                ("beta", format!("{}", r.beta)),
                (
                    "beta_c",
                    r.beta_c
                        .map_or("none (psi > 0 for every beta)".into(), |b| format!("{b}")),
                ),
                ("psi (Eq. 25/31)", format!("{:.6}", r.psi)),
            ];
            if let Some(c) = r.psi_closed_form {
                rows.push(("psi closed form", format!("{c:.6}")));
            }
            output::pairs(&rows);
        }
        TheoryCommand::MuEff {
            waveform,
            alpha,
            beta,
            mu0,
        } => {
            let (_, psi) = psi_of(*waveform, *beta)?;
            let r = MuEffReport {
                waveform: waveform.to_string(),
                alpha: *alpha,
                beta: *beta,
                mu0: *mu0,
                psi,
                mu_eff: popov::mu_eff(*mu0, *alpha, psi)?,
            };
            if json {
                return output::json(&r);
            }
            output::pairs(&[
                ("waveform", r.waveform.clone()),
                ("psi", format!("{:.6}", r.psi)),
                ("mu_eff (Eq. 33)", format!("{:.6}", r.mu_eff)),
            ]);
        }
        TheoryCommand::Drive {
            alpha,
            tangential,
            mu0,
            waveform,
            speed,
            phase_shift,
        } => {
            let shifts: Vec<f64> = if phase_shift.is_empty() {
                (0..=16).map(|i| -0.5 + i as f64 / 16.0).collect()
            } else {
                phase_shift.iter().take(MAX_SHIFTS).copied().collect()
            };
            let w = Waveform::from(*waveform);
            let r = DriveReport {
                waveform: waveform.to_string(),
                alpha: *alpha,
                tangential: *tangential,
                mu0: *mu0,
                speed: *speed,
                points: popov::drive_curve(*mu0, *alpha, *tangential, &w, *speed, &shifts)?,
            };
            if json {
                return output::json(&r);
            }
            output::line(format_args!(
                "{:>8} {:>9} {:>9} {:>9} {:>9} {:>10}",
                "shift", "mu_lower", "mu_upper", "blocking", "mu_eff", "v_drive"
            ));
            for p in &r.points {
                output::line(format_args!(
                    "{:>8.4} {:>9.5} {:>9.5} {:>9.5} {:>9.5} {:>10.5}",
                    p.phase_shift, p.lower, p.upper, p.blocking, p.mu_eff, p.drive_velocity
                ));
            }
        }
        TheoryCommand::Static {
            direction,
            amplitude_ratio,
            mu0,
        } => {
            let mu_s = match direction {
                Direction::Normal => popov::mu_s_normal(*mu0, *amplitude_ratio)?,
                Direction::Tangential => popov::mu_s_tangential(*mu0, *amplitude_ratio)?,
                Direction::Transverse => popov::mu_s_transverse(*mu0, *amplitude_ratio)?,
            };
            let r = StaticReport {
                direction: *direction,
                amplitude_ratio: *amplitude_ratio,
                mu0: *mu0,
                mu_s,
            };
            if json {
                return output::json(&r);
            }
            output::pairs(&[("mu_s", format!("{:.6}", r.mu_s))]);
        }
    }
    Ok(())
}
