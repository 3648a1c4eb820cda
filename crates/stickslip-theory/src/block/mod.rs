//! The seed's Example 1: a block of mass m on a plane under a time-dependent tangential force
//! F(t), integrated with adaptive ODE methods from `differential-equations`, for every law.
//!
//! - [`ForceProfile`] (from `stickslip_core::profile`): a validated piecewise-linear F(t); [`ForceProfile::example1`] gives the
//!   three phases of the seed (sticking just below break-away, stick-slip then sliding,
//!   slip-stick back to rest).
//! - `simulate`: EP (state [x, v, μ, σ], arcs between the law's reset events) and Regul as
//!   smooth ODEs; Phys and Coulomb as the exact
//!   switched system: sliding arcs integrated up to the event v = 0, sticking arcs resolved
//!   from the profile in closed form.
//! - `BeltSpring`: the mass–spring on a moving belt with EP (the stick-slip oscillator), and
//!   its analytic period for static/kinetic Coulomb friction.
//! - `Integrator`: explicit Runge–Kutta–Fehlberg 4(5) or Dormand–Prince 5(4) (the ode45
//!   analogue), or the L-stable ESDIRK 3(2) (an implicit stiff method in the spirit of ode23s).

mod simulate;

pub use simulate::{
    BeltSpring, BlockRun, Integrator, MAX_DURATION, PhaseSummary, RunStats, STICK_SPEED, SimError,
    Tolerances, simulate,
};

use stickslip_core::error::{ParamError, in_range};
use stickslip_core::law::Law;
pub use stickslip_core::profile::ForceProfile;

/// A block on a horizontal plane: mass, gravity and the friction law at its contact.
#[derive(Debug, Clone, PartialEq)]
pub struct Block {
    mass: f64,
    gravity: f64,
    law: Law,
}

impl Block {
    /// Mass (kg) > 0, gravity (m/s²) > 0 and law.
    /// A block of `mass` (kg, in [1e-9, 1e12]) under `gravity` (m/s², in [1e-9, 1e6]): the
    /// bounds keep m·g and every force of the run finite.
    pub fn new(mass: f64, gravity: f64, law: Law) -> Result<Self, ParamError> {
        Ok(Block {
            mass: in_range("mass", mass, 1e-9, 1e12)?,
            gravity: in_range("gravity", gravity, 1e-9, 1e6)?,
            law,
        })
    }
    /// Mass (kg).
    pub fn mass(&self) -> f64 {
        self.mass
    }
    /// Normal force m·g (N).
    pub fn normal_force(&self) -> f64 {
        self.mass * self.gravity
    }
    /// The friction law.
    pub fn law(&self) -> &Law {
        &self.law
    }
}
