//! Time-stepped reference simulator of the seed's displacement-controlled, quasi-static spring
//! contact (Section 3.2): one spring with lateral stiffness k_x and normal stiffness k_z, mean
//! indentation ū_z, Amontons friction μ0, the substrate sliding at v0 under it.
//!
//! Oscillations (displacements): normal u_z = ū_z + A_z w(ft) so F_z = k_z (u_z)⁺; tangential,
//! the spring base moving by A_x w(ft) along v0 (relative velocity v0 + A_x f w′); transverse,
//! the base moving by A_y w(ft) across v0. The in-plane spring is isotropic (k_x both ways).
//!
//! Each step is a predictor (stick: the in-plane force grows by k_x times the base's motion
//! relative to the substrate) and a corrector (slip: the force is projected back onto the disc
//! of radius μ0 F_z). It uses none of the closed forms, so it checks them.

use stickslip_core::error::{ParamError, finite, non_negative, positive};
use stickslip_core::popov::CompliantContact;
use stickslip_core::popov::{Excitation, Oscillation};

/// Change of the in-plane force over one period, relative to μ0 k_z ū_z, below which the
/// motion counts as periodic.
const PERIODIC_TOL: f64 = 1e-12;

/// A validated spring contact and its excitation.
#[derive(Clone, Debug)]
pub struct SpringModel {
    k_x: f64,
    k_z: f64,
    mu0: f64,
    mean_indentation: f64,
    v0: f64,
    frequency: f64,
    excitation: Excitation,
}

/// Time-stepping controls.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SimulationOptions {
    steps_per_period: usize,
    min_warmup_periods: usize,
    max_warmup_periods: usize,
    average_periods: usize,
}

impl SimulationOptions {
    /// Steps per oscillation period; warm-up runs at least `min_warmup_periods` and then until
    /// one period repeats the previous (at most `max_warmup_periods`); averages over
    /// `average_periods`. All must be ≥ 1 except `min_warmup_periods`, and
    /// `max_warmup_periods ≥ min_warmup_periods`.
    pub fn new(
        steps_per_period: usize,
        min_warmup_periods: usize,
        max_warmup_periods: usize,
        average_periods: usize,
    ) -> Result<Self, ParamError> {
        positive("steps per period", steps_per_period as f64)?;
        positive("average periods", average_periods as f64)?;
        if max_warmup_periods < min_warmup_periods.max(1) {
            return Err(ParamError::OutOfRange {
                name: "max warm-up periods",
                value: max_warmup_periods as f64,
                min: min_warmup_periods.max(1) as f64,
                max: f64::INFINITY,
            });
        }
        Ok(Self {
            steps_per_period,
            min_warmup_periods,
            max_warmup_periods,
            average_periods,
        })
    }
}

impl Default for SimulationOptions {
    /// 8192 steps per period, 2 to 200 warm-up periods, 2 averaged periods.
    fn default() -> Self {
        Self {
            steps_per_period: 8192,
            min_warmup_periods: 2,
            max_warmup_periods: 200,
            average_periods: 2,
        }
    }
}

/// Period averages of the steady state.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpringModelOutcome {
    /// μ̄ = ⟨F_x⟩/⟨F_z⟩ (Eq. 10).
    pub mu_eff: f64,
    /// ⟨F_x⟩, along the sliding direction.
    pub mean_fx: f64,
    /// ⟨F_y⟩, across it.
    pub mean_fy: f64,
    /// ⟨F_z⟩.
    pub mean_fz: f64,
    /// Fraction of averaged steps in stick.
    pub stick_fraction: f64,
    /// Warm-up periods run.
    pub warmup_periods: usize,
    /// Whether the warm-up ended because the motion became periodic (not at the cap).
    pub periodic: bool,
}

impl SpringModel {
    /// Validates stiffnesses, μ0, ū_z and f (> 0) and v0 (≥ 0); oscillation amplitudes in
    /// `excitation` are displacements.
    pub fn new(
        k_x: f64,
        k_z: f64,
        mu0: f64,
        mean_indentation: f64,
        v0: f64,
        frequency: f64,
        excitation: Excitation,
    ) -> Result<Self, ParamError> {
        Ok(Self {
            k_x: positive("k_x", k_x)?,
            k_z: positive("k_z", k_z)?,
            mu0: positive("mu0", mu0)?,
            mean_indentation: positive("mean indentation", mean_indentation)?,
            v0: non_negative("v0", v0)?,
            frequency: positive("frequency", frequency)?,
            excitation,
        })
    }

    /// The same simulator for a [`CompliantContact`] dragged at a *signed* speed `v0` along x
    /// (negative: towards −x; the warm-up then starts in backward slip), to check the theory
    /// of [`compliant`](super::compliant) under superimposed `excitation` (displacements).
    pub fn compliant(
        contact: &CompliantContact,
        v0: f64,
        frequency: f64,
        excitation: Excitation,
    ) -> Result<Self, ParamError> {
        Ok(Self {
            k_x: contact.k_x(),
            k_z: contact.k_z(),
            mu0: contact.mu0(),
            mean_indentation: contact.mean_indentation(),
            v0: finite("v0", v0)?,
            frequency: positive("frequency", frequency)?,
            excitation,
        })
    }

    /// α = A_z/ū_z (Eq. 16); 0 without normal oscillation.
    pub fn alpha(&self) -> f64 {
        self.excitation
            .normal
            .as_ref()
            .map_or(0.0, |o| o.amplitude() / self.mean_indentation)
    }

    /// β = k_x v0/(μ0 k_z A_z f) (Eq. 17), signed like v0; `None` without a nonzero normal
    /// amplitude.
    pub fn beta(&self) -> Option<f64> {
        let a_z = self.excitation.normal.as_ref()?.amplitude();
        (a_z > 0.0).then(|| self.k_x * self.v0 / (self.mu0 * self.k_z * a_z * self.frequency))
    }

    fn normal_force(&self, phase: f64) -> f64 {
        let u_z = self.mean_indentation + at(self.excitation.normal.as_ref(), phase);
        self.k_z * u_z.max(0.0)
    }

    /// Runs to the periodic steady state and averages over whole periods.
    ///
    /// Starts in slip along the drag (F_x = ±μ0 F_z, forward at v0 = 0): under normal
    /// oscillation the motion is then exact once the normal force has passed its minimum, i.e.
    /// after one period.
    pub fn simulate(&self, options: &SimulationOptions) -> SpringModelOutcome {
        let n = options.steps_per_period;
        let mut state = State {
            fx: self.mu0 * self.normal_force(0.0) * if self.v0 < 0.0 { -1.0 } else { 1.0 },
            fy: 0.0,
        };
        let scale = self.mu0 * self.k_z * self.mean_indentation;
        let mut warmup = 0;
        let mut periodic = false;
        while warmup < options.max_warmup_periods {
            let before = state;
            for i in 0..n {
                self.step(&mut state, i, n);
            }
            warmup += 1;
            let change = (state.fx - before.fx).hypot(state.fy - before.fy);
            if warmup >= options.min_warmup_periods && change <= PERIODIC_TOL * scale {
                periodic = true;
                break;
            }
        }
        let (mut sx, mut sy, mut sz, mut stuck) = (0.0, 0.0, 0.0, 0usize);
        for _ in 0..options.average_periods {
            for i in 0..n {
                let (fz, slipped) = self.step(&mut state, i, n);
                sx += state.fx;
                sy += state.fy;
                sz += fz;
                stuck += usize::from(!slipped);
            }
        }
        let total = (n * options.average_periods) as f64;
        SpringModelOutcome {
            mu_eff: sx / sz,
            mean_fx: sx / total,
            mean_fy: sy / total,
            mean_fz: sz / total,
            stick_fraction: stuck as f64 / total,
            warmup_periods: warmup,
            periodic,
        }
    }

    /// Advances from step `i` to `i + 1` of a period of `n` steps; returns (F_z, slipped).
    fn step(&self, s: &mut State, i: usize, n: usize) -> (f64, bool) {
        // Phases from the step index, so they repeat exactly every period.
        let (p0, p1) = (i as f64 / n as f64, ((i + 1) % n) as f64 / n as f64);
        let dt = 1.0 / (self.frequency * n as f64);
        let delta = |o: Option<&Oscillation>| at(o, p1) - at(o, p0);
        s.fx += self.k_x * (self.v0 * dt + delta(self.excitation.tangential.as_ref()));
        s.fy += self.k_x * delta(self.excitation.transverse.as_ref());
        let fz = self.normal_force(p1);
        let limit = self.mu0 * fz;
        let norm = s.fx.hypot(s.fy);
        let slipped = norm > limit;
        if slipped {
            let shrink = limit / norm;
            s.fx *= shrink;
            s.fy *= shrink;
        }
        (fz, slipped)
    }
}

fn at(osc: Option<&Oscillation>, phase: f64) -> f64 {
    osc.map_or(0.0, |o| o.at(phase))
}

/// In-plane spring force.
#[derive(Clone, Copy)]
struct State {
    fx: f64,
    fy: f64,
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::popov::static_friction::{mu_s_tangential, mu_s_transverse};
    use stickslip_core::waveform::Waveform;

    fn model(v0: f64, excitation: Excitation) -> SpringModel {
        SpringModel::new(1.0, 1.0, 0.5, 1.0, v0, 1.0, excitation).unwrap()
    }

    fn sine(a: f64) -> Oscillation {
        Oscillation::new(a, Waveform::Sine, 0.0).unwrap()
    }

    #[test]
    fn rejects_bad_parameters() {
        assert!(SpringModel::new(0.0, 1.0, 0.5, 1.0, 1.0, 1.0, Excitation::default()).is_err());
        assert!(SpringModel::new(1.0, 1.0, 0.5, 1.0, -1.0, 1.0, Excitation::default()).is_err());
        assert!(SimulationOptions::new(0, 1, 2, 1).is_err());
        assert!(SimulationOptions::new(10, 5, 2, 1).is_err());
    }

    #[test]
    fn without_oscillation_it_slides_at_mu0() {
        let out = model(1.0, Excitation::default()).simulate(&SimulationOptions::default());
        assert!((out.mu_eff - 0.5).abs() < 1e-12 && out.periodic);
    }

    #[test]
    fn fast_sliding_under_tangential_oscillation_returns_to_mu0() {
        // Eq. 12 holds for tangential oscillation once v0 exceeds the base's velocity amplitude.
        let a = 0.1;
        let v0 = 1.01 * std::f64::consts::TAU * a;
        let out =
            model(v0, Excitation::tangential(sine(a))).simulate(&SimulationOptions::default());
        assert!((out.mu_eff - 0.5).abs() < 1e-9, "{out:?}");
    }

    #[test]
    fn creeping_under_tangential_oscillation_approaches_eq_6() {
        // As v0 → 0 the mean force settles at the largest force that sticks: Eq. 6 with
        // A_x/F_z = k_x A_x/(k_z ū_z).
        let a = 0.2;
        let out =
            model(1e-4, Excitation::tangential(sine(a))).simulate(&SimulationOptions::default());
        let eq6 = mu_s_tangential(0.5, a).unwrap();
        assert!((out.mu_eff - eq6).abs() < 2e-3, "{out:?} vs {eq6}");
    }

    #[test]
    fn transverse_oscillation_lowers_friction_from_mu0_towards_eq_8() {
        // Creeping: μ̄ → Eq. 8 (A_y/F_z = k_x A_y/(k_z ū_z)); fast: continuous sliding, yet
        // μ̄ < μ0 since part of the friction vector points across v0 (seed Section 4).
        let a = 0.3;
        let opts = SimulationOptions::default();
        let slow = model(1e-3, Excitation::transverse(sine(a))).simulate(&opts);
        let fast = model(10.0, Excitation::transverse(sine(a))).simulate(&opts);
        let eq8 = mu_s_transverse(0.5, a).unwrap();
        assert!((slow.mu_eff - eq8).abs() < 2e-3, "{slow:?} vs {eq8}");
        assert!(
            fast.stick_fraction == 0.0 && fast.mu_eff < 0.5 && fast.mu_eff > 0.49,
            "{fast:?}"
        );
    }
}
