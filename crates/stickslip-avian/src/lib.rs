//! # stickslip-avian
//!
//! stickslip's friction as an add-on to [avian3d](https://docs.rs/avian3d) 0.7 (bevy 0.19):
//! add [`StickSlipAvianPlugin`] beside `PhysicsPlugins` and
//!
//! - avian's own `Friction::new(μ_k).with_static_coefficient(μ_s)` becomes real static
//!   friction: a contact holds without creep below μ_s, breaks away at μ_s and slides at μ_k
//!   (avian alone reads only the dynamic coefficient). Nothing else in the app changes; pairs
//!   whose combined static coefficient is not above the dynamic one stay avian's own.
//! - a collider with [`StickSlipFriction`] gets a stickslip material: the elasto-plastic law
//!   with any sliding curve (Stribeck), or the seed's "Phys" and "Regul" baselines;
//! - [`StickSlipVibration`] makes a collider's contacts feel a vibration source (Popov's normal,
//!   tangential, transverse or superimposed oscillation, elliptical drives);
//! - [`SurfaceVelocity`] moves a collider's surface (a conveyor belt) on every pair, and keeps
//!   what it carries awake;
//! - [`StickSlipContacts`] reads the contacts back by entity with their regime, and
//!   [`RegimeChanged`] tells when a contact sticks, slips or slides.
//!
//! ```no_run
//! use avian3d::prelude::*;
//! use bevy::prelude::*;
//! use stickslip_avian::StickSlipAvianPlugin;
//!
//! App::new()
//!     .add_plugins((MinimalPlugins, PhysicsPlugins::default(), StickSlipAvianPlugin::default()))
//!     .add_systems(Startup, |mut commands: Commands| {
//!         commands.spawn((RigidBody::Static, Collider::cuboid(10.0, 0.2, 10.0)));
//!         // Holds on slopes up to tan θ = 0.6, slides at 0.4 above.
//!         commands.spawn((
//!             RigidBody::Dynamic,
//!             Collider::cuboid(0.5, 0.5, 0.5),
//!             Friction::new(0.4).with_static_coefficient(0.6),
//!         ));
//!     })
//!     .run();
//! ```
//!
//! ## How it hooks into avian
//!
//! Not through `CollisionHooks`: the app keeps its own hooks type, and avian's hooks see the
//! contacts before the last tick's impulses are matched onto them. Two systems of avian's
//! `PhysicsSchedule` instead:
//!
//! - **apply**, at the end of the narrow phase (after the app's hooks and avian's warm-start
//!   matching, before the solver builds its constraints): one step of the friction law per
//!   contact manifold, from the manifold's slip and what the last solve measured; it writes
//!   the manifold's `friction` (the law's limit) and `tangent_velocity` (the law's target, a
//!   vibration's drive, a moving surface).
//! - **measure**, right after the solver stored its impulses: each manifold's normal force and
//!   friction, read from the solver's constraints.
//!
//! **Per tick, not per substep.** avian solves each tick in `SubstepCount` substeps (6 by
//! default) with the friction and tangent velocity its narrow phase left on the manifold, as
//! rapier's steps do with its hook's: the law steps once per physics tick with the tick's dt,
//! and its limit and target hold for all of the tick's substeps. The normal force it measures
//! is the last substep's accumulated normal impulse over the substep's length (what the
//! contact carried at the end of the tick), its friction that substep's friction impulse over
//! it. The law's state therefore does not depend on the substep count; the tests run at 6
//! substeps and at 2 and 12.
//!
//! **The app's hooks.** They run first, on the pairs avian calls them for; stickslip sees what
//! they left. A pair of two colliders without stickslip material whose `friction` the app's
//! hook changed keeps it (avian's Coulomb friction at the app's coefficient); a pair with a
//! stickslip material gets the material's law; a `tangent_velocity` the hook set is the
//! surface's motion the law works against.
//!
//! Contacts are keyed by their collider entities and manifold: a despawned collider or a
//! separated pair leaves no state after the tick it is gone in.
#![warn(missing_docs)]

mod apply;
mod components;
#[cfg(feature = "debug")]
pub mod debug;
mod key;
mod measure;
mod pair_law;
mod plugin;
pub mod prelude;
mod report;
mod store;

pub use components::{StickSlipFriction, StickSlipVibration, SurfaceVelocity};
pub use plugin::{StickSlipAvianPlugin, StickSlipAvianSystems};
pub use report::{AvianContact, RegimeChanged, StickSlipContacts};
/// The engine-free core (laws, sliding curves, vibration sources), so an app needs no second
/// stickslip dependency.
pub use stickslip_core as core;
pub use stickslip_core::FrictionMaterial;
pub use stickslip_core::contact::VibrationSource;
pub use store::ContactStore;
