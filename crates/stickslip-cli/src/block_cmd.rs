//! `stickslip block`: the seed's Example 1 with any law.

use crate::{CliError, output};
use clap::{Args, ValueEnum};
use serde::Serialize;
use stickslip_core::error::in_range;
use stickslip_core::law::{Coulomb, Law, Physical, Regularization, Regularized};
use stickslip_core::sliding_curve::{Curve, StribeckDecay};
use stickslip_theory::block::{Block, BlockRun, ForceProfile, Integrator, Tolerances, simulate};

/// Which law the block's contact uses.
#[derive(Debug, Clone, Copy, ValueEnum)]
pub enum LawName {
    /// Elasto-plastic (seed Eq. 4–7).
    Ep,
    /// Exact switched (seed Eq. 1–3).
    Phys,
    /// Regularized with velocity --v-reg.
    Regul,
    /// Plain Coulomb with coefficient --mu-max.
    Coulomb,
}

/// Which ODE method integrates it.
#[derive(Debug, Clone, Copy, ValueEnum)]
pub enum IntegratorName {
    /// Runge–Kutta–Fehlberg 4(5).
    Explicit,
    /// Dormand–Prince 5(4) (ode45).
    DormandPrince,
    /// ESDIRK 3(2), L-stable (stiff).
    Implicit,
}

/// Decay of a Stribeck curve.
#[derive(Debug, Clone, Copy, ValueEnum)]
pub enum DecayName {
    /// exp(−v/v_s).
    Exp,
    /// exp(−(v/v_s)²).
    Gauss,
}

/// Arguments of `stickslip block`.
#[derive(Debug, Args)]
pub struct BlockArgs {
    /// Friction law.
    #[arg(long, value_enum, default_value = "ep")]
    law: LawName,
    /// Block mass (kg).
    #[arg(long, default_value_t = 1.0)]
    mass: f64,
    /// Gravity (m/s²); the normal force is mass·gravity.
    #[arg(long, default_value_t = 9.81)]
    gravity: f64,
    /// Break-away coefficient μ_ba.
    #[arg(long, default_value_t = 0.3)]
    mu_ba: f64,
    /// Upper switch threshold μ_max = μ_ve(0+) (also the Coulomb coefficient).
    #[arg(long, default_value_t = 0.32)]
    mu_max: f64,
    /// EP stiffness c (1/m).
    #[arg(long, default_value_t = 1e4)]
    c: f64,
    /// Stribeck curve "MU_K,V_S" falling (or rising) from μ_max to MU_K with velocity V_S;
    /// constant μ_max when absent.
    #[arg(long, value_name = "MU_K,V_S")]
    stribeck: Option<String>,
    /// Stribeck decay shape.
    #[arg(long, value_enum, default_value = "gauss")]
    decay: DecayName,
    /// Viscous slope added to the sliding curve (s/m).
    #[arg(long, default_value_t = 0.0)]
    viscous: f64,
    /// Regularization velocity ġ_t0 of Regul (m/s).
    #[arg(long, default_value_t = 0.01)]
    v_reg: f64,
    /// Force profile "t0:F0,t1:F1,..." (s:N, piecewise linear, at most 1000 s long). Default:
    /// the seed's three phases built from --hold and --push.
    #[arg(long, value_name = "T:F,...")]
    force_profile: Option<String>,
    /// Phase I force as a fraction of F_ba (default profile), in [0, 1000].
    #[arg(long, default_value_t = 0.95)]
    hold: f64,
    /// Phase II force as a multiple of F_ba (default profile), in [0, 1000].
    #[arg(long, default_value_t = 1.5)]
    push: f64,
    /// ODE method.
    #[arg(long, value_enum, default_value = "explicit")]
    integrator: IntegratorName,
    /// Relative tolerance, in [1e-14, 0.1].
    #[arg(long, default_value_t = 1e-8)]
    rtol: f64,
    /// Absolute tolerance, in [1e-20, 0.1].
    #[arg(long, default_value_t = 1e-10)]
    atol: f64,
}

#[derive(Serialize)]
struct Report<'a> {
    law: &'a str,
    integrator: Integrator,
    phases: &'a [stickslip_theory::block::PhaseSummary],
    final_displacement: f64,
    stick_time: f64,
    slip_time: f64,
    break_away_displacement: Option<f64>,
    stats: stickslip_theory::block::RunStats,
}

fn curve(args: &BlockArgs) -> Result<Curve, CliError> {
    let decay = match args.decay {
        DecayName::Exp => StribeckDecay::Exponential,
        DecayName::Gauss => StribeckDecay::Gaussian,
    };
    match &args.stribeck {
        None if args.viscous == 0.0 => Ok(Curve::constant(args.mu_max)?),
        None => Ok(Curve::stribeck(
            args.mu_max,
            args.mu_max,
            1.0,
            decay,
            args.viscous,
        )?),
        Some(spec) => {
            let nums = parse_numbers(spec, ',')?;
            let [mu_k, v_s] = nums[..] else {
                return Err(CliError::Argument(format!(
                    "--stribeck expects MU_K,V_S, got {spec:?}"
                )));
            };
            Ok(Curve::stribeck(
                args.mu_max,
                mu_k,
                v_s,
                decay,
                args.viscous,
            )?)
        }
    }
}

fn parse_numbers(spec: &str, sep: char) -> Result<Vec<f64>, CliError> {
    spec.split(sep)
        .map(|s| {
            s.trim()
                .parse::<f64>()
                .map_err(|e| CliError::Argument(format!("{s:?} is not a number ({e})")))
        })
        .collect()
}

fn profile(args: &BlockArgs, f_ba: f64) -> Result<ForceProfile, CliError> {
    in_range("hold", args.hold, 0.0, 1e3)?;
    in_range("push", args.push, 0.0, 1e3)?;
    match &args.force_profile {
        None => Ok(ForceProfile::example1(f_ba, args.hold, args.push)?),
        Some(spec) => {
            let (mut times, mut forces) = (Vec::new(), Vec::new());
            for knot in spec.split(',') {
                let nums = parse_numbers(knot, ':')?;
                let [t, f] = nums[..] else {
                    return Err(CliError::Argument(format!(
                        "--force-profile knot {knot:?} is not T:F"
                    )));
                };
                times.push(t);
                forces.push(f);
            }
            Ok(ForceProfile::new(times, forces)?)
        }
    }
}

fn law(args: &BlockArgs) -> Result<Law, CliError> {
    let curve = curve(args)?;
    Ok(match args.law {
        LawName::Ep => Law::elasto_plastic(args.c, args.mu_ba, args.mu_max, curve)?,
        LawName::Phys => Law::Physical(Physical::new(args.mu_ba, curve)?),
        LawName::Regul => {
            Law::Regularized(Regularized::new(curve, args.v_reg, Regularization::Linear)?)
        }
        LawName::Coulomb => Law::Coulomb(Coulomb::new(args.mu_max)?),
    })
}

/// Runs `stickslip block`.
pub fn run(args: &BlockArgs, json: bool) -> Result<(), CliError> {
    let law = law(args)?;
    let break_away = match &law {
        Law::ElastoPlastic(l) => Some(l.break_away_displacement()),
        _ => None,
    };
    let block = Block::new(args.mass, args.gravity, law)?;
    let profile = profile(args, args.mu_ba * block.normal_force())?;
    let integrator = match args.integrator {
        IntegratorName::Explicit => Integrator::Explicit,
        IntegratorName::DormandPrince => Integrator::DormandPrince,
        IntegratorName::Implicit => Integrator::Implicit,
    };
    let tol = Tolerances {
        rtol: args.rtol,
        atol: args.atol,
        ..Tolerances::default()
    };
    tol.validate()?;
    let end = profile.end();
    let ends: Vec<f64> = if args.force_profile.is_none() {
        vec![1.0, 2.0, 3.0]
    } else {
        vec![end]
    };
    let r: BlockRun = simulate(&block, &profile, integrator, tol, &ends)?;
    let report = Report {
        law: r.law,
        integrator,
        phases: &r.phases,
        final_displacement: r.final_displacement(),
        stick_time: r.stick_time,
        slip_time: r.slip_time,
        break_away_displacement: break_away,
        stats: r.stats,
    };
    if json {
        return output::json(&report);
    }
    out!("block, law {} , integrator {integrator:?}", r.law);
    out!("{:>8} {:>14} {:>14}", "t (s)", "x (m)", "v (m/s)");
    for p in &r.phases {
        out!("{:>8.3} {:>14.6e} {:>14.6e}", p.t, p.x, p.v);
    }
    let mut rows = vec![
        ("stick time (s)", format!("{:.4}", r.stick_time)),
        ("slip time (s)", format!("{:.4}", r.slip_time)),
        ("accepted steps", r.stats.accepted_steps.to_string()),
        ("rejected steps", r.stats.rejected_steps.to_string()),
        ("rhs evaluations", r.stats.function_evals.to_string()),
        (
            "integration time (ms)",
            format!("{:.3}", r.stats.seconds * 1e3),
        ),
    ];
    if let Some(g) = break_away {
        rows.push(("g_ba = mu_ba/c (m)", format!("{g:.3e}")));
    }
    output::pairs(&rows);
    Ok(())
}
