//! Integrating the block with adaptive methods.

use super::{Block, ForceProfile};
use crate::integrate::solve_with;
use differential_equations::prelude::*;
use differential_equations::stats::{Evals, Steps};
use serde::Serialize;
use std::time::Instant;
use stickslip_core::ParamError;
use stickslip_core::error::in_range;
use stickslip_core::law::{ElastoPlastic, Law, Regularized};
use stickslip_core::sliding_curve::{Curve, SlidingCurve};
use thiserror::Error;

/// The adaptive method.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Integrator {
    /// Runge–Kutta–Fehlberg 4(5), explicit, adaptive: the workhorse explicit method here.
    Explicit,
    /// Dormand–Prince 5(4), explicit (the ode45 analogue). Its implementation in
    /// `differential-equations` aborts with a stiffness error when the step size is limited by
    /// stability for long (an EP contact sticking with large c, Regul with small ġ_t0): that
    /// abort is reported as [`SimError::Solver`] and is itself the seed's point about explicit
    /// methods and stiff friction.
    DormandPrince,
    /// ESDIRK 3(2) L-stable, implicit, finite-difference Jacobian (stiff, like ode23s).
    Implicit,
}

/// Error tolerances of the adaptive step control.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Tolerances {
    /// Relative tolerance.
    pub rtol: f64,
    /// Absolute tolerance.
    pub atol: f64,
    /// Step budget per integrated arc (and the budget of arcs).
    pub max_steps: usize,
}

impl Tolerances {
    /// Checks the values: `rtol` in [1e-14, 0.1] (tighter than f64 can resolve, or so loose
    /// that the result means nothing, is refused), `atol` in [1e-20, 0.1], `max_steps` in
    /// [1, 1e8].
    pub fn validate(&self) -> Result<(), ParamError> {
        in_range("rtol", self.rtol, 1e-14, 0.1)?;
        in_range("atol", self.atol, 1e-20, 0.1)?;
        in_range("max_steps", self.max_steps as f64, 1.0, 1e8)?;
        Ok(())
    }
}

/// The longest simulated time a block run accepts (s): its output is sampled every
/// millisecond, so this bounds a run's memory to about 32 MB.
pub const MAX_DURATION: f64 = 1000.0;

impl Default for Tolerances {
    fn default() -> Self {
        Tolerances {
            rtol: 1e-8,
            atol: 1e-10,
            max_steps: 2_000_000,
        }
    }
}

/// Why a simulation failed.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum SimError {
    /// The ODE solver gave up (step budget, step size underflow, ...).
    #[error("the ODE solver failed: {0}")]
    Solver(String),
    /// The tolerances are out of range.
    #[error("{0}")]
    Param(#[from] ParamError),
    /// The run is longer than [`MAX_DURATION`].
    #[error("the run lasts {duration} s, more than the {MAX_DURATION} s a block run accepts")]
    TooLong {
        /// The requested simulated time (s).
        duration: f64,
    },
}

/// Cost of a run.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize)]
pub struct RunStats {
    /// Accepted steps.
    pub accepted_steps: usize,
    /// Rejected steps.
    pub rejected_steps: usize,
    /// Right-hand-side evaluations.
    pub function_evals: usize,
    /// Wall-clock integration time (s).
    pub seconds: f64,
}

/// Displacement and velocity at the end of a phase.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PhaseSummary {
    /// Phase end time (s).
    pub t: f64,
    /// Displacement g_t (m).
    pub x: f64,
    /// Velocity ġ_t (m/s).
    pub v: f64,
}

/// A finished run.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BlockRun {
    /// Law name.
    pub law: &'static str,
    /// Output times (s), uniform grid plus events.
    pub t: Vec<f64>,
    /// Displacement (m).
    pub x: Vec<f64>,
    /// Velocity (m/s).
    pub v: Vec<f64>,
    /// Friction coefficient acting (μ state for EP, μ(ġ) for Regul, sliding value or 0 for
    /// Phys/Coulomb).
    pub mu: Vec<f64>,
    /// Phase-end summaries at the requested times.
    pub phases: Vec<PhaseSummary>,
    /// Total time the block sticks (|ġ| below `stick_speed`) (s).
    pub stick_time: f64,
    /// Total time it slips (s).
    pub slip_time: f64,
    /// Integrator cost.
    pub stats: RunStats,
}

impl BlockRun {
    /// Final displacement (m).
    pub fn final_displacement(&self) -> f64 {
        *self.x.last().unwrap_or(&0.0)
    }

    /// Largest |x| over `t ∈ [t0, t1]` (m).
    pub fn max_displacement_between(&self, t0: f64, t1: f64) -> f64 {
        self.t
            .iter()
            .zip(&self.x)
            .filter(|(t, _)| **t >= t0 && **t <= t1)
            .map(|(_, x)| x.abs())
            .fold(0.0, f64::max)
    }

    fn sample(&self, t: f64) -> (f64, f64) {
        let i = self.t.partition_point(|&s| s < t).min(self.t.len() - 1);
        if i == 0 || self.t[i] == t {
            return (self.x[i], self.v[i]);
        }
        let w = (t - self.t[i - 1]) / (self.t[i] - self.t[i - 1]);
        (
            self.x[i - 1] + w * (self.x[i] - self.x[i - 1]),
            self.v[i - 1] + w * (self.v[i] - self.v[i - 1]),
        )
    }
}

/// Speed below which a block counts as sticking in the summaries (m/s).
pub const STICK_SPEED: f64 = 1e-4;
/// Output grid spacing (s).
const OUTPUT_DT: f64 = 1e-3;

/// Simulates `block` under `profile` from rest until the profile's end, reporting (x, v) at
/// each of `phase_ends`.
pub fn simulate(
    block: &Block,
    profile: &ForceProfile,
    integrator: Integrator,
    tol: Tolerances,
    phase_ends: &[f64],
) -> Result<BlockRun, SimError> {
    check_run(profile.end(), tol)?;
    let started = Instant::now();
    let mut run = match block.law() {
        Law::ElastoPlastic(l) => elasto_plastic(block, profile, integrator, tol, l)?,
        Law::Regularized(l) => smooth(block, profile, integrator, tol, Smooth::Regul(l))?,
        Law::Physical(l) => switched(block, profile, integrator, tol, l.mu_ba(), l.curve())?,
        Law::Coulomb(l) => {
            let curve = Curve::constant(l.mu()).expect("validated coefficient");
            switched(block, profile, integrator, tol, l.mu(), &curve)?
        }
    };
    run.law = block.law().as_dyn().name();
    run.stats.seconds = started.elapsed().as_secs_f64();
    run.phases = phase_ends
        .iter()
        .map(|&t| {
            let (x, v) = run.sample(t);
            PhaseSummary { t, x, v }
        })
        .collect();
    let (mut stick, mut slip) = (0.0, 0.0);
    for i in 1..run.t.len() {
        let dt = run.t[i] - run.t[i - 1];
        if run.v[i].abs() < STICK_SPEED && run.v[i - 1].abs() < STICK_SPEED {
            stick += dt;
        } else {
            slip += dt;
        }
    }
    run.stick_time = stick;
    run.slip_time = slip;
    Ok(run)
}

/// Refuses runs whose output or arcs could not be bounded.
fn check_run(duration: f64, tol: Tolerances) -> Result<(), SimError> {
    tol.validate()?;
    if !(duration <= MAX_DURATION) {
        return Err(SimError::TooLong { duration });
    }
    Ok(())
}

enum Smooth<'a> {
    Regul(&'a Regularized),
}

/// Regul: m ẍ = F(t) − F_n μ(ġ).
struct SmoothOde<'a> {
    mass: f64,
    f_n: f64,
    profile: &'a ForceProfile,
    law: &'a Smooth<'a>,
}

impl SmoothOde<'_> {
    fn mu(&self, y: &[f64; 3]) -> f64 {
        match self.law {
            Smooth::Regul(l) => l.coefficient(y[1]),
        }
    }
}

impl ODE<f64, [f64; 3]> for SmoothOde<'_> {
    fn diff(&self, t: f64, y: &[f64; 3], dydt: &mut [f64; 3]) {
        dydt[0] = y[1];
        dydt[1] = (self.profile.value(t) - self.f_n * self.mu(y)) / self.mass;
        dydt[2] = 0.0;
    }
}

fn empty_run() -> BlockRun {
    BlockRun {
        law: "",
        t: Vec::new(),
        x: Vec::new(),
        v: Vec::new(),
        mu: Vec::new(),
        phases: Vec::new(),
        stick_time: 0.0,
        slip_time: 0.0,
        stats: RunStats::default(),
    }
}

fn add_stats(run: &mut BlockRun, steps: &Steps, evals: &Evals) {
    run.stats.accepted_steps += steps.accepted;
    run.stats.rejected_steps += steps.rejected;
    run.stats.function_evals += evals.function;
}

fn smooth(
    block: &Block,
    profile: &ForceProfile,
    integrator: Integrator,
    tol: Tolerances,
    law: Smooth<'_>,
) -> Result<BlockRun, SimError> {
    let ode = SmoothOde {
        mass: block.mass(),
        f_n: block.normal_force(),
        profile,
        law: &law,
    };
    let sol = solve_with!(
        integrator,
        tol,
        IVP::ode(&ode, 0.0, profile.end(), [0.0; 3]).even(OUTPUT_DT)
    )?;
    let mut run = empty_run();
    add_stats(&mut run, &sol.steps, &sol.evals);
    for (t, y) in sol.t.iter().zip(&sol.y) {
        run.t.push(*t);
        run.x.push(y[0]);
        run.v.push(y[1]);
        run.mu.push(ode.mu(y));
    }
    Ok(run)
}

/// EP: m ẍ = F(t, x) − F_n μ with the law's state (μ, σ) (Eq. 4b, latched switch) driven by
/// the slip ġ = ẋ − v_s against a surface moving at v_s; y = [x, v, μ, σ]. The reset σ = 0 when
/// the slip turns against the state is the event that ends an arc.
struct EpOde<'a> {
    mass: f64,
    f_n: f64,
    external: &'a dyn Fn(f64, f64) -> f64,
    surface: f64,
    law: &'a ElastoPlastic,
}

impl ODE<f64, [f64; 4]> for EpOde<'_> {
    fn diff(&self, t: f64, y: &[f64; 4], dydt: &mut [f64; 4]) {
        dydt[0] = y[1];
        dydt[1] = ((self.external)(t, y[0]) - self.f_n * y[2]) / self.mass;
        let (dmu, dsigma) = self.law.rates(y[2], y[3], y[1] - self.surface);
        dydt[2] = dmu;
        dydt[3] = dsigma;
    }
}

impl Event<f64, [f64; 4]> for EpOde<'_> {
    fn config(&self) -> EventConfig {
        EventConfig::new(CrossingDirection::Negative, Some(1))
    }
    fn event(&self, _t: f64, y: &[f64; 4]) -> f64 {
        // Only a latched contact has something to reset.
        if y[3] > 0.0 {
            y[2] * (y[1] - self.surface)
        } else {
            1.0
        }
    }
}

/// Integrates `ode` from `y0` at t = 0 to `end` arc by arc (an arc ends at a reset event).
fn ep_arcs(
    ode: &EpOde<'_>,
    y0: [f64; 4],
    end: f64,
    integrator: Integrator,
    tol: Tolerances,
) -> Result<BlockRun, SimError> {
    let mut run = empty_run();
    let (mut t, mut y) = (0.0, y0);
    let mut arcs = 0usize;
    // A reset leaves σ = 0, so the next arc cannot end at once on the same event.
    while t < end {
        arcs += 1;
        if arcs > tol.max_steps {
            return Err(SimError::Solver(format!(
                "more than {} arcs",
                tol.max_steps
            )));
        }
        let sol = solve_with!(
            integrator,
            tol,
            IVP::ode(ode, t, end, y).even(OUTPUT_DT).event(ode)
        )?;
        add_stats(&mut run, &sol.steps, &sol.evals);
        let skip = usize::from(!run.t.is_empty());
        for (ti, yi) in sol.t.iter().zip(&sol.y).skip(skip) {
            run.t.push(*ti);
            run.x.push(yi[0]);
            run.v.push(yi[1]);
            run.mu.push(yi[2]);
        }
        let t_last = *sol.t.last().unwrap_or(&end);
        y = *sol.y.last().unwrap_or(&y);
        y[3] = 0.0;
        // Guard against a zero-length arc looping forever.
        t = if t_last > t { t_last } else { t + 1e-9 };
    }
    Ok(run)
}

fn elasto_plastic(
    block: &Block,
    profile: &ForceProfile,
    integrator: Integrator,
    tol: Tolerances,
    law: &ElastoPlastic,
) -> Result<BlockRun, SimError> {
    let external = |t: f64, _x: f64| profile.value(t);
    let ode = EpOde {
        mass: block.mass(),
        f_n: block.normal_force(),
        external: &external,
        surface: 0.0,
        law,
    };
    ep_arcs(&ode, [0.0; 4], profile.end(), integrator, tol)
}

/// A block of mass m held by a spring of stiffness k to a fixed wall, lying on a belt that
/// moves at v_b: m ẍ = −k x − F_n μ with slip ġ = ẋ − v_b. The classic stick-slip oscillator.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BeltSpring {
    /// Mass (kg).
    pub mass: f64,
    /// Gravity (m/s²): F_n = m g.
    pub gravity: f64,
    /// Spring stiffness k (N/m).
    pub stiffness: f64,
    /// Belt velocity v_b (m/s).
    pub belt_velocity: f64,
}

impl BeltSpring {
    /// Integrates the oscillator with the elasto-plastic law `law` from x = 0, riding the belt,
    /// to `t_end`.
    pub fn simulate(
        &self,
        law: &ElastoPlastic,
        t_end: f64,
        integrator: Integrator,
        tol: Tolerances,
    ) -> Result<BlockRun, SimError> {
        check_run(t_end, tol)?;
        let k = self.stiffness;
        let spring = |_t: f64, x: f64| -k * x;
        let ode = EpOde {
            mass: self.mass,
            f_n: self.mass * self.gravity,
            external: &spring,
            surface: self.belt_velocity,
            law,
        };
        let mut run = ep_arcs(
            &ode,
            [0.0, self.belt_velocity, 0.0, 0.0],
            t_end,
            integrator,
            tol,
        )?;
        run.law = "ep";
        Ok(run)
    }

    /// The stick-slip period with static coefficient `mu_s` and constant kinetic coefficient
    /// `mu_k` < `mu_s` (Coulomb): sticking from x_k − Δ to x_k + Δ at belt speed, then a
    /// harmonic slip arc back, T = 2Δ/v_b + (π + 2 atan(v_b/(ωΔ)))/ω with ω = √(k/m),
    /// Δ = (μ_s − μ_k) m g/k.
    pub fn period(&self, mu_s: f64, mu_k: f64) -> f64 {
        let omega = (self.stiffness / self.mass).sqrt();
        let delta = (mu_s - mu_k) * self.mass * self.gravity / self.stiffness;
        let v_b = self.belt_velocity;
        2.0 * delta / v_b + (std::f64::consts::PI + 2.0 * (v_b / (omega * delta)).atan()) / omega
    }
}

/// A sliding arc of the switched model: m ẍ = F(t) − F_n μ_ve(|ẋ|) sgn ẋ, stopping when the
/// velocity returns to zero (the event).
struct SlidingArc<'a> {
    mass: f64,
    f_n: f64,
    profile: &'a ForceProfile,
    curve: &'a Curve,
    direction: f64,
}

impl ODE<f64, [f64; 2]> for SlidingArc<'_> {
    fn diff(&self, t: f64, y: &[f64; 2], dydt: &mut [f64; 2]) {
        // The arc starts at rest in `direction`; sgn ġ is that direction throughout the arc.
        let friction = self.f_n * self.curve.mu(y[1].abs()) * self.direction;
        dydt[0] = y[1];
        dydt[1] = (self.profile.value(t) - friction) / self.mass;
    }
}

impl Event<f64, [f64; 2]> for SlidingArc<'_> {
    fn config(&self) -> EventConfig {
        EventConfig::new(CrossingDirection::Negative, Some(1))
    }
    fn event(&self, _t: f64, y: &[f64; 2]) -> f64 {
        y[1] * self.direction
    }
}

/// Phys (Eq. 1–3) as an exact switched system. A block at rest breaks away once |F| reaches
/// F_n·max(μ_ba, μ_ve(0+)): between the two values Eq. 3 would start a slip that the sliding
/// curve stops at once, so sticking is the only consistent (Filippov) motion there.
fn switched(
    block: &Block,
    profile: &ForceProfile,
    integrator: Integrator,
    tol: Tolerances,
    mu_ba: f64,
    curve: &Curve,
) -> Result<BlockRun, SimError> {
    let f_n = block.normal_force();
    let release = f_n * mu_ba.max(curve.at_rest());
    let end = profile.end();
    let mut run = empty_run();
    let (mut t, mut x) = (0.0, 0.0);
    let mut arcs = 0usize;
    let push_rest = |run: &mut BlockRun, from: f64, to: f64, x: f64| {
        // Sticking arc: sample the grid so the output stays uniform.
        let mut s = from;
        while s < to {
            run.t.push(s);
            run.x.push(x);
            run.v.push(0.0);
            run.mu.push(0.0);
            s += OUTPUT_DT;
        }
    };
    while t < end {
        arcs += 1;
        if arcs > tol.max_steps {
            return Err(SimError::Solver(format!(
                "more than {} arcs",
                tol.max_steps
            )));
        }
        let Some(start) = profile.first_reaching(t, end, release) else {
            push_rest(&mut run, t, end, x);
            run.t.push(end);
            run.x.push(x);
            run.v.push(0.0);
            run.mu.push(0.0);
            break;
        };
        push_rest(&mut run, t, start, x);
        let direction = profile.value(start).signum();
        let arc = SlidingArc {
            mass: block.mass(),
            f_n,
            profile,
            curve,
            direction,
        };
        // A tiny initial speed keeps the event function off zero at the arc start.
        let y0 = [x, direction * 1e-12];
        let sol = solve_with!(
            integrator,
            tol,
            IVP::ode(&arc, start, end, y0).even(OUTPUT_DT).event(&arc)
        )?;
        add_stats(&mut run, &sol.steps, &sol.evals);
        // The even-grid output of the step that crossed the event can run past it; the arc
        // ends at the event (the last point).
        let t_stop = *sol.t.last().unwrap_or(&end);
        for (ti, y) in sol.t.iter().zip(&sol.y) {
            if *ti > t_stop {
                continue;
            }
            run.t.push(*ti);
            run.x.push(y[0]);
            run.v.push(y[1]);
            run.mu.push(curve.mu(y[1].abs()) * direction);
        }
        let last = *sol.y.last().unwrap_or(&y0);
        t = *sol.t.last().unwrap_or(&end);
        x = last[0];
        if t < end {
            // Stopped: stick from here on (the velocity is zero at the event).
            if let Some(v) = run.v.last_mut() {
                *v = 0.0;
            }
            // Guard against a zero-length arc looping forever.
            t += 1e-9;
        }
    }
    Ok(run)
}
