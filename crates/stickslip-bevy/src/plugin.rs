//! The plugins, their group and their system sets.

use crate::contacts::{ContactReports, RegimeChanged, read_back};
use crate::friction::*;
use crate::removal::*;
use crate::spawn::{create_objects, sync_changes};
use crate::step::{Gravity, apply_inputs, step_world};
use crate::world::StickSlipWorld;
use crate::writeback::writeback;
use bevy::app::PluginGroupBuilder;
use bevy::ecs::schedule::{InternedScheduleLabel, ScheduleLabel};
use bevy::prelude::*;
use bevy::transform::TransformSystems;

/// The plugins' systems, chained in this order in their schedule, before transform
/// propagation. Order your own systems against them (e.g. drive a kinematic body
/// `.before(StickSlipSystems::Prepare)`).
#[derive(SystemSet, Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum StickSlipSystems {
    /// New entities into rapier, changed components, user inputs (poses, velocities, forces).
    Prepare,
    /// One step of the rapier world with the stickslip modifier.
    Step,
    /// Poses and velocities back onto entities; contact reports and messages.
    Writeback,
}

/// The rapier bridge: one world, bodies, colliders, velocities, forces, `Transform` in and
/// out, cleanup on removal. Alone, it is plain rapier.
pub struct StickSlipPhysicsPlugin {
    schedule: InternedScheduleLabel,
}

impl StickSlipPhysicsPlugin {
    /// Runs the physics in `schedule` (`FixedPostUpdate` by default).
    pub fn new(schedule: impl ScheduleLabel) -> Self {
        StickSlipPhysicsPlugin {
            schedule: schedule.intern(),
        }
    }
}

impl Default for StickSlipPhysicsPlugin {
    fn default() -> Self {
        StickSlipPhysicsPlugin::new(FixedPostUpdate)
    }
}

impl Plugin for StickSlipPhysicsPlugin {
    fn build(&self, app: &mut App) {
        // The modifier's own default material is the app's `DefaultFriction` (inserted before
        // the plugins, or the default); `FrictionLaw(None)` colliders follow later changes.
        let defaults = app
            .world_mut()
            .get_resource_or_init::<DefaultFriction>()
            .0
            .clone();
        app.insert_resource(StickSlipWorld::new(defaults))
            .init_resource::<Gravity>()
            .configure_sets(
                self.schedule,
                (
                    StickSlipSystems::Prepare,
                    StickSlipSystems::Step,
                    StickSlipSystems::Writeback,
                )
                    .chain()
                    .before(TransformSystems::Propagate),
            )
            .add_systems(
                self.schedule,
                (
                    (create_objects, sync_changes, apply_inputs)
                        .chain()
                        .in_set(StickSlipSystems::Prepare),
                    step_world.in_set(StickSlipSystems::Step),
                    writeback.in_set(StickSlipSystems::Writeback),
                ),
            )
            .add_observer(on_remove_body)
            .add_observer(on_remove_collider)
            .add_observer(on_remove_force);
    }
}

/// The friction layer: [`FrictionLaw`], [`DefaultFriction`], [`Vibration`] and
/// [`SurfaceVelocity`] on colliders, and the read-back after every step (the
/// [`ContactReports`] resource, [`RegimeChanged`] messages). Needs [`StickSlipPhysicsPlugin`]
/// in the same schedule.
pub struct StickSlipFrictionPlugin {
    schedule: InternedScheduleLabel,
}

impl StickSlipFrictionPlugin {
    /// Runs in `schedule` (the physics plugin's).
    pub fn new(schedule: impl ScheduleLabel) -> Self {
        StickSlipFrictionPlugin {
            schedule: schedule.intern(),
        }
    }
}

impl Default for StickSlipFrictionPlugin {
    fn default() -> Self {
        StickSlipFrictionPlugin::new(FixedPostUpdate)
    }
}

impl Plugin for StickSlipFrictionPlugin {
    fn build(&self, app: &mut App) {
        app.init_resource::<DefaultFriction>()
            .init_resource::<ContactReports>()
            .add_message::<RegimeChanged>()
            .add_systems(
                self.schedule,
                (
                    // After creation: new colliders have their handles then.
                    sync_friction
                        .after(sync_changes)
                        .before(apply_inputs)
                        .in_set(StickSlipSystems::Prepare),
                    read_back
                        .after(writeback)
                        .in_set(StickSlipSystems::Writeback),
                ),
            )
            .add_observer(on_remove_friction_law)
            .add_observer(on_remove_vibration)
            .add_observer(on_remove_surface);
    }
}

/// All of stickslip-bevy: [`StickSlipPhysicsPlugin`], [`StickSlipFrictionPlugin`] and, with
/// feature `debug`, `debug::StickSlipDebugPlugin` (which draws
/// only in apps with bevy's `GizmoPlugin`). `StickSlipPlugins::default()` runs in
/// `FixedPostUpdate`, `StickSlipPlugins::new(schedule)` elsewhere; `.build().disable::<P>()`
/// leaves a plugin out.
pub struct StickSlipPlugins {
    schedule: InternedScheduleLabel,
}

impl StickSlipPlugins {
    /// The plugins running in `schedule`.
    pub fn new(schedule: impl ScheduleLabel) -> Self {
        StickSlipPlugins {
            schedule: schedule.intern(),
        }
    }
}

impl Default for StickSlipPlugins {
    fn default() -> Self {
        StickSlipPlugins::new(FixedPostUpdate)
    }
}

impl PluginGroup for StickSlipPlugins {
    fn build(self) -> PluginGroupBuilder {
        let group = PluginGroupBuilder::start::<Self>()
            .add(StickSlipPhysicsPlugin::new(self.schedule))
            .add(StickSlipFrictionPlugin::new(self.schedule));
        #[cfg(feature = "debug")]
        let group = group.add(crate::debug::StickSlipDebugPlugin);
        group
    }
}
