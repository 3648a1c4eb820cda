//! # stickslip-bevy
//!
//! bevy 0.19 plugins for stickslip: friction that sticks without creep, breaks away, follows
//! a Stribeck curve and changes when a surface vibrates, on bevy entities. bevy_rapier for
//! bevy 0.19 pins another rapier, so this crate drives rapier3d 0.36 itself (one world in the
//! [`StickSlipWorld`] resource) through `stickslip-rapier`'s contact modifier.
//!
//! - [`StickSlipPlugins`] (a `PluginGroup`):
//!   - [`StickSlipPhysicsPlugin`], the rapier bridge: [`RigidBody`], [`Collider`] (on the body
//!     or on a child), [`Velocity`], [`ExternalForce`], [`Density`] or [`ColliderMass`],
//!     [`Friction`] (rapier's own Coulomb), [`Restitution`], [`Damping`], [`Ccd`],
//!     [`LockRotations`], [`AllowSleep`]; `Transform` in and out.
//!   - [`StickSlipFrictionPlugin`], the friction layer: [`FrictionLaw`] per collider (or the
//!     [`DefaultFriction`] resource's material), [`Vibration`], [`SurfaceVelocity`] (belts),
//!     and the read-back: the [`ContactReports`] resource and [`RegimeChanged`] messages.
//!   - with feature `debug`, `debug::StickSlipDebugPlugin`: contact gizmos coloured by
//!     regime.
//! - with feature `scenario`, `scenario`: the TOML scenarios of `stickslip run` spawned as
//!   entities, their drivers acting on them (`cargo run -p stickslip-bevy --features
//!   window,scenario --example view -- scenarios/incline.toml`).
//! - Physics runs in `FixedPostUpdate` by default, in the chained sets [`StickSlipSystems`]
//!   before transform propagation; `StickSlipPlugins::new(schedule)` picks another schedule.
//!   The step is the schedule's `Time` delta (`Time<Fixed>`'s timestep in fixed schedules), so
//!   pausing or slowing bevy's virtual time pauses or slows the physics.
//! - Despawning or removing components takes rapier bodies, colliders and stickslip state
//!   with them (observers, at once).
//! - bevy's glam (0.32) and rapier's (0.33) are different types: [`convert`] is the one place
//!   that converts.
//!
//! ## Quick start
//!
//! ```
//! use bevy::prelude::*;
//! use bevy::time::TimeUpdateStrategy;
//! use stickslip_bevy::prelude::*;
//!
//! let mut app = App::new();
//! app.add_plugins((MinimalPlugins, StickSlipPlugins::default()))
//!     .insert_resource(Time::<Fixed>::from_hz(120.0))
//!     // Headless and deterministic: every update runs one fixed step.
//!     .insert_resource(TimeUpdateStrategy::FixedTimesteps(1));
//! // A fixed ground under stickslip's default elasto-plastic friction, and a box on it.
//! app.world_mut().spawn((
//!     RigidBody::Fixed,
//!     Collider::cuboid(5.0, 0.1, 5.0),
//!     FrictionLaw::default(),
//! ));
//! let part = app
//!     .world_mut()
//!     .spawn((
//!         RigidBody::Dynamic,
//!         Collider::cuboid(0.1, 0.1, 0.1),
//!         Transform::from_xyz(0.0, 0.2, 0.0),
//!     ))
//!     .id();
//! for _ in 0..121 {
//!     app.update(); // the first update has no time step; each later one runs one fixed step
//! }
//! let y = app.world().get::<Transform>(part).unwrap().translation.y;
//! assert!((y - 0.2).abs() < 1e-3, "the box rests on the ground: y = {y}");
//! let contacts = app.world().resource::<ContactReports>();
//! assert_eq!(contacts.regime_of(part), Some(Regime::Sticking));
//! assert!((contacts.time - 1.0).abs() < 1e-6, "one simulated second");
//! ```
#![warn(missing_docs)]

mod components;
mod contacts;
pub mod convert;
#[cfg(feature = "debug")]
pub mod debug;
mod friction;
mod hooks;
mod plugin;
mod removal;
#[cfg(feature = "scenario")]
pub mod scenario;
mod spawn;
mod step;
mod world;
mod writeback;

pub use components::{
    AllowSleep, Ccd, Collider, ColliderMass, Damping, Density, ExternalForce, Friction,
    FrictionCombine, LockRotations, RapierBody, RapierCollider, Restitution, RigidBody, Velocity,
};
pub use contacts::{Contact, ContactReports, RegimeChanged};
pub use friction::{DefaultFriction, FrictionLaw, SurfaceVelocity, Vibration, default_material};
pub use hooks::SurfaceHooks;
pub use plugin::{
    StickSlipFrictionPlugin, StickSlipPhysicsPlugin, StickSlipPlugins, StickSlipSystems,
};
pub use step::Gravity;
pub use world::StickSlipWorld;

pub use stickslip_core as core;
pub use stickslip_rapier as rapier;

/// Everything a typical app uses: the plugins, components, resources and messages, and the
/// stickslip types they wrap.
pub mod prelude {
    pub use crate::{
        AllowSleep, Ccd, Collider, ColliderMass, Contact, ContactReports, Damping, DefaultFriction,
        Density, ExternalForce, Friction, FrictionLaw, Gravity, LockRotations, RegimeChanged,
        Restitution, RigidBody, StickSlipPlugins, StickSlipSystems, StickSlipWorld,
        SurfaceVelocity, Velocity, Vibration,
    };
    pub use stickslip_core::law::{Law, Regime};
    pub use stickslip_core::waveform::Waveform;
    pub use stickslip_rapier::{
        Amplitude, FrictionMaterial, VibrationComponent, VibrationDirection, VibrationMode,
        VibrationSource,
    };
}
