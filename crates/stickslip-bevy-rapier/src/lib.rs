//! stickslip as an add-on to bevy_rapier3d 0.36 (bevy 0.19): a bevy_rapier app keeps its
//! `RapierPhysicsPlugin`, components and systems, adds [`StickSlipRapierPlugin`], and gets
//! stickslip's friction on the colliders it marks with [`StickSlipFriction`].
//!
//! ```
//! use bevy::prelude::*;
//! use bevy_rapier3d::prelude::*;
//! use stickslip_bevy_rapier::{StickSlipFriction, StickSlipRapier, StickSlipRapierPlugin};
//!
//! let mut app = App::new();
//! app.add_plugins((MinimalPlugins, TransformPlugin))
//!     // The app's bevy_rapier, as it was (any timestep mode, its own hooks type).
//!     .add_plugins(RapierPhysicsPlugin::<NoUserData>::default())
//!     // stickslip: one plugin (same hooks type and schedule as bevy_rapier's) …
//!     .add_plugins(StickSlipRapierPlugin::default());
//! app.update();
//! // … and one component on the colliders whose pairs get stickslip's friction.
//! let ground = app
//!     .world_mut()
//!     .spawn((RigidBody::Fixed, Collider::cuboid(5.0, 0.1, 5.0), StickSlipFriction(None)))
//!     .id();
//! app.update();
//! assert!(app.world().resource::<StickSlipRapier>().is_attached(ground));
//! ```
//!
//! How it brackets rapier's steps: bevy_rapier's step system runs all the rapier steps of a
//! frame (substeps, `Interpolated` catch-up) in one call, where nothing can run between two
//! steps. The plugin therefore takes that system's place in `PhysicsSet::StepSimulation`
//! with its own, which runs the same rapier steps through bevy_rapier's context one at a
//! time, each between `StickSlip::begin_step` and `end_step`, with the same events, hooks and
//! transform interpolation — in every `TimestepMode` (Fixed, Variable, Interpolated, any
//! substeps). If bevy_rapier's step system is not found (another hooks type or schedule than
//! the plugin's), an error says so at startup and stickslip stays off: the app keeps rapier's
//! own friction, never a silently wrong one.
//!
//! The app's own `BevyPhysicsHooks` (a one-way platform, …) keep working: name them in both
//! plugins, `RapierPhysicsPlugin::<MyHooks>` and
//! `StickSlipRapierPlugin::default().with_hooks::<MyHooks>()`; they run first, on exactly the
//! pairs bevy_rapier would call them for without stickslip (the hook flag stickslip turns on
//! in rapier is its own; the app's `ActiveHooks` component stays the app's).
//! stickslip acts on the default rapier context; other contexts step as in bevy_rapier.
//!
//! Rolling and spinning resistance (`FrictionMaterial::with_rolling`, `with_spinning`) work
//! as in rapier: before each bracketed step stickslip sets the motors of one impulse joint per
//! resisting pair, which it keeps in the context's joint set without an entity (and, for
//! colliders without a rigid body, one fixed body of its own in the body set);
//! `StickSlipRapier::modifier().rolling_reports(&joints.impulse_joints)` reads them back.

#![warn(missing_docs)]

// One source for both dimensions (the package stickslip-bevy-rapier2d builds it with cfg
// `dim2`), as rapier builds rapier2d and rapier3d.
#[cfg(dim2)]
extern crate bevy_rapier2d as bevy_rapier;
#[cfg(not(dim2))]
extern crate bevy_rapier3d as bevy_rapier;
#[cfg(dim2)]
extern crate stickslip_rapier2d_035 as stickslip_rapier;
#[cfg(not(dim2))]
extern crate stickslip_rapier_035 as stickslip_rapier;

mod hooks;
pub mod prelude;
#[cfg(feature = "scenario")]
pub mod scenario;
mod state;
mod step;
mod sync;

pub use state::StickSlipRapier;
/// Contact gizmos (feature `debug`), shared with stickslip-avian: `StickSlipDebugPlugin` turns
/// this plugin's contact read-back on.
#[cfg(feature = "debug")]
pub use stickslip_bevy::debug;
/// Windowed apps' support (feature `window`): command line, display check, screenshots.
#[cfg(feature = "window")]
pub use stickslip_bevy::window;
pub use stickslip_bevy::{
    ContactReport, RegimeChanged, RollingReport, StickSlipContacts, StickSlipFriction,
    StickSlipVibration, SurfaceVelocity,
};
/// The engine-free core (laws, sliding curves, vibration sources), so an app needs no second
/// stickslip dependency.
pub use stickslip_core as core;
pub use stickslip_core::FrictionMaterial;

use bevy::ecs::intern::Interned;
use bevy::ecs::schedule::{ScheduleCleanupPolicy, ScheduleLabel};
use bevy::ecs::system::SystemParamItem;
use bevy::prelude::*;
use bevy_rapier::plugin::systems::step_simulation;
use bevy_rapier::prelude::*;
use std::marker::PhantomData;
use stickslip_rapier::StickSlip;

/// Adds stickslip to a bevy_rapier app (see the crate docs). `H` is the app's
/// `BevyPhysicsHooks` type, the one of its `RapierPhysicsPlugin::<H>` (`()` is bevy_rapier's
/// `NoUserData`).
pub struct StickSlipRapierPlugin<H = ()> {
    default_material: FrictionMaterial,
    schedule: Interned<dyn ScheduleLabel>,
    hooks: PhantomData<fn() -> H>,
}

impl StickSlipRapierPlugin {
    /// stickslip with this material for colliders marked `StickSlipFriction(None)`, beside
    /// `RapierPhysicsPlugin::<NoUserData>` in `PostUpdate`.
    pub fn new(default_material: FrictionMaterial) -> Self {
        StickSlipRapierPlugin {
            default_material,
            schedule: PostUpdate.intern(),
            hooks: PhantomData,
        }
    }

    /// The app's own hooks type, as in its `RapierPhysicsPlugin::<H>`.
    pub fn with_hooks<H>(self) -> StickSlipRapierPlugin<H> {
        StickSlipRapierPlugin {
            default_material: self.default_material,
            schedule: self.schedule,
            hooks: PhantomData,
        }
    }
}

impl<H> StickSlipRapierPlugin<H> {
    /// The schedule bevy_rapier runs in (`RapierPhysicsPlugin::in_schedule`).
    pub fn in_schedule(mut self, schedule: impl ScheduleLabel) -> Self {
        self.schedule = schedule.intern();
        self
    }

    /// bevy_rapier in `FixedUpdate` (`RapierPhysicsPlugin::in_fixed_schedule`).
    pub fn in_fixed_schedule(self) -> Self {
        self.in_schedule(FixedUpdate)
    }

    /// The material of colliders marked `StickSlipFriction(None)`.
    pub fn with_default_material(mut self, material: FrictionMaterial) -> Self {
        self.default_material = material;
        self
    }
}

impl Default for StickSlipRapierPlugin {
    /// Elasto-plastic friction with rapier's default coefficient 0.5 for break-away, static
    /// and sliding friction, contact stiffness c = 1e5 1/m: sticking without creep.
    fn default() -> Self {
        use stickslip_core::law::{Coulomb, Law};
        use stickslip_core::sliding_curve::Curve;
        let law = Curve::constant(0.5)
            .and_then(|c| Law::elasto_plastic(1e5, 0.5, 0.5, c))
            .unwrap_or_else(|_| Law::Coulomb(Coulomb::clamped(0.5)));
        StickSlipRapierPlugin::new(FrictionMaterial::new(law))
    }
}

impl<H> Plugin for StickSlipRapierPlugin<H>
where
    H: BevyPhysicsHooks + 'static,
    for<'w, 's> SystemParamItem<'w, 's, H>: BevyPhysicsHooks,
{
    fn build(&self, app: &mut App) {
        app.insert_resource(StickSlipRapier::new(StickSlip::new(
            self.default_material.clone(),
        )))
        .init_resource::<StickSlipContacts>()
        .init_resource::<state::LastRegimes>()
        .add_message::<RegimeChanged>()
        .add_systems(
            self.schedule,
            (
                sync::removals,
                sync::attach,
                sync::sync_vibrations,
                sync::sync_surfaces,
                sync::follow_app_hooks,
            )
                .chain()
                .after(PhysicsSet::SyncBackend)
                .before(PhysicsSet::StepSimulation),
        )
        // Where bevy_rapier reads its own removals (none is missed in any schedule), before
        // it removes the colliders.
        .add_systems(
            PostUpdate,
            sync::removals.before(bevy_rapier::plugin::systems::sync_removals),
        );

        // bevy_rapier's step system is replaced at startup, when every plugin is built
        // (whatever the order they were added in; `App::update` alone never calls
        // `Plugin::finish`).
        let schedule = self.schedule;
        app.add_systems(PreStartup, move |world: &mut World| {
            take_over_step::<H>(world, schedule)
        });
    }

    /// The contact gizmos draw what is read back: with them, contacts are read back.
    #[cfg(feature = "debug")]
    fn finish(&self, app: &mut App) {
        use stickslip_rapier::ReadBack;
        if app.is_plugin_added::<debug::StickSlipDebugPlugin>()
            && let Some(mut state) = app.world_mut().get_resource_mut::<StickSlipRapier>()
            && state.modifier.read_back() != ReadBack::Contacts
        {
            state.modifier.set_read_back(ReadBack::Contacts);
        }
    }
}

/// Replaces bevy_rapier's step system for hooks `H` in `schedule` by the bracketed one; or,
/// if it is not there, says so and leaves stickslip off.
fn take_over_step<H>(world: &mut World, schedule: Interned<dyn ScheduleLabel>)
where
    H: BevyPhysicsHooks + 'static,
    for<'w, 's> SystemParamItem<'w, 's, H>: BevyPhysicsHooks,
{
    let removed = world.try_schedule_scope(schedule, |world, s| {
        s.remove_systems_in_set(
            step_simulation::<H>,
            world,
            ScheduleCleanupPolicy::RemoveSystemsOnly,
        )
    });
    if let Ok(Ok(n)) = removed
        && n > 0
    {
        world.resource_mut::<Schedules>().add_systems(
            schedule,
            step::step_simulation_bracketed::<H>.in_set(PhysicsSet::StepSimulation),
        );
        return;
    }
    error!(
        "stickslip: bevy_rapier's step system `step_simulation::<{}>` is not in schedule \
         {:?}: add RapierPhysicsPlugin::<H> with the same hooks type H and schedule as \
         StickSlipRapierPlugin (with_hooks::<H>(), in_schedule(..)). stickslip is off: this \
         app has rapier's own friction",
        std::any::type_name::<H>(),
        schedule
    );
    if let Some(mut state) = world.get_resource_mut::<StickSlipRapier>() {
        state.active = false;
    }
}
