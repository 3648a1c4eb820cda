//! Friction laws behind one interface.
//!
//! A physics engine calls [`FrictionLaw::step`] once per time step and contact with the slip
//! that happened over the step and the normal force, and gets back the friction force, the
//! regime, the energy dissipated, and the friction *limit* a rigid-constraint solver (such as
//! rapier's) should enforce next. All laws share one small state type, [`FrictionState`], so a
//! contact can switch law without reallocating and an engine stores one layout.
//!
//! - [`ElastoPlastic`]: the seed's stateful law (Eq. 4–7), generalized isotropically to the
//!   tangent plane.
//! - [`Physical`]: the exact switched model "Phys" (Eq. 1–3).
//! - [`Regularized`]: "Regul", the sliding curve regularized below a velocity ġ_t0 (Fig. 1E).
//! - [`Coulomb`]: plain Coulomb friction, what rapier does without stickslip.
//!
//! Sign convention: slip `ġ` is the velocity of the body the friction acts on relative to its
//! counterpart; the state μ⃗ points along the slip it resists and the friction force is
//! F_f = −F_n μ⃗ (seed Eq. 4a).

mod combine;
mod coulomb;
mod elasto_plastic;
mod physical;
mod regularized;

pub use crate::combine_rule::CombineRule;
pub use coulomb::Coulomb;
pub use elasto_plastic::{ElastoPlastic, EpParams, EpVariant};
pub use physical::Physical;
pub use regularized::{Regularization, Regularized};

use crate::sliding_curve::SlidingCurve;
pub use crate::switch::Regime;
use crate::vec2::Vec2;
use serde::{Deserialize, Serialize};

/// The per-contact state every law uses: 24 bytes.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
pub struct FrictionState {
    /// Tangential force carried by the contact, s⃗ = F_n μ⃗ (N), pointing along the slip it
    /// resists. The elasto-plastic law keeps its elastic spring force here; memoryless laws
    /// keep the last force they applied (for read-back only).
    pub force: Vec2,
    /// Break-away progress σ ∈ [0, 1] of the elasto-plastic law (0: not broken away, 1:
    /// sliding on the sliding curve; see [`ElastoPlastic`]). Other laws leave it 0.
    #[serde(default)]
    pub slide: f64,
}

impl FrictionState {
    /// A state carrying spring force `force` that has not broken away.
    pub fn with_force(force: Vec2) -> Self {
        FrictionState { force, slide: 0.0 }
    }
}

/// What happened at a contact over one step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StepInput {
    /// Slip increment Δg⃗ over the step (m), in the tangent plane.
    pub slip: Vec2,
    /// Step length (s), > 0.
    pub dt: f64,
    /// Normal force during the step (N); may be modulated by vibration. ≤ 0 means no contact.
    pub normal_force: f64,
    /// Normal force that sets the tangential stiffness k_t = c·F_ref of a compliant law (N).
    /// Pass the unmodulated (mean) normal force; ≤ 0 means "use `normal_force`".
    pub stiffness_normal_force: f64,
}

impl StepInput {
    /// A step with a constant normal force (the seed's setting).
    pub fn new(slip: Vec2, dt: f64, normal_force: f64) -> Self {
        StepInput {
            slip,
            dt,
            normal_force,
            stiffness_normal_force: normal_force,
        }
    }

    /// Slip speed |Δg⃗|/dt (m/s); 0 for a non-positive or non-finite `dt`.
    pub fn speed(&self) -> f64 {
        let v = crate::vec2::norm(self.slip) / self.dt;
        if v.is_finite() { v } else { 0.0 }
    }
}

/// The law's answer for one step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StepOutput {
    /// Friction coefficient vector μ⃗ at the end of the step (F_f = −F_n μ⃗).
    pub mu: Vec2,
    /// Friction force on the slipping body at the end of the step, −F_n μ⃗ (N).
    pub force: Vec2,
    /// Regime at the end of the step.
    pub regime: Regime,
    /// Largest friction coefficient a rigid-constraint solver should allow at this contact
    /// for the next step: the law sticks as long as the required coefficient stays below it.
    pub limit: f64,
    /// Energy dissipated over the step (J): friction work minus the change of stored elastic
    /// energy. Never negative beyond rounding.
    pub dissipated: f64,
}

/// A friction law: a pure function of (state, step input) that updates the state.
pub trait FrictionLaw: Send + Sync + std::fmt::Debug {
    /// Advances `state` over one step and returns the friction the contact produces.
    /// Must not panic and must keep `state` finite for any finite input.
    fn step(&self, state: &mut FrictionState, input: &StepInput) -> StepOutput;

    /// The coefficient this law slides with at speed `speed` once in steady sliding.
    fn sliding_coefficient(&self, speed: f64) -> f64;

    /// The coefficient up to which a contact at rest holds (break-away, seed Eq. 2–3).
    fn static_coefficient(&self) -> f64;

    /// Short name: `ep`, `phys`, `regul` or `coulomb`.
    fn name(&self) -> &'static str;
}

/// How a law without sticking creeps under a load (see [`Law::creep`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Creep {
    /// Steady creep speed (m/s).
    pub speed: f64,
    /// The sliding level μ_ve(|ġ|) the creep runs against.
    pub level: f64,
}

/// Any of the built-in laws, serializable (e.g. in scenario files and collider materials).
///
/// ```
/// use stickslip_core::law::{Law, FrictionLaw, FrictionState, StepInput, Regime};
/// use stickslip_core::sliding_curve::Curve;
/// let law = Law::elasto_plastic(1e4, 0.5, 0.55, Curve::constant(0.55).unwrap()).unwrap();
/// let mut state = FrictionState::default();
/// // 10 µm of slip under 100 N: elastic, μ = c·g = 0.1 (seed, sticking).
/// let out = law.step(&mut state, &StepInput::new([1e-5, 0.0], 1e-3, 100.0));
/// assert_eq!(out.regime, Regime::Sticking);
/// assert!((out.mu[0] - 0.1).abs() < 1e-12);
/// assert!((out.force[0] + 10.0).abs() < 1e-9);
/// ```
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "law", rename_all = "kebab-case")]
pub enum Law {
    /// The seed's elasto-plastic law ("EP"), latched by default (see [`ElastoPlastic`]).
    #[serde(rename = "ep")]
    ElastoPlastic(ElastoPlastic),
    /// The exact switched model ("Phys").
    #[serde(rename = "phys")]
    Physical(Physical),
    /// The regularized model ("Regul").
    #[serde(rename = "regul")]
    Regularized(Regularized),
    /// Plain Coulomb.
    #[serde(rename = "coulomb")]
    Coulomb(Coulomb),
}

impl Law {
    /// Whether the law keeps no state between steps (Phys, Regul, Coulomb): its friction is
    /// a function of the step's slip alone.
    pub fn is_memoryless(&self) -> bool {
        !matches!(self, Law::ElastoPlastic(_))
    }

    /// Whether the law has a sticking regime a rigid solver may hold (all but Regul, which
    /// creeps under any load).
    pub fn can_stick(&self) -> bool {
        !matches!(self, Law::Regularized(_))
    }

    /// The law's contact stiffness per unit normal force, c (1/m), for a compliant law (EP):
    /// its tangential stiffness is k_t = c·F_n. `None` for rigid laws.
    pub fn stiffness(&self) -> Option<f64> {
        match self {
            Law::ElastoPlastic(l) => Some(l.c()),
            _ => None,
        }
    }

    /// How a law without sticking (Regul) creeps under a load of `ratio` = |F_t|/F_n at slip
    /// speed `speed`: its steady creep speed and the sliding level μ_ve(|ġ|) it creeps
    /// against; `None` for laws that stick.
    pub fn creep(&self, ratio: f64, speed: f64) -> Option<Creep> {
        match self {
            Law::Regularized(l) => Some(Creep {
                speed: l.creep_speed(ratio, speed),
                level: l.curve().mu(speed),
            }),
            _ => None,
        }
    }

    /// [`ElastoPlastic::new`] wrapped in a [`Law`].
    pub fn elasto_plastic(
        c: f64,
        mu_ba: f64,
        mu_max: f64,
        curve: crate::sliding_curve::Curve,
    ) -> Result<Self, crate::ParamError> {
        ElastoPlastic::new(c, mu_ba, mu_max, curve).map(Law::ElastoPlastic)
    }

    /// The law as a trait object.
    pub fn as_dyn(&self) -> &dyn FrictionLaw {
        match self {
            Law::ElastoPlastic(l) => l,
            Law::Physical(l) => l,
            Law::Regularized(l) => l,
            Law::Coulomb(l) => l,
        }
    }
}

impl FrictionLaw for Law {
    #[inline]
    fn step(&self, state: &mut FrictionState, input: &StepInput) -> StepOutput {
        match self {
            Law::ElastoPlastic(l) => l.step(state, input),
            Law::Physical(l) => l.step(state, input),
            Law::Regularized(l) => l.step(state, input),
            Law::Coulomb(l) => l.step(state, input),
        }
    }
    fn sliding_coefficient(&self, speed: f64) -> f64 {
        self.as_dyn().sliding_coefficient(speed)
    }
    fn static_coefficient(&self) -> f64 {
        self.as_dyn().static_coefficient()
    }
    fn name(&self) -> &'static str {
        self.as_dyn().name()
    }
}

/// Output for a contact without load: no friction, state relaxed.
pub(crate) fn unloaded(state: &mut FrictionState) -> StepOutput {
    state.force = [0.0; 2];
    state.slide = 0.0;
    StepOutput {
        mu: [0.0; 2],
        force: [0.0; 2],
        regime: Regime::Sliding,
        limit: 0.0,
        dissipated: 0.0,
    }
}

/// Output of a memoryless law that prescribes coefficient vector `mu` (along the slip).
pub(crate) fn memoryless(
    state: &mut FrictionState,
    input: &StepInput,
    mu: Vec2,
    regime: Regime,
    limit: f64,
) -> StepOutput {
    use crate::vec2::{dot, scale};
    let f_n = input.normal_force;
    state.force = scale(mu, f_n);
    StepOutput {
        mu,
        force: scale(mu, -f_n),
        regime,
        limit,
        dissipated: (f_n * dot(mu, input.slip)).max(0.0),
    }
}
