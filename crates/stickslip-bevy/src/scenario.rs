//! Scenario files as entities (feature `scenario`): the TOML scenarios that `stickslip run`
//! steps headless and streams to rerun spawn as bevy entities with this crate's components,
//! and their drivers act on those entities every step.
//!
//! The scenario is validated and built by `stickslip-scenario` first (same typed errors, with
//! field and line, as the CLI); the entities then copy the built rapier objects' values
//! (poses, shapes, friction, materials, vibration sources), and the drivers run through the
//! scenario crate's own [`apply_drivers`], so a scenario behaves in bevy as it does in
//! `stickslip run`.
//!
//! ```
//! use bevy::prelude::*;
//! use bevy::time::TimeUpdateStrategy;
//! use stickslip_bevy::prelude::*;
//! use stickslip_bevy::scenario::{LoadedScenario, Scenario, StickSlipScenarioPlugin, spawn_scenario};
//!
//! let mut app = App::new();
//! app.add_plugins((MinimalPlugins, StickSlipPlugins::default(), StickSlipScenarioPlugin::default()))
//!     .insert_resource(TimeUpdateStrategy::FixedTimesteps(1));
//! spawn_scenario(app.world_mut(), &Scenario::builtin()).expect("a valid scenario");
//! app.update();
//! let loaded = app.world().resource::<LoadedScenario>();
//! assert!(!loaded.bodies.is_empty());
//! ```

use crate::components::*;
use crate::convert::{rot_to_bevy, to_bevy};
use crate::friction::{DefaultFriction, FrictionLaw, Vibration};
use crate::plugin::StickSlipSystems;
use crate::step::{Gravity, apply_inputs};
use crate::world::StickSlipWorld;
use bevy::ecs::schedule::{InternedScheduleLabel, ScheduleLabel};
use bevy::prelude::*;
use rapier3d::prelude as rp;
use stickslip_rapier::FrictionMaterial;
use stickslip_scenario::spec::{BodyKind, ColliderSpec};
use stickslip_scenario::{Driver, apply_drivers};

pub use stickslip_scenario::{BuildError, Scenario, ScenarioError};

/// Runs a loaded scenario's drivers in the physics schedule (`FixedPostUpdate` by default),
/// after the user's inputs and before the step.
pub struct StickSlipScenarioPlugin {
    schedule: InternedScheduleLabel,
}

impl StickSlipScenarioPlugin {
    /// Drives in `schedule` (the physics plugin's).
    pub fn new(schedule: impl ScheduleLabel) -> Self {
        StickSlipScenarioPlugin {
            schedule: schedule.intern(),
        }
    }
}

impl Default for StickSlipScenarioPlugin {
    fn default() -> Self {
        StickSlipScenarioPlugin::new(FixedPostUpdate)
    }
}

impl Plugin for StickSlipScenarioPlugin {
    fn build(&self, app: &mut App) {
        app.add_systems(
            self.schedule,
            drive.after(apply_inputs).in_set(StickSlipSystems::Prepare),
        );
    }
}

/// A body the scenario spawned.
#[derive(Debug, Clone)]
pub struct ScenarioBody {
    /// Its unique name (`NAME`, or `NAME_i` for repeated bodies); also its `Name`.
    pub name: String,
    /// The `[[body]]` it came from.
    pub group: String,
    /// Its type.
    pub kind: BodyKind,
    /// The body entity (its colliders are children).
    pub entity: Entity,
    /// Position at t = 0 (m).
    pub start: Vec3,
}

/// The scenario spawned last by [`spawn_scenario`]: what it is and which entities it made.
#[derive(Resource, Debug, Clone)]
pub struct LoadedScenario {
    /// The scenario's name.
    pub name: String,
    /// What it shows.
    pub description: String,
    /// Its bodies, in file order (repeats expanded).
    pub bodies: Vec<ScenarioBody>,
    /// Its collider entities, in file order.
    pub colliders: Vec<Entity>,
    /// The steps the scenario asks for.
    pub steps: u64,
    /// The simulated time when it was spawned (its drivers' t = 0).
    pub start_time: f64,
    drivers: Vec<Driver>,
}

impl LoadedScenario {
    /// The drivers acting on its bodies (`Driver::body` indexes [`Self::bodies`]).
    pub fn drivers(&self) -> &[Driver] {
        &self.drivers
    }
}

/// Validates and spawns `scenario`: despawns the previously loaded scenario's entities, sets
/// the world (gravity, `Time<Fixed>`'s timestep = the scenario's dt, solver iterations and
/// friction model, the modifier's configuration, [`DefaultFriction`]) and spawns one entity
/// per body with a child per collider. Needs the stickslip plugins (and
/// [`StickSlipScenarioPlugin`] for the drivers). The world's other entities stay.
pub fn spawn_scenario(world: &mut World, scenario: &Scenario) -> Result<(), BuildError> {
    let scene = scenario.build()?;
    despawn_scenario(world);

    world.insert_resource(Gravity(to_bevy(scene.world.gravity)));
    if let Some(mut fixed) = world.get_resource_mut::<Time<Fixed>>() {
        fixed.set_timestep(timestep(scenario.world.dt));
    }
    world.insert_resource(DefaultFriction(scene.stickslip.default_material().clone()));
    let start_time = {
        let mut w = world.resource_mut::<StickSlipWorld>();
        let params = &mut w.physics.integration_parameters;
        params.num_solver_iterations = scene.world.integration_parameters.num_solver_iterations;
        params.friction_model = scene.world.integration_parameters.friction_model;
        w.friction
            .set_config(*scene.stickslip.config())
            .expect("a built scene's configuration is valid");
        w.friction.time()
    };

    let mut bodies = Vec::with_capacity(scene.bodies.len());
    for b in &scene.bodies {
        let rb = &scene.world.bodies[b.handle];
        let spec = scenario.bodies.iter().find(|s| s.name == b.group);
        let pose = rb.position();
        let mut entity = world.spawn((
            Name::new(b.name.clone()),
            match b.kind {
                BodyKind::Fixed => RigidBody::Fixed,
                BodyKind::Dynamic => RigidBody::Dynamic,
                BodyKind::Kinematic => RigidBody::KinematicVelocityBased,
            },
            Transform::from_translation(to_bevy(pose.translation))
                .with_rotation(rot_to_bevy(pose.rotation)),
            Velocity {
                linear: to_bevy(rb.linvel()),
                angular: to_bevy(rb.angvel()),
            },
            Damping {
                linear: rb.linear_damping(),
                angular: rb.angular_damping(),
            },
        ));
        if rb.is_ccd_enabled() {
            entity.insert(Ccd);
        }
        if spec.is_some_and(|s| s.lock_rotations) {
            entity.insert(LockRotations);
        }
        if spec.is_some_and(|s| s.can_sleep) {
            entity.insert(AllowSleep);
        }
        bodies.push(ScenarioBody {
            name: b.name.clone(),
            group: b.group.clone(),
            kind: b.kind,
            entity: entity.id(),
            start: Vec3::from_array(b.start.map(|x| x as f32)),
        });
    }

    let mut colliders = Vec::with_capacity(scene.colliders.len());
    for c in &scene.colliders {
        let rc = &scene.world.colliders[c.handle];
        let body = &bodies[c.body];
        let spec = scenario
            .bodies
            .iter()
            .find(|s| s.name == body.group)
            .and_then(|s| s.colliders.get(c.index));
        let offset = rc.position_wrt_parent().copied().unwrap_or_default();
        let mut entity = world.spawn((
            Collider {
                shape: rc.shared_shape().clone(),
            },
            Transform::from_translation(to_bevy(offset.translation))
                .with_rotation(rot_to_bevy(offset.rotation)),
            Friction(rc.friction()),
            FrictionCombine(stickslip_rapier::combine_rule(rc.friction_combine_rule())),
            Restitution(rc.restitution()),
            ChildOf(body.entity),
        ));
        match spec {
            Some(ColliderSpec { mass: Some(m), .. }) => entity.insert(ColliderMass(*m as f32)),
            // rapier's default density when a scenario gives neither.
            Some(ColliderSpec { density, .. }) => {
                entity.insert(Density(density.unwrap_or(1.0) as f32))
            }
            None => entity.insert(Density(rc.density())),
        };
        if c.stickslip {
            let own: Option<FrictionMaterial> = scene.stickslip.material(c.handle).cloned();
            entity.insert(FrictionLaw(own));
        }
        if let Some(v) = scene.stickslip.vibration(c.handle) {
            entity.insert(Vibration(v.clone()));
        }
        colliders.push(entity.id());
    }

    world.insert_resource(LoadedScenario {
        name: scene.name.clone(),
        description: scenario.description.clone(),
        bodies,
        colliders,
        steps: scene.steps,
        start_time,
        drivers: scene.drivers,
    });
    Ok(())
}

/// The fixed timestep for a scenario's `dt`: a whole number of nanoseconds that bevy's
/// `delta_secs()` turns into exactly the f32 `dt` rapier gets in `stickslip run` (e.g.
/// 1/120 s is 8 333 334 ns, not 8 333 333), so both step the same world the same way.
fn timestep(dt: f64) -> std::time::Duration {
    let target = dt as f32;
    let nanos = (dt * 1e9).round() as u64;
    (nanos.saturating_sub(3)..=nanos + 3)
        .map(std::time::Duration::from_nanos)
        .find(|d| d.as_secs_f32() == target)
        .unwrap_or_else(|| std::time::Duration::from_secs_f64(dt))
}

/// Despawns the loaded scenario's entities (rapier and stickslip state go with them) and
/// removes [`LoadedScenario`]. Nothing happens when none is loaded.
pub fn despawn_scenario(world: &mut World) {
    let Some(loaded) = world.remove_resource::<LoadedScenario>() else {
        return;
    };
    for e in loaded
        .colliders
        .iter()
        .chain(loaded.bodies.iter().map(|b| &b.entity))
    {
        if let Ok(entity) = world.get_entity_mut(*e) {
            entity.despawn();
        }
    }
}

/// The scenario's drivers, at the scenario's time (t = 0 when it was spawned), on the rapier
/// bodies of its entities.
fn drive(loaded: Option<Res<LoadedScenario>>, mut w: ResMut<StickSlipWorld>, time: Res<Time>) {
    let Some(loaded) = loaded else {
        return;
    };
    let dt = time.delta_secs() as f64;
    if loaded.drivers.is_empty() || dt.is_nan() || dt <= 0.0 {
        return;
    }
    let w = &mut *w;
    let t = w.friction.time() - loaded.start_time;
    // The world's own map: bodies created this step have a handle before `RapierBody` lands.
    let handles: Vec<rp::RigidBodyHandle> = loaded
        .bodies
        .iter()
        .map(|b| w.body(b.entity).unwrap_or(rp::RigidBodyHandle::invalid()))
        .collect();
    apply_drivers(
        &loaded.drivers,
        &mut w.physics.bodies,
        |i| handles[i],
        t,
        dt,
    );
}
