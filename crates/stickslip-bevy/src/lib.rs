//! # stickslip-bevy
//!
//! bevy 0.19 plugins for [stickslip](../stickslip/index.html): friction that sticks without
//! creep, breaks away, follows a Stribeck curve and changes when a surface vibrates, on bevy
//! entities. bevy_rapier for bevy 0.19 pins another rapier, so this crate drives rapier3d 0.36
//! itself (one world in the [`StickSlipWorld`] resource) through `stickslip-rapier`.
//!
//! - [`StickSlipPlugins`] (a `PluginGroup`): [`StickSlipPhysicsPlugin`] (bodies, colliders,
//!   velocities, forces; `Transform` in and out), [`StickSlipFrictionPlugin`] (contact
//!   read-back in [`StickSlipContacts`], [`RegimeChanged`] messages, removals) and, with
//!   feature `debug`, [`debug::StickSlipDebugPlugin`] (contact gizmos coloured by regime).
//! - Components: [`RigidBody`], [`Collider`], [`Velocity`], [`ExternalForce`], [`Density`],
//!   [`Friction`] (plain rapier), [`LockRotations`], [`AllowSleep`] (bodies never sleep
//!   otherwise: a slowly conveyed part must not freeze); the friction layer's [`FrictionLaw`]
//!   (per collider, or the [`DefaultFriction`] resource), [`Vibration`] and
//!   [`SurfaceVelocity`] (belts).
//! - Runs in `FixedPostUpdate` by default in the chained sets [`StickSlipSystems`] before
//!   transform propagation; `StickSlipPlugins::new(schedule)` picks another schedule. The step
//!   is the schedule's `Time` delta, so pausing or slowing bevy's virtual time pauses or slows
//!   the physics. Removing components or despawning cleans up rapier and stickslip state.
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
//! assert!((y - 0.2).abs() < 1e-2, "the box rests on the ground: y = {y}");
//! let contacts = app.world().resource::<StickSlipContacts>();
//! assert!(contacts.of(part).count() > 0);
//! ```
#![warn(missing_docs)]

mod components;
mod contacts;
mod convert;
#[cfg(feature = "debug")]
pub mod debug;
mod hooks;
mod plugin;
mod step;
mod world;

pub use components::{
    AllowSleep, Collider, Density, ExternalForce, Friction, FrictionLaw, LockRotations, RapierBody,
    RapierCollider, RigidBody, SurfaceVelocity, Velocity, Vibration,
};
pub use contacts::{Contact, RegimeChanged, StickSlipContacts};
pub use convert::{rot_to_bevy, rot_to_rapier, to_bevy, to_rapier};
pub use hooks::SurfaceHooks;
pub use plugin::{
    StickSlipFrictionPlugin, StickSlipPhysicsPlugin, StickSlipPlugins, StickSlipSystems,
    default_material,
};
pub use step::Gravity;
pub use world::{DefaultFriction, StickSlipWorld};

pub use stickslip_core as core;
pub use stickslip_rapier as rapier;

/// Everything a typical app uses.
pub mod prelude {
    pub use crate::{
        AllowSleep, Collider, Contact, DefaultFriction, Density, ExternalForce, Friction,
        FrictionLaw, Gravity, LockRotations, RegimeChanged, RigidBody, StickSlipContacts,
        StickSlipPlugins, StickSlipSystems, StickSlipWorld, SurfaceVelocity, Velocity, Vibration,
    };
    pub use stickslip_rapier::{
        Amplitude, FrictionMaterial, VibrationDirection, VibrationMode, VibrationSource,
    };
}
