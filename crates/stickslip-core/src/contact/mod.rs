//! The engine-free friction kernel: one contact patch's step, its state, vibration sources and
//! what they do to a contact.
//!
//! An engine adapter keeps a [`ContactState`] per contact patch (a rapier manifold, an avian
//! contact manifold), gathers a [`ContactInput`] from what the engine's last solve left there
//! (normal force, the friction it measured, the slip of the touching points) and writes the
//! [`ContactOutput`] of [`step_contact`] back (a friction limit and a target tangent velocity).
//! Nothing here knows an engine: world vectors are `[f32; 3]` (`[x, y, 0]` in 2D) and a
//! contact's tangent plane — or, in 2D, tangent line — is a [`TangentBasis`].
//!
//! ```
//! use stickslip_core::contact::{ContactInput, ContactState, TangentBasis, step_contact};
//! use stickslip_core::law::{Law, Regime};
//! use stickslip_core::sliding_curve::Curve;
//!
//! let law = Law::elasto_plastic(1e4, 0.5, 0.55, Curve::constant(0.45).unwrap()).unwrap();
//! // A 2D contact on a floor (normal +y), 100 N of load.
//! let basis = TangentBasis::line([0.0, 1.0]);
//! let mut state = ContactState::default();
//! let input = |mu: f64, slip: f64| {
//!     ContactInput::new(&law, &basis, 1.0 / 60.0)
//!         .with_solve(100.0, [mu, 0.0], [slip, 0.0])
//!         .with_inv_mass(0.1)
//! };
//! // The solver held a push of 0.3 of the load under the law's limit: the contact holds and
//! // the solver gets the law's static capacity as its limit.
//! step_contact(&mut state, &input(0.0, 0.0));
//! let out = step_contact(&mut state, &input(0.3, 0.0));
//! assert!(out.holding && (out.limit - 0.5).abs() < 1e-12);
//! assert_eq!(state.regime(), Some(Regime::Sticking));
//! ```

mod state;
mod step;
mod tangent;
pub mod vibration;
mod vibration_limit;

pub use state::{ContactState, REGIME_NONE, REGIME_RESET};
pub use step::{
    ContactInput, ContactOutput, GIVING, MAX_SANE_SPEED, SATURATION, slip_matters, step_contact,
};
pub use tangent::{TangentBasis, World, dot, length};
pub use vibration::{
    Amplitude, MAX_AXIS_COSINE, MAX_COMPONENTS, MAX_FORCE, MAX_FREQUENCY, MAX_RATIO,
    MAX_TANGENTIAL_STIFFNESS, VibrationComponent, VibrationDirection, VibrationMode,
    VibrationSource,
};
pub use vibration_limit::{in_plane_force, in_plane_limit, normal_factor, static_factor};
