//! The plugins and their system sets.

use crate::contacts::{RegimeChanged, StickSlipContacts, read_back};
use crate::step::{Gravity, apply_inputs, step_world, writeback};
use crate::world::*;
use bevy::app::PluginGroupBuilder;
use bevy::ecs::schedule::{InternedScheduleLabel, ScheduleLabel};
use bevy::prelude::*;
use bevy::transform::TransformSystems;
use stickslip_core::law::Law;
use stickslip_core::sliding_curve::Curve;
use stickslip_rapier::FrictionMaterial;

/// The plugin's systems, chained in this order in its schedule, before transform
/// propagation.
#[derive(SystemSet, Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum StickSlipSystems {
    /// New entities into rapier, friction-layer components, user inputs.
    Prepare,
    /// One step of the rapier world with the stickslip modifier.
    Step,
    /// Poses, velocities and contact reports back onto entities and resources.
    Writeback,
}

/// The rapier bridge: one world, bodies, colliders, velocities, forces, Transform in and out.
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

/// The material of `FrictionLaw(None)` colliders unless the app inserts its own
/// [`DefaultFriction`]: elasto-plastic, break-away at μ_ba = 0.5 after g_ba = 5 µm, sliding
/// at 0.5.
pub fn default_material() -> FrictionMaterial {
    let curve = Curve::constant(0.5).expect("a positive coefficient");
    FrictionMaterial::new(Law::elasto_plastic(1e5, 0.5, 0.5, curve).expect("valid parameters"))
}

impl Plugin for StickSlipPhysicsPlugin {
    fn build(&self, app: &mut App) {
        let material = app
            .world()
            .get_resource::<DefaultFriction>()
            .map_or_else(default_material, |d| d.0.clone());
        app.insert_resource(StickSlipWorld::new(material.clone()))
            .init_resource::<Gravity>();
        if !app.world().contains_resource::<DefaultFriction>() {
            app.insert_resource(DefaultFriction(material));
        }
        app.configure_sets(
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
                (create_objects, sync_friction, apply_inputs)
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

/// The friction layer's read-back and removals: `StickSlipContacts`, `RegimeChanged`, and
/// taking `FrictionLaw`, `Vibration` and `SurfaceVelocity` back out.
pub struct StickSlipFrictionPlugin {
    schedule: InternedScheduleLabel,
}

impl StickSlipFrictionPlugin {
    /// Reads back in `schedule` (the physics plugin's).
    pub fn new(schedule: impl ScheduleLabel) -> Self {
        StickSlipFrictionPlugin {
            schedule: schedule.intern(),
        }
    }
}

impl Plugin for StickSlipFrictionPlugin {
    fn build(&self, app: &mut App) {
        app.init_resource::<StickSlipContacts>()
            .add_message::<RegimeChanged>()
            .add_systems(self.schedule, read_back.in_set(StickSlipSystems::Writeback))
            .add_observer(on_remove_friction_law)
            .add_observer(on_remove_vibration)
            .add_observer(on_remove_surface);
    }
}

/// All of stickslip-bevy: physics bridge, friction layer and (feature `debug`) gizmos.
/// `StickSlipPlugins::default()` runs in `FixedPostUpdate`; `StickSlipPlugins::new(schedule)`
/// elsewhere.
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
