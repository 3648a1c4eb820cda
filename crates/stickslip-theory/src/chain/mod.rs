//! A reference model for the seed's Example 2 (Fig. 2B): a chain of many frictional contacts
//! under high-frequency oscillation, integrated with the same adaptive methods as the block
//! ([`crate::block::Integrator`]).
//!
//! ## The model
//! `links` masses m in a row, neighbours coupled by Kelvin–Voigt elements (stiffness k,
//! damping d), the last one tied to a fixed wall by the same element. The first one is tied
//! by the same element to a drive point that oscillates, x_d(t) = X sin(2π f t). Every mass
//! presses on a fixed guide with the normal force F_n and carries one frictional contact
//! (slip = the mass's velocity):
//!
//! m ẍ_i = k (x_{i−1} − 2 x_i + x_{i+1}) + d (ẋ_{i−1} − 2 ẋ_i + ẋ_{i+1}) − F_n μ_i,
//!
//! with x_{−1} = x_d(t), x_N = 0, and μ_i the elasto-plastic state (seed Eq. 4b, one extra
//! state per contact, as the seed's Eq. 8 says) or the regularized coefficient μ(ẋ_i).
//! The state vector is interleaved per link, [x_i, ẋ_i, (μ_i)], so the Jacobian is banded;
//! its last component is the friction work W = ∫ Σ F_n μ_i ẋ_i dt (J), the quantity of the
//! seed's Fig. 2C (chain friction power).
//!
//! Only the smooth laws fit an ODE integrator: `ChainLaw` is EP or Regul. The exact switched
//! model with 250 contacts is a complementarity problem, not an ODE, so a reference solution
//! is a tightly integrated smooth model (see `ChainRun::error_against`).
//!
//! `ChainParams::timing_drive` gives the parameters used in the benchmarks: 250 strand
//! segments pressed on a guide, driven at 500 Hz.
//!
//! ```
//! use stickslip_theory::block::{Integrator, Tolerances};
//! use stickslip_theory::chain::{Chain, ChainLaw, ChainParams, simulate};
//! use stickslip_core::law::{Regularization, Regularized};
//! use stickslip_core::sliding_curve::Curve;
//! let params = ChainParams { links: 10, ..ChainParams::timing_drive() };
//! let law = Regularized::new(Curve::constant(0.1).unwrap(), 0.01, Regularization::Linear).unwrap();
//! let chain = Chain::new(params, ChainLaw::Regularized(law)).unwrap();
//! let tol = Tolerances { rtol: 1e-6, atol: 1e-9, max_steps: 1_000_000 };
//! let run = simulate(&chain, Integrator::Explicit, tol, 0.01, 1e-3).unwrap();
//! assert!(run.final_work() > 0.0); // friction dissipates
//! ```

use crate::block::{Integrator, RunStats, SimError, Tolerances};
use crate::integrate::solve_with;
use differential_equations::prelude::*;
use serde::Serialize;
use std::time::Instant;
use stickslip_core::error::{ParamError, non_negative, positive};
use stickslip_core::law::{ElastoPlastic, Regularized};

/// Parameters of the chain (validated by [`Chain::new`]).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ChainParams {
    /// Number of masses, each with one frictional contact (≥ 1).
    pub links: usize,
    /// Mass of each link (kg).
    pub mass: f64,
    /// Stiffness of the coupling elements (N/m).
    pub stiffness: f64,
    /// Damping of the coupling elements (N s/m).
    pub damping: f64,
    /// Normal force of each contact (N).
    pub normal_force: f64,
    /// Amplitude X of the drive point (m).
    pub drive_amplitude: f64,
    /// Frequency f of the drive (Hz).
    pub drive_frequency: f64,
}

impl ChainParams {
    /// The benchmark chain: 250 strand segments of 10 g coupled with k = 2·10⁶ N/m
    /// (d = 2 N s/m), each pressed on a guide with 2 N, driven with X = 0.2 mm at f = 500 Hz
    /// (drive velocity amplitude 0.63 m/s, acceleration 200 g). With μ = 0.1 the oscillation
    /// travels the whole chain and reverses the slip of every contact twice a period: the
    /// seed's oscillatory sliding at all 250 contacts.
    pub fn timing_drive() -> Self {
        ChainParams {
            links: 250,
            mass: 0.01,
            stiffness: 2e6,
            damping: 2.0,
            normal_force: 2.0,
            drive_amplitude: 2e-4,
            drive_frequency: 500.0,
        }
    }

    fn validate(&self) -> Result<(), ParamError> {
        positive("links", self.links as f64)?;
        positive("mass", self.mass)?;
        positive("stiffness", self.stiffness)?;
        non_negative("damping", self.damping)?;
        positive("normal_force", self.normal_force)?;
        non_negative("drive_amplitude", self.drive_amplitude)?;
        positive("drive_frequency", self.drive_frequency)?;
        Ok(())
    }
}

/// The smooth friction laws the chain can be integrated with.
#[derive(Debug, Clone, PartialEq)]
pub enum ChainLaw {
    /// The seed's elasto-plastic law ("EP"): one extra state μ_i per contact.
    ElastoPlastic(ElastoPlastic),
    /// The regularized law ("Regul").
    Regularized(Regularized),
}

impl ChainLaw {
    /// `ep` or `regul`.
    pub fn name(&self) -> &'static str {
        match self {
            ChainLaw::ElastoPlastic(_) => "ep",
            ChainLaw::Regularized(_) => "regul",
        }
    }

    /// State components per link: 3 (x, ẋ, μ) for EP, 2 (x, ẋ) for Regul.
    pub fn stride(&self) -> usize {
        match self {
            ChainLaw::ElastoPlastic(_) => 3,
            ChainLaw::Regularized(_) => 2,
        }
    }
}

/// A chain with its friction law.
#[derive(Debug, Clone, PartialEq)]
pub struct Chain {
    params: ChainParams,
    law: ChainLaw,
}

impl Chain {
    /// Validates `params` (all positive, damping and amplitude ≥ 0, at least one link).
    pub fn new(params: ChainParams, law: ChainLaw) -> Result<Self, ParamError> {
        params.validate()?;
        Ok(Chain { params, law })
    }

    /// The parameters.
    pub fn params(&self) -> &ChainParams {
        &self.params
    }

    /// The law.
    pub fn law(&self) -> &ChainLaw {
        &self.law
    }

    /// Length of the ODE state: stride × links + 1 (the friction work).
    pub fn state_len(&self) -> usize {
        self.law.stride() * self.params.links + 1
    }

    /// Drive point position and velocity at `t`.
    #[inline]
    fn drive(&self, t: f64) -> (f64, f64) {
        let w = 2.0 * std::f64::consts::PI * self.params.drive_frequency;
        let a = self.params.drive_amplitude;
        (a * (w * t).sin(), a * w * (w * t).cos())
    }

    /// Friction coefficient of link `i` (signed, along +x) from its state slice.
    #[inline]
    fn mu(&self, link: &[f64]) -> f64 {
        match &self.law {
            ChainLaw::ElastoPlastic(_) => link[2],
            ChainLaw::Regularized(l) => l.coefficient(link[1]),
        }
    }

    /// Total tangential force of the coupling elements on link `i` (N).
    #[inline]
    fn coupling(&self, t_drive: (f64, f64), y: &[f64], i: usize) -> f64 {
        let s = self.law.stride();
        let n = self.params.links;
        let (x, v) = (y[i * s], y[i * s + 1]);
        let (xl, vl) = if i == 0 {
            t_drive
        } else {
            (y[(i - 1) * s], y[(i - 1) * s + 1])
        };
        let (xr, vr) = if i + 1 == n {
            (0.0, 0.0)
        } else {
            (y[(i + 1) * s], y[(i + 1) * s + 1])
        };
        self.params.stiffness * (xl - 2.0 * x + xr) + self.params.damping * (vl - 2.0 * v + vr)
    }
}

impl ODE<f64, Vec<f64>> for Chain {
    fn diff(&self, t: f64, y: &Vec<f64>, dydt: &mut Vec<f64>) {
        let s = self.law.stride();
        let n = self.params.links;
        let (m, f_n) = (self.params.mass, self.params.normal_force);
        let drive = self.drive(t);
        let mut power = 0.0;
        for i in 0..n {
            let link = &y[i * s..i * s + s];
            let mu = self.mu(link);
            let v = link[1];
            dydt[i * s] = v;
            dydt[i * s + 1] = (self.coupling(drive, y, i) - f_n * mu) / m;
            if let ChainLaw::ElastoPlastic(l) = &self.law {
                dydt[i * s + 2] = l.rate(mu, v);
            }
            power += f_n * mu * v;
        }
        dydt[n * s] = power;
    }
}

/// A finished chain run, sampled on a uniform output grid.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ChainRun {
    /// Law name.
    pub law: &'static str,
    /// Output times (s).
    pub t: Vec<f64>,
    /// Link displacements at each output time (m), `x[k][i]`.
    pub x: Vec<Vec<f64>>,
    /// Friction work since t = 0 at each output time (J).
    pub work: Vec<f64>,
    /// Integrator cost.
    pub stats: RunStats,
}

/// How far a run is from a reference run.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ChainError {
    /// Relative error of the friction work at the end, |W − W_ref| / W_ref.
    pub work: f64,
    /// Largest error of the friction work over the run, max_t |W(t) − W_ref(t)| / W_ref(end).
    pub work_max: f64,
    /// RMS displacement error over all links and output times, over the reference's RMS
    /// displacement.
    pub displacement: f64,
}

impl ChainRun {
    /// Friction work over the whole run (J).
    pub fn final_work(&self) -> f64 {
        *self.work.last().unwrap_or(&0.0)
    }

    /// Errors against `reference`, compared at the output times both runs share (the same
    /// grid for the same `output_dt`; runs of different length compare over the shorter).
    pub fn error_against(&self, reference: &ChainRun) -> ChainError {
        let k = self.t.len().min(reference.t.len());
        let w_ref_end = reference.work[k - 1].abs().max(f64::MIN_POSITIVE);
        let mut work_max: f64 = 0.0;
        let (mut se, mut sr) = (0.0, 0.0);
        for j in 0..k {
            work_max = work_max.max((self.work[j] - reference.work[j]).abs() / w_ref_end);
            for (a, b) in self.x[j].iter().zip(&reference.x[j]) {
                se += (a - b) * (a - b);
                sr += b * b;
            }
        }
        ChainError {
            work: (self.work[k - 1] - reference.work[k - 1]).abs() / w_ref_end,
            work_max,
            displacement: if sr > 0.0 { (se / sr).sqrt() } else { 0.0 },
        }
    }

    /// RMS displacement of each link over the run (m): how far the oscillation reaches.
    pub fn rms_displacement(&self) -> Vec<f64> {
        let n = self.x.first().map_or(0, |x| x.len());
        let mut acc = vec![0.0; n];
        for row in &self.x {
            for (a, x) in acc.iter_mut().zip(row) {
                *a += x * x;
            }
        }
        let k = self.x.len().max(1) as f64;
        acc.into_iter().map(|a| (a / k).sqrt()).collect()
    }
}

/// Integrates `chain` from rest over `[0, t_end]`, sampling every `output_dt`.
///
/// The reported wall time covers the integration only (not building the output). The implicit
/// method solves its Newton systems with the ODE crate's dense LU, O(n³) in the state length
/// n = 3·links + 1 (EP) or 2·links + 1 (Regul), which dominates its cost on long chains.
pub fn simulate(
    chain: &Chain,
    integrator: Integrator,
    tol: Tolerances,
    t_end: f64,
    output_dt: f64,
) -> Result<ChainRun, SimError> {
    let y0 = vec![0.0; chain.state_len()];
    let started = Instant::now();
    let sol = solve_with!(
        integrator,
        tol,
        IVP::ode(chain, 0.0, t_end, y0).even(output_dt)
    )?;
    let seconds = started.elapsed().as_secs_f64();
    let s = chain.law.stride();
    let n = chain.params.links;
    let x = sol
        .y
        .iter()
        .map(|y| (0..n).map(|i| y[i * s]).collect())
        .collect();
    let work = sol.y.iter().map(|y| y[n * s]).collect();
    Ok(ChainRun {
        law: chain.law.name(),
        t: sol.t.clone(),
        x,
        work,
        stats: RunStats {
            accepted_steps: sol.steps.accepted,
            rejected_steps: sol.steps.rejected,
            function_evals: sol.evals.function,
            seconds,
        },
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use stickslip_core::law::Regularization;
    use stickslip_core::sliding_curve::Curve;

    fn params(links: usize) -> ChainParams {
        ChainParams {
            links,
            ..ChainParams::timing_drive()
        }
    }

    fn tol(rtol: f64) -> Tolerances {
        Tolerances {
            rtol,
            atol: rtol * 1e-3,
            max_steps: 5_000_000,
        }
    }

    #[test]
    fn frictionless_single_link_is_a_driven_oscillator() {
        // The smallest friction a curve accepts: the work stays tiny and the link follows the
        // linear response.
        let law = Regularized::new(
            Curve::constant(stickslip_core::error::MIN_COEFFICIENT).unwrap(),
            1.0,
            Regularization::Linear,
        )
        .unwrap();
        let chain = Chain::new(params(1), ChainLaw::Regularized(law)).unwrap();
        let run = simulate(&chain, Integrator::Explicit, tol(1e-9), 0.01, 1e-4).unwrap();
        assert!(run.final_work().abs() < 1e-6, "{}", run.final_work());
        let max = run.x.iter().map(|x| x[0].abs()).fold(0.0, f64::max);
        assert!(max > 0.0 && max < 10.0 * 2e-4, "{max}");
    }

    #[test]
    fn ep_and_regul_agree_on_a_short_chain() {
        let curve = Curve::constant(0.1).unwrap();
        let regul = Regularized::new(curve.clone(), 1e-3, Regularization::Linear).unwrap();
        let ep = ElastoPlastic::new(1e5, 0.09, 0.1, curve).unwrap();
        let a = simulate(
            &Chain::new(params(5), ChainLaw::Regularized(regul)).unwrap(),
            Integrator::Explicit,
            tol(1e-8),
            0.02,
            1e-4,
        )
        .unwrap();
        let b = simulate(
            &Chain::new(params(5), ChainLaw::ElastoPlastic(ep)).unwrap(),
            Integrator::Explicit,
            tol(1e-8),
            0.02,
            1e-4,
        )
        .unwrap();
        let e = b.error_against(&a);
        assert!(a.final_work() > 0.0);
        assert!(e.work < 0.05, "{e:?}");
    }
}
