//! The seed's Example 1 (Fig. 1 C, D): a 1 kg block under F(t) through sticking at
//! 0.95 F_ba (phase I, 0–1 s), break-away and sliding at 1.5 F_ba (II, 1–2 s) and slip-stick
//! back to rest (III, 2–3 s); displacement and friction force over time for Phys, EP and Regul
//! (several ġ_t0), in the core's ODE simulator and in a rapier world
//! (`crate::scenes::example1_trace`), and the integrators' cost.
//! Parameters as in `tests/example1_reference.rs` and `crates/stickslip-fixtures/tests/rapier_example1.rs`.

use crate::FigureError;
use serde::Serialize;
use stickslip_core::law::{Law, Physical, Regularization, Regularized};
use stickslip_core::sliding_curve::Curve;
use stickslip_theory::block::{Block, ForceProfile, Integrator, STICK_SPEED, Tolerances, simulate};

/// Block mass (kg).
pub const MASS: f64 = 1.0;
/// Gravity (m/s²).
pub const G: f64 = 9.81;
/// Break-away coefficient.
pub const MU_BA: f64 = 0.3;
/// Upper threshold = sliding level.
pub const MU_MAX: f64 = 0.32;
/// EP stiffness (1/m).
pub const C: f64 = 1e4;
/// Ends of the three phases (s).
pub const PHASE_ENDS: [f64; 3] = [1.0, 2.0, 3.0];
/// rapier's step for Example 1 (s), as in `crates/stickslip-fixtures/tests/rapier_example1.rs`.
pub const RAPIER_DT: f64 = 1.0 / 240.0;

/// Displacement and friction force over time for one law.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Trace {
    /// Law (and regularization).
    pub label: String,
    /// Times (s).
    pub t: Vec<f64>,
    /// Displacement (m).
    pub x: Vec<f64>,
    /// Friction force on the block along x (N; negative while it resists a push along +x).
    pub friction: Vec<f64>,
}

impl Trace {
    /// Displacement at the last sample (m).
    pub fn final_x(&self) -> f64 {
        self.x.last().copied().unwrap_or(f64::NAN)
    }

    /// Largest |x| for t ≤ `until` (m).
    pub fn max_abs_x_until(&self, until: f64) -> f64 {
        self.t
            .iter()
            .zip(&self.x)
            .filter(|(t, _)| **t <= until + 1e-9)
            .fold(0.0, |m, (_, x)| m.max(x.abs()))
    }
}

/// Cost of one core run.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Timing {
    /// Law.
    pub law: String,
    /// Integrator.
    pub integrator: String,
    /// Wall-clock time (s), `None` when the integrator gave up.
    pub seconds: Option<f64>,
    /// Right-hand-side evaluations, `None` when the integrator gave up.
    pub evals: Option<usize>,
}

/// Everything Fig. 1 C and D show.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Example1 {
    /// Core simulator runs.
    pub core: Vec<Trace>,
    /// rapier runs at [`RAPIER_DT`].
    pub rapier: Vec<Trace>,
    /// Integration cost per law and method.
    pub timings: Vec<Timing>,
}

/// The profile of the seed's three phases.
pub fn profile() -> Result<ForceProfile, FigureError> {
    Ok(ForceProfile::example1(MU_BA * MASS * G, 0.95, 1.5)?)
}

fn curve() -> Result<Curve, FigureError> {
    Ok(Curve::constant(MU_MAX)?)
}

/// The laws compared: Phys, EP and Regul with each of `v_regs`.
pub fn laws(v_regs: &[f64]) -> Result<Vec<(String, Law)>, FigureError> {
    let mut out = vec![
        (
            "Phys".to_string(),
            Law::Physical(Physical::new(MU_BA, curve()?)?),
        ),
        (
            "EP".to_string(),
            Law::elasto_plastic(C, MU_BA, MU_MAX, curve()?)?,
        ),
    ];
    for &v in v_regs {
        out.push((
            format!("Regul ġ_t0 = {v}"),
            Law::Regularized(Regularized::new(curve()?, v, Regularization::Linear)?),
        ));
    }
    Ok(out)
}

/// Runs everything: core traces for Phys, EP and Regul at each of `v_regs` (explicit RKF45,
/// implicit ESDIRK for ġ_t0 < 1e-3), rapier traces for the same laws, and the cost of every
/// law with ġ_t0 ≥ 1e-3 under each of the three integrators. Traces keep at most
/// `max_points` samples.
pub fn compute(v_regs: &[f64], max_points: usize) -> Result<Example1, FigureError> {
    let profile = profile()?;
    let mut core = Vec::new();
    let mut rapier = Vec::new();
    let mut timings = Vec::new();
    for (label, law) in laws(v_regs)? {
        let stiff = matches!(&law, Law::Regularized(r) if r.v_reg() < 1e-3);
        let block = Block::new(MASS, G, law.clone())?;
        let integrator = if stiff {
            Integrator::Implicit
        } else {
            Integrator::Explicit
        };
        let run = simulate(
            &block,
            &profile,
            integrator,
            Tolerances::default(),
            &PHASE_ENDS,
        )?;
        let n_force = block.normal_force();
        let friction: Vec<f64> = run
            .t
            .iter()
            .zip(&run.v)
            .zip(&run.mu)
            .map(|((&t, &v), &mu)| match law {
                // The switched model's sticking force is whatever holds the block.
                Law::Physical(_) if v.abs() < STICK_SPEED && mu == 0.0 => -profile.value(t),
                _ => -n_force * mu,
            })
            .collect();
        let idx: Vec<usize> = super::thin(&(0..run.t.len()).collect::<Vec<_>>(), max_points);
        core.push(Trace {
            label: label.clone(),
            t: idx.iter().map(|&i| run.t[i]).collect(),
            x: idx.iter().map(|&i| run.x[i]).collect(),
            friction: idx.iter().map(|&i| friction[i]).collect(),
        });
        let samples =
            crate::scenes::example1_trace(law.clone(), &profile, RAPIER_DT, PHASE_ENDS[2]);
        let samples = super::thin(&samples, max_points);
        rapier.push(Trace {
            label: label.clone(),
            t: samples.iter().map(|s| s.t).collect(),
            x: samples.iter().map(|s| s.x).collect(),
            friction: samples.iter().map(|s| s.friction).collect(),
        });
        if !stiff {
            for (name, integ) in [
                ("RKF45", Integrator::Explicit),
                ("DoPri54", Integrator::DormandPrince),
                ("ESDIRK32", Integrator::Implicit),
            ] {
                let r = simulate(&block, &profile, integ, Tolerances::default(), &PHASE_ENDS);
                timings.push(Timing {
                    law: label.clone(),
                    integrator: name.into(),
                    seconds: r.as_ref().ok().map(|r| r.stats.seconds),
                    evals: r.as_ref().ok().map(|r| r.stats.function_evals),
                });
            }
        }
    }
    Ok(Example1 {
        core,
        rapier,
        timings,
    })
}
