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
//! - [`StickSlipContacts`] reads the contacts back by entity ([`ContactReport`], the type
//!   every stickslip engine reads back, its slip velocity the one the law stepped with, at
//!   the start of the tick), and [`RegimeChanged`] tells when a contact sticks, slips or
//!   slides;
//! - a material with rolling or spinning resistance (`FrictionMaterial::with_rolling`,
//!   `with_spinning`) gets a torque against the bodies' relative rolling and spinning,
//!   governed by its own law (a ball that holds on a gentle slope, rolls to a stop, stops
//!   spinning), read back in [`StickSlipRolling`] ([`RollingReport`]).
//!
//! The components, the read-back and the gizmos are stickslip-bevy's, shared with
//! stickslip-bevy-rapier: an app moving between bevy_rapier and avian changes its plugin.
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
//! contacts before the last tick's impulses are matched onto them. Systems of avian's
//! `PhysicsSchedule` instead:
//!
//! - **apply**, at the end of the narrow phase (after the app's hooks and avian's warm-start
//!   matching, before the solver builds its constraints): one step of the friction law per
//!   contact manifold, from the manifold's slip and what the last solve measured; it writes
//!   the manifold's `friction` (the law's limit) and `tangent_velocity` (the law's target, a
//!   vibration's drive, a moving surface).
//! - **carry the warm start**, before the substeps (`SolverSystems::PreSubstep`), and **add up
//!   the impulses** after each substep's relax pass (`SubstepSchedule`);
//! - **measure**, right after the solver stored its impulses: each manifold's normal force and
//!   friction over the tick.
//! - **rolling resistance**: `apply` also steps each resisting pair's rolling and spinning
//!   laws and gives the substeps their angular rows, warm-started and solved after avian's
//!   contact rows in both of its passes (see the `rolling` module's docs: why the torque comes
//!   out of one solve with the contact's friction and normal force, and how a hold stays
//!   still).
//!
//! **Per tick, not per substep.** avian solves each tick in `SubstepCount` substeps (6 by
//! default) with the friction and tangent velocity its narrow phase left on the manifold, as
//! rapier's steps do with its hook's: the law steps once per physics tick with the tick's dt,
//! and its limit and target hold for all of the tick's substeps. What it measures is the
//! tick's: the normal and friction impulses of all substeps (and restitution's) over the tick.
//! The law's state therefore does not depend on the substep count; the tests run at 2, 6 and
//! 12 substeps.
//!
//! **Holding without creep.** avian keeps a contact's friction warm start as coordinates in a
//! tangent basis it picks again every tick from the bodies' relative velocity, which for a
//! held contact is solver noise: the basis turns at random and the warm start, applied in the
//! new basis, pushes the held friction off its direction, so avian's own hold creeps (2 mm in
//! 5 s for a box at 0.9 of break-away, 120 Hz, 6 substeps). Before the substeps stickslip
//! turns the warm start of each contact it steps into the new basis, the same world impulse
//! (as rapier keeps it), and a held contact stays within the law's elastic range
//! (`tests/hold_creep.rs`: within 2.8 µm of a range of 16.7 µm at 60 Hz and 2 substeps, within
//! 0.01 µm at 6 and 12). A box put down on a slope close to its break-away falls free for the
//! tick before avian has its contact and lands sliding; avian brakes that slide with each
//! point at its own clamp, which stickslip reads as the solve at its limit, and the law holds
//! the contact at its capacity while the slide shrinks. While avian's soft normal rows then
//! move the load to the front points, a held contact whose points did not all share the
//! friction gets twice the limit per point (the kernel still judges the whole contact against
//! the law's limit): the box moves 3.0 µm in 5 s at 60 Hz and 2 substeps, 0.19 µm at 120 Hz,
//! under 0.5 µm at 6 and 12 substeps.
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

// One source for both dimensions (the package stickslip-avian2d builds it with cfg `dim2`),
// as avian builds avian2d and avian3d.
#[cfg(dim2)]
extern crate avian2d as avian;
#[cfg(not(dim2))]
extern crate avian3d as avian;

mod apply;
mod dim;
mod key;
mod measure;
mod pair_law;
mod plugin;
pub mod prelude;
mod rolling;
mod store;

pub use plugin::{StickSlipAvianPlugin, StickSlipAvianSystems};
/// Contact gizmos (feature `debug`), shared with stickslip-bevy-rapier.
#[cfg(feature = "debug")]
pub use stickslip_bevy::debug;
/// Windowed apps' support (feature `window`): command line, display check, screenshots.
#[cfg(feature = "window")]
pub use stickslip_bevy::window;
pub use stickslip_bevy::{
    ContactReport, RegimeChanged, RollingReport, StickSlipContacts, StickSlipFriction,
    StickSlipRolling, StickSlipVibration, SurfaceVelocity,
};
/// The engine-free core (laws, sliding curves, vibration sources), so an app needs no second
/// stickslip dependency.
pub use stickslip_core as core;
pub use stickslip_core::FrictionMaterial;
pub use stickslip_core::contact::VibrationSource;
pub use store::ContactStore;
