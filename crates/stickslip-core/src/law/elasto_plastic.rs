//! The seed's elasto-plastic friction law (Eq. 4–7).
//!
//! ## The law in 1D (seed)
//! F_f = −F_n μ (4a), μ̇ = c ġ (1 − α(μ) μ/μ_ve(|ġ|) sgn ġ) (4b), with the switch α of Eq. 5–7
//! ([`crate::switch::alpha`]).
//!
//! ## Isotropic generalization to the tangent plane
//! With the state a vector μ⃗ and the slip velocity ġ⃗ in the tangent plane:
//!
//! dμ⃗/dt = c ( ġ⃗ − α(|μ⃗|) |ġ⃗| μ⃗ / μ_ve(|ġ⃗|) ).
//!
//! Along a line (ġ⃗ = ġ e⃗, μ⃗ = μ e⃗) this is c ġ − c α |ġ| μ/μ_ve = c ġ (1 − α μ/μ_ve sgn ġ),
//! exactly Eq. 4b. Sticking (α = 0) is an isotropic spring, sliding (α = 1) drives μ⃗ to
//! μ_ve ġ⃗/|ġ⃗|: the friction opposes the slip-velocity direction and only |μ⃗| enters α.
//!
//! ## A state that survives a changing normal force
//! The seed's state is a coefficient, so with F_f = −F_n μ a jump of F_n would rescale the stick
//! force instantly. Popov's vibration mechanism needs the opposite: a tangentially compliant
//! contact whose spring force stays put while the normal load changes and which slips when it
//! exceeds μ F_n(t). So the stored state is the **spring force** s⃗ = F_n μ⃗ (N) with tangential
//! stiffness k_t = c·F_ref, where F_ref is the (mean) normal force the caller passes:
//!
//! - at constant F_n = F_ref, μ⃗ = s⃗/F_n obeys Eq. 4–7 exactly (k_t = c F_n);
//! - when F_n(t) changes, s⃗ does not jump; in μ-space the step uses c_eff = k_t/F_n, and if the
//!   load drops below what the spring carries (|s⃗| > μ_max F_n) the contact slips at once back
//!   onto the friction cone (a return mapping), which is Popov's quasi-static slip (seed 001,
//!   Eq. 21–22). [`crate::popov`] checks the outcome against his theory.
//!
//! ## Integration over a step
//! For a given slip direction and speed the ODE is piecewise linear in μ⃗ along the slip path:
//! the elastic part (α = 0) is integrated exactly, the crossing of μ_ba is found in closed form,
//! and the plastic remainder uses implicit-Euler sub-steps whose scalar equation for |μ⃗| is
//! monotone (solved by Brent's method from the `roots` crate only inside the blend band).
//! Implicit Euler keeps |μ⃗| ≤ max(|μ⃗₀|, μ_ve) for any c·|Δg|, so the update is bounded and
//! stable for any stiffness and step.
//!
//! ## A property worth knowing
//! In steady sliding Eq. 4b settles where α(μ)·μ = μ_ve(|ġ|). That is μ = μ_ve only if
//! μ_ve ≥ μ_max; for a sliding curve below μ_max (a falling Stribeck curve) the state settles
//! inside the blend band [μ_ba, μ_max], so this law never slides with less than μ_ba. Use
//! [`ElastoPlastic::steady_sliding_coefficient`] for the value.

use super::{FrictionLaw, FrictionState, StepInput, StepOutput, unloaded};
use crate::error::{ParamError, positive};
use crate::sliding_curve::{Curve, SlidingCurve};
use crate::switch::{alpha, regime};
use crate::vec2::{Vec2, add, clamp_norm, dot, norm, normalize, scale};
use serde::{Deserialize, Serialize};

/// Most plastic sub-steps per step (the implicit scheme is stable with one; more only refine
/// the stick-slip transient).
const MAX_PLASTIC_SUBSTEPS: usize = 32;

/// The elasto-plastic law with its parameters (validated).
///
/// ```
/// use stickslip_core::law::ElastoPlastic;
/// use stickslip_core::sliding_curve::Curve;
/// use stickslip_core::ParamError;
/// let ok = ElastoPlastic::new(1e5, 0.3, 0.35, Curve::constant(0.35).unwrap()).unwrap();
/// assert!((ok.break_away_displacement() - 3e-6).abs() < 1e-18);
/// // μ_ba above μ_max is rejected, as is μ_max above μ_ve(0+).
/// assert!(matches!(
///     ElastoPlastic::new(1e5, 0.4, 0.35, Curve::constant(0.35).unwrap()),
///     Err(ParamError::BreakAwayAboveMax { .. })
/// ));
/// assert!(matches!(
///     ElastoPlastic::new(1e5, 0.3, 0.5, Curve::constant(0.35).unwrap()),
///     Err(ParamError::MaxAboveSlidingCurve { .. })
/// ));
/// assert!(ElastoPlastic::new(-1.0, 0.3, 0.35, Curve::constant(0.35).unwrap()).is_err());
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct ElastoPlastic<C: SlidingCurve = Curve> {
    c: f64,
    mu_ba: f64,
    mu_max: f64,
    curve: C,
}

/// Serialized form of [`ElastoPlastic`] (validated on deserialization).
#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct ElastoPlasticParams {
    c: f64,
    mu_ba: f64,
    mu_max: f64,
    curve: Curve,
}

impl TryFrom<ElastoPlasticParams> for ElastoPlastic {
    type Error = ParamError;
    fn try_from(p: ElastoPlasticParams) -> Result<Self, ParamError> {
        p.curve.validate()?;
        ElastoPlastic::new(p.c, p.mu_ba, p.mu_max, p.curve)
    }
}

impl From<ElastoPlastic> for ElastoPlasticParams {
    fn from(l: ElastoPlastic) -> Self {
        ElastoPlasticParams {
            c: l.c,
            mu_ba: l.mu_ba,
            mu_max: l.mu_max,
            curve: l.curve,
        }
    }
}

impl Serialize for ElastoPlastic {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        ElastoPlasticParams::from(self.clone()).serialize(s)
    }
}

impl<'de> Deserialize<'de> for ElastoPlastic {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        ElastoPlasticParams::deserialize(d)?
            .try_into()
            .map_err(serde::de::Error::custom)
    }
}

impl<C: SlidingCurve> ElastoPlastic<C> {
    /// Builds the law: stiffness `c` (1/m), thresholds `mu_ba <= mu_max`, sliding curve.
    ///
    /// Errors: non-finite values, `c <= 0`, `mu_ba <= 0`, `mu_ba > mu_max`, and
    /// `mu_max > mu_ve(0+)` (the seed sets μ_ba < μ_max = μ_ve(0+) to avoid a step in the
    /// switching process; `mu_max < mu_ve(0+)` is allowed and continuous).
    pub fn new(c: f64, mu_ba: f64, mu_max: f64, curve: C) -> Result<Self, ParamError> {
        positive("c", c)?;
        positive("mu_ba", mu_ba)?;
        positive("mu_max", mu_max)?;
        if mu_ba > mu_max {
            return Err(ParamError::BreakAwayAboveMax { mu_ba, mu_max });
        }
        let mu_ve0 = curve.at_rest();
        positive("mu_ve(0+)", mu_ve0)?;
        if mu_max > mu_ve0 * (1.0 + 1e-12) {
            return Err(ParamError::MaxAboveSlidingCurve { mu_max, mu_ve0 });
        }
        Ok(ElastoPlastic {
            c,
            mu_ba,
            mu_max,
            curve,
        })
    }

    /// Stiffness c (1/m).
    pub fn c(&self) -> f64 {
        self.c
    }
    /// Break-away coefficient μ_ba.
    pub fn mu_ba(&self) -> f64 {
        self.mu_ba
    }
    /// Upper switch threshold μ_max.
    pub fn mu_max(&self) -> f64 {
        self.mu_max
    }
    /// The sliding curve.
    pub fn curve(&self) -> &C {
        &self.curve
    }
    /// g_ba = μ_ba / c: the largest elastic (sticking) displacement (m).
    pub fn break_away_displacement(&self) -> f64 {
        self.mu_ba / self.c
    }

    /// The right-hand side of Eq. 4b in 1D: dμ/dt for state `mu` and slip velocity `v`.
    #[inline]
    pub fn rate(&self, mu: f64, v: f64) -> f64 {
        if v == 0.0 {
            return 0.0;
        }
        let a = alpha(mu.abs(), self.mu_ba, self.mu_max);
        self.c * v * (1.0 - a * mu / self.curve.mu(v.abs()) * v.signum())
    }

    /// The isotropic vector form: dμ⃗/dt for state `mu` and slip velocity `v`.
    #[inline]
    pub fn rate_vec(&self, mu: Vec2, v: Vec2) -> Vec2 {
        let speed = norm(v);
        if speed == 0.0 {
            return [0.0; 2];
        }
        let a = alpha(norm(mu), self.mu_ba, self.mu_max);
        let k = a * speed / self.curve.mu(speed);
        [self.c * (v[0] - k * mu[0]), self.c * (v[1] - k * mu[1])]
    }

    /// The coefficient this law slides with in steady state at `speed`: the solution of
    /// α(μ)·μ = μ_ve(speed) (equal to μ_ve when μ_ve ≥ μ_max).
    pub fn steady_sliding_coefficient(&self, speed: f64) -> f64 {
        let m = self.curve.mu(speed);
        if m >= self.mu_max {
            return m;
        }
        if self.mu_max == self.mu_ba {
            return self.mu_ba; // step switch: the state sits on the threshold
        }
        let f = |r: f64| alpha(r, self.mu_ba, self.mu_max) * r - m;
        let mut conv = roots::SimpleConvergency {
            eps: 1e-14,
            max_iter: 200,
        };
        roots::find_root_brent(self.mu_ba, self.mu_max, f, &mut conv).unwrap_or(self.mu_max)
    }

    /// Advances the coefficient state `mu` along a straight slip path of length `path`
    /// (m) in direction `e` at sliding level `m` = μ_ve(speed), with stiffness `c` (1/m).
    pub fn advance(&self, mu: Vec2, e: Vec2, path: f64, c: f64, m: f64) -> Vec2 {
        let mut mu = mu;
        let mut rest = path;
        // Elastic part: exact, up to the crossing of |μ| = μ_ba.
        let mag = norm(mu);
        if mag < self.mu_ba {
            let p = dot(mu, e);
            let disc = (p * p - mag * mag + self.mu_ba * self.mu_ba).max(0.0);
            let to_yield = (disc.sqrt() - p) / c;
            if to_yield >= rest {
                return add(mu, scale(e, c * rest));
            }
            mu = clamp_norm(add(mu, scale(e, c * to_yield)), self.mu_ba);
            rest -= to_yield;
        }
        // Plastic part: implicit Euler sub-steps, fine enough to resolve the blend band.
        let band = (self.mu_max - self.mu_ba).max(0.05 * self.mu_max);
        let n = ((c * rest / (0.25 * band)).ceil() as usize).clamp(1, MAX_PLASTIC_SUBSTEPS);
        let hc = c * rest / n as f64;
        for _ in 0..n {
            mu = if self.stays_sliding(mu, e, m) {
                // α = 1 along the whole way: the linear ODE's exact solution.
                add(scale(e, m), scale(add(mu, scale(e, -m)), (-hc / m).exp()))
            } else {
                self.implicit_substep(mu, e, hc, m)
            };
        }
        mu
    }

    /// Whether the straight path from `mu` towards `m·e` (the α = 1 solution) stays outside
    /// the disc |μ| < μ_max, so α = 1 holds all along it.
    fn stays_sliding(&self, mu: Vec2, e: Vec2, m: f64) -> bool {
        if m < self.mu_max || norm(mu) < self.mu_max {
            return false;
        }
        let target = scale(e, m);
        let d = add(mu, scale(target, -1.0));
        let dd = dot(d, d);
        let lambda = if dd > 0.0 {
            (-dot(target, d) / dd).clamp(0.0, 1.0)
        } else {
            0.0
        };
        norm(add(target, scale(d, lambda))) >= self.mu_max
    }

    /// One implicit Euler sub-step μ' = μ + hc (e − α(|μ'|) μ'/m): with q = μ + hc·e the
    /// solution is μ' = q·r/|q| where r(1 + hc·α(r)/m) = |q|, a monotone scalar equation.
    #[inline]
    fn implicit_substep(&self, mu: Vec2, e: Vec2, hc: f64, m: f64) -> Vec2 {
        let q = add(mu, scale(e, hc));
        let qn = norm(q);
        if qn < self.mu_ba {
            return q; // still elastic (α = 0): exact
        }
        let r_slide = qn / (1.0 + hc / m);
        let r = if r_slide >= self.mu_max {
            r_slide // α = 1 throughout
        } else {
            let g = |r: f64| r * (1.0 + hc * alpha(r, self.mu_ba, self.mu_max) / m) - qn;
            let mut conv = roots::SimpleConvergency {
                eps: 1e-12 * self.mu_max,
                max_iter: 100,
            };
            // g(μ_ba) ≤ 0 ≤ g(μ_max) here, so the bracket always holds.
            roots::find_root_brent(self.mu_ba, self.mu_max, g, &mut conv)
                .unwrap_or(self.mu_ba)
                .clamp(self.mu_ba, self.mu_max)
        };
        scale(q, r / qn)
    }
}

impl<C: SlidingCurve> FrictionLaw for ElastoPlastic<C> {
    fn step(&self, state: &mut FrictionState, input: &StepInput) -> StepOutput {
        let f_n = input.normal_force;
        if !(f_n > 0.0 && f_n.is_finite() && input.dt > 0.0) {
            return unloaded(state);
        }
        let f_ref =
            if input.stiffness_normal_force > 0.0 && input.stiffness_normal_force.is_finite() {
                input.stiffness_normal_force
            } else {
                f_n
            };
        let k_t = self.c * f_ref;
        let slip = normalize(input.slip)
            .filter(|_| input.slip.iter().all(|x| x.is_finite()))
            .map(|e| {
                let path = norm(input.slip);
                (e, path, self.curve.mu(path / input.dt))
            });
        // The cone the state can sit on: μ_max, or the sliding curve where it rises above.
        let cone = slip.map_or(self.mu_max, |(_, _, m)| m.max(self.mu_max));
        // Load drop below what the spring carries: instantaneous slip onto the cone.
        let s_before = if state.force.iter().all(|x| x.is_finite()) {
            state.force
        } else {
            [0.0; 2]
        };
        let s0 = clamp_norm(s_before, cone * f_n);
        let released = (dot(s_before, s_before) - dot(s0, s0)) / (2.0 * k_t);
        let mu0 = scale(s0, 1.0 / f_n);

        let mu1 = match slip {
            Some((e, path, m)) => self.advance(mu0, e, path, k_t / f_n, m),
            None => mu0,
        };
        let s1 = scale(mu1, f_n);
        state.force = s1;

        // Trapezoidal work is exact on the elastic branch, so pure sticking dissipates 0.
        let work = dot(scale(add(s0, s1), 0.5), input.slip);
        let stored = (dot(s1, s1) - dot(s0, s0)) / (2.0 * k_t);
        let mag = norm(mu1);
        StepOutput {
            mu: mu1,
            force: scale(s1, -1.0),
            regime: regime(mag, self.mu_ba, self.mu_max),
            limit: mag.max(self.mu_ba),
            dissipated: work - stored + released,
        }
    }

    fn sliding_coefficient(&self, speed: f64) -> f64 {
        self.steady_sliding_coefficient(speed)
    }

    fn static_coefficient(&self) -> f64 {
        self.mu_ba
    }

    fn name(&self) -> &'static str {
        "ep"
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::law::Regime;

    fn law() -> ElastoPlastic {
        ElastoPlastic::new(1e4, 0.3, 0.4, Curve::constant(0.4).unwrap()).unwrap()
    }

    #[test]
    fn elastic_branch_is_a_spring() {
        let l = law();
        let mut s = FrictionState::default();
        let out = l.step(&mut s, &StepInput::new([0.0, 2e-5], 1e-3, 50.0));
        assert_eq!(out.regime, Regime::Sticking);
        assert!((out.mu[1] - 0.2).abs() < 1e-12);
        assert!(out.dissipated.abs() < 1e-12);
    }

    #[test]
    fn sliding_reaches_mu_ve_with_sign_of_motion() {
        let l = law();
        let mut s = FrictionState::default();
        for _ in 0..100 {
            l.step(&mut s, &StepInput::new([-1e-3, 0.0], 1e-3, 10.0));
        }
        assert!((s.force[0] + 4.0).abs() < 1e-9, "{:?}", s.force);
    }

    #[test]
    fn falling_curve_settles_inside_the_band() {
        let curve = Curve::stribeck(
            0.4,
            0.2,
            1e-3,
            crate::sliding_curve::StribeckDecay::Gaussian,
            0.0,
        )
        .unwrap();
        let l = ElastoPlastic::new(1e4, 0.3, 0.4, curve).unwrap();
        let mut s = FrictionState::default();
        let mut out = None;
        for _ in 0..2000 {
            out = Some(l.step(&mut s, &StepInput::new([1e-5, 0.0], 1e-3, 1.0)));
        }
        let mu = out.unwrap().mu[0];
        let expect = l.steady_sliding_coefficient(1e-2);
        assert!((alpha(expect, 0.3, 0.4) * expect - 0.2).abs() < 1e-9);
        assert!((mu - expect).abs() < 1e-6, "{mu} vs {expect}");
    }
}
