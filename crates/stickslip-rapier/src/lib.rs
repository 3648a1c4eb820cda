//! # stickslip-rapier
//!
//! A rapier3d 0.36 contact modifier that replaces plain Coulomb friction with stickslip's
//! friction laws (the elasto-plastic law of the seed paper, or the Phys/Regul/Coulomb
//! baselines) and applies vibration-modulated friction.
//!
//! ## Quick start
//! ```
//! # extern crate rapier as rapier3d;
//! use rapier3d::prelude::*;
//! use stickslip_core::law::Law;
//! use stickslip_core::sliding_curve::Curve;
//! use stickslip_rapier::{FrictionMaterial, ReadBack, StickSlip};
//!
//! let mut world = PhysicsWorld::default();
//! let ground = world.insert_collider(ColliderBuilder::cuboid(5.0, 0.1, 5.0), None);
//! let (body, cube) = world.insert(
//!     RigidBodyBuilder::dynamic().translation(Vector::new(0.0, 0.35, 0.0)),
//!     ColliderBuilder::cuboid(0.25, 0.25, 0.25).density(1000.0),
//! );
//! // Elasto-plastic friction: c = 1e4 1/m, μ_ba = 0.5, μ_max = μ_ve = 0.55.
//! let law = Law::elasto_plastic(1e4, 0.5, 0.55, Curve::constant(0.55).unwrap()).unwrap();
//! // Per-contact reports are opt-in (the friction is the same without them).
//! let mut friction = StickSlip::new(FrictionMaterial::new(law)).with_read_back(ReadBack::Contacts);
//! // Both sides attached: the pair is the material's alone. (An unattached cube would bring
//! // its rapier friction, 0.5 by default, combined with the material like rapier combines
//! // coefficients; pairs without an attached collider stay plain rapier's.)
//! friction.attach(&mut world.colliders, ground, None);
//! friction.attach(&mut world.colliders, cube, None);
//! for _ in 0..60 {
//!     friction.step(&mut world);
//! }
//! // The read-back: the 125 kg box's weight rests on the contact, which sticks.
//! // `reports()` is an error, not an empty slice, when read-back is off.
//! let report = &friction.reports().unwrap()[0];
//! assert!((report.normal_force - 125.0 * 9.81).abs() < 0.02 * 125.0 * 9.81);
//! assert_eq!(report.regime, stickslip_core::law::Regime::Sticking);
//! # let _ = (body, cube);
//! ```
//!
//! Save and resume a world with [`WorldSnapshot`] (see [`snapshot`]).
//!
//! How the law maps onto rapier's per-manifold friction — how sticking is realized for every
//! motion a rigid contact has (translation, rolling, spinning, stacks), and why a hold cannot
//! pump energy — is in the docs of the engine-free kernel ([`stickslip_core::contact`]); see
//! [`VibrationSource`] for vibration.
#![warn(missing_docs)]
// `!(x > 0.0)` is deliberate throughout: it rejects NaN along with non-positive values.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

mod collider_map;
mod contact_store;
mod fast_hash;
mod heap;
mod hook;
mod measure;
mod modifier;
mod pair_law;
mod pair_list;
mod patches;
pub mod prelude;
mod quiet;
mod rapier_compat;
mod read_back;
mod recycle;
mod report;
mod rolling;
pub mod snapshot;
mod surface;
mod tangent;
mod warnings;

pub use modifier::{
    MAX_DT, MIN_DT, NotReadBack, ReadBack, SWEEP_INTERVAL, StickSlip, StickSlipConfig, valid_dt,
};
pub use pair_law::{MAX_COMBINATIONS, combine_rule};
pub use report::{ContactReport, DIM, RollingReport, WorldTotals};
pub use snapshot::{SnapshotError, StickSlipSnapshot, WorldSnapshot};
pub use stickslip_core::FrictionMaterial;
pub use stickslip_core::contact::{
    Amplitude, MAX_AXIS_COSINE, MAX_COMPONENTS, MAX_FORCE, MAX_FREQUENCY, MAX_RATIO,
    MAX_TANGENTIAL_STIFFNESS, VibrationComponent, VibrationDirection, VibrationMode,
    VibrationSource,
};

/// Re-export of the core crate.
pub use stickslip_core as core;

/// Re-export of the rapier this adapter is built for (rapier3d 0.36, rapier3d 0.35 or
/// rapier2d 0.36), for code that must name the same version.
pub use rapier;
