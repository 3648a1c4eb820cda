//! Scenario files as bevy_rapier entities (feature `scenario`): the TOML scenarios that
//! `stickslip run` steps headless and streams to rerun spawn as bevy_rapier bodies and child
//! colliders with stickslip's components, and their drivers act on those bodies every step.
//!
//! The scenario is validated and built by `stickslip-scenario` (built against bevy_rapier's
//! rapier 0.35) first — the same typed errors, with field and line, as the CLI; the entities
//! then copy the built rapier objects' values (poses, shapes, friction, materials, vibration
//! sources), and the drivers run through the scenario crate's own `apply_drivers` on
//! bevy_rapier's rigid-body set, so a scenario behaves here as it does in `stickslip run`.
//!
//! ```
//! use bevy::prelude::*;
//! use bevy_rapier3d::prelude::*;
//! use stickslip_bevy_rapier::StickSlipRapierPlugin;
//! use stickslip_bevy_rapier::scenario::{LoadedScenario, Scenario, StickSlipScenarioPlugin, spawn_scenario};
//!
//! let mut app = App::new();
//! app.add_plugins((MinimalPlugins, TransformPlugin))
//!     .add_plugins(RapierPhysicsPlugin::<NoUserData>::default())
//!     .add_plugins((StickSlipRapierPlugin::default(), StickSlipScenarioPlugin::default()));
//! app.update();
//! spawn_scenario(app.world_mut(), &Scenario::builtin()).expect("a valid scenario");
//! app.update();
//! let loaded = app.world().resource::<LoadedScenario>();
//! assert!(!loaded.bodies.is_empty());
//! ```

use crate::state::StickSlipRapier;
use bevy::ecs::schedule::{InternedScheduleLabel, ScheduleLabel};
use bevy::prelude::*;
use bevy_rapier::plugin::context::{
    DefaultRapierContext, RapierContextColliders, RapierContextSimulation, RapierRigidBodySet,
};
use bevy_rapier::prelude::*;
use bevy_rapier::rapier::dynamics::{CoefficientCombineRule as RapierRule, RigidBodyHandle};
use stickslip_bevy::{StickSlipFriction, StickSlipVibration};
use stickslip_scenario_035::spec::{BodyKind, ColliderSpec};
use stickslip_scenario_035::{Driver, apply_drivers};

pub use stickslip_scenario_035::{BuildError, DriverAction, Scenario, ScenarioError};

/// Runs a loaded scenario's drivers before each frame's rapier step, in bevy_rapier's
/// schedule (`PostUpdate` unless it runs elsewhere: give the same schedule).
pub struct StickSlipScenarioPlugin {
    schedule: InternedScheduleLabel,
}

impl StickSlipScenarioPlugin {
    /// Drives in `schedule` (bevy_rapier's).
    pub fn new(schedule: impl ScheduleLabel) -> Self {
        StickSlipScenarioPlugin {
            schedule: schedule.intern(),
        }
    }
}

impl Default for StickSlipScenarioPlugin {
    fn default() -> Self {
        StickSlipScenarioPlugin::new(PostUpdate)
    }
}

impl Plugin for StickSlipScenarioPlugin {
    fn build(&self, app: &mut App) {
        app.add_systems(
            self.schedule,
            (combine_rules, drive)
                .chain()
                .after(PhysicsSet::SyncBackend)
                .before(PhysicsSet::StepSimulation),
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
    /// Mass (kg; 0 for fixed and kinematic bodies).
    pub mass: f32,
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
    /// The box worth looking at (min, max corners, m): the bounding boxes at t = 0 of the
    /// colliders of the bodies that move (of all bodies when none moves).
    pub region: (Vec3, Vec3),
    /// Gravity's magnitude (m/s²).
    pub gravity: f32,
    /// The steps the scenario asks for.
    pub steps: u64,
    /// The scenario's dt (s).
    pub dt: f32,
    /// The simulated time when it was spawned (its drivers' t = 0).
    pub start_time: f64,
    drivers: Vec<Driver>,
}

impl LoadedScenario {
    /// The drivers acting on its bodies (`Driver::body` indexes [`Self::bodies`]).
    pub fn drivers(&self) -> &[Driver] {
        &self.drivers
    }

    /// The heaviest dynamic body's weight (N; 0 without one): the scale of its contact
    /// forces.
    pub fn max_weight(&self) -> f32 {
        let m = self.bodies.iter().map(|b| b.mass).fold(0.0, f32::max);
        m * self.gravity
    }

    /// The camera pose that shows all of [`Self::region`] with a perspective camera of
    /// vertical field of view `fov_y` (rad) and `aspect` (width/height), looking down on it
    /// from the front right.
    pub fn framing(&self, fov_y: f32, aspect: f32) -> Transform {
        let (min, max) = self.region;
        let centre = (min + max) / 2.0;
        let radius = ((max - min).length() / 2.0).max(0.05);
        // The bounding sphere fits the narrower of the two fields of view.
        let half = (fov_y / 2.0).min((aspect * (fov_y / 2.0).tan()).atan());
        let distance = radius / half.sin() * 1.05;
        let eye = centre + Vec3::new(0.5, 1.0, 1.2).normalize() * distance;
        Transform::from_translation(eye).looking_at(centre, Vec3::Y)
    }
}

/// A collider's friction combine rule for rapier, when bevy_rapier's `Friction` cannot say it
/// (`ClampedSum`, `GeometricMean`): written into the rapier collider once it exists.
#[derive(Component, Debug, Clone, Copy)]
struct RapierFrictionRule(RapierRule);

/// bevy_rapier's rule for rapier's, or `None` for the two it does not have.
fn bevy_rule(rule: RapierRule) -> Option<CoefficientCombineRule> {
    match rule {
        RapierRule::Average => Some(CoefficientCombineRule::Average),
        RapierRule::Min => Some(CoefficientCombineRule::Min),
        RapierRule::Multiply => Some(CoefficientCombineRule::Multiply),
        RapierRule::Max => Some(CoefficientCombineRule::Max),
        _ => None,
    }
}

/// Validates and spawns `scenario`: despawns the previously loaded scenario's entities, sets
/// the default rapier context (gravity, solver iterations, friction model), bevy_rapier's
/// `TimestepMode::Fixed` at the scenario's dt with one substep (and `Time<Fixed>`'s timestep
/// to it), the modifier's configuration, and spawns one entity per body with a child per
/// collider. Needs bevy_rapier's plugin, [`crate::StickSlipRapierPlugin`] and (for the
/// drivers) [`StickSlipScenarioPlugin`], after one update (the context exists). The world's
/// other entities stay.
pub fn spawn_scenario(world: &mut World, scenario: &Scenario) -> Result<(), BuildError> {
    let scene = scenario.build()?;
    despawn_scenario(world);

    let dt = scenario.world.dt as f32;
    world.insert_resource(TimestepMode::Fixed { dt, substeps: 1 });
    if let Some(mut fixed) = world.get_resource_mut::<Time<Fixed>>() {
        fixed.set_timestep(timestep(scenario.world.dt));
    }
    let mut contexts = world.query_filtered::<(
        &mut RapierConfiguration,
        &mut RapierContextSimulation,
    ), With<DefaultRapierContext>>();
    for (mut config, mut sim) in contexts.iter_mut(world) {
        config.gravity = scene.world.gravity;
        let params = &mut sim.integration_parameters;
        params.num_solver_iterations = scene.world.integration_parameters.num_solver_iterations;
        params.friction_model = scene.world.integration_parameters.friction_model;
    }
    let start_time = match world.get_resource_mut::<StickSlipRapier>() {
        Some(mut state) => {
            // A built scene's configuration is valid; keep the running one if not.
            let _ = state.modifier.set_config(*scene.stickslip.config());
            state.modifier.time()
        }
        None => 0.0,
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
            Transform::from_translation(pose.translation).with_rotation(pose.rotation),
            Velocity {
                linear: rb.linvel(),
                angular: rb.angvel(),
            },
            Damping {
                linear_damping: rb.linear_damping(),
                angular_damping: rb.angular_damping(),
            },
        ));
        if rb.is_ccd_enabled() {
            entity.insert(Ccd::enabled());
        }
        if spec.is_some_and(|s| s.lock_rotations) {
            entity.insert(LockedAxes::ROTATION_LOCKED);
        }
        if !spec.is_some_and(|s| s.can_sleep) {
            entity.insert(Sleeping::disabled());
        }
        bodies.push(ScenarioBody {
            name: b.name.clone(),
            group: b.group.clone(),
            kind: b.kind,
            entity: entity.id(),
            start: Vec3::from_array(b.start.map(|x| x as f32)),
            mass: if b.kind == BodyKind::Dynamic {
                rb.mass()
            } else {
                0.0
            },
        });
    }

    let mut colliders = Vec::with_capacity(scene.colliders.len());
    let any_moving = scene.bodies.iter().any(|b| b.kind != BodyKind::Fixed);
    let mut region = (Vec3::splat(f32::MAX), Vec3::splat(f32::MIN));
    for c in &scene.colliders {
        let rc = &scene.world.colliders[c.handle];
        let body = &bodies[c.body];
        if !any_moving || body.kind != BodyKind::Fixed {
            let aabb = rc.compute_aabb();
            region.0 = region.0.min(aabb.mins);
            region.1 = region.1.max(aabb.maxs);
        }
        let spec = scenario
            .bodies
            .iter()
            .find(|s| s.name == body.group)
            .and_then(|s| s.colliders.get(c.index));
        let offset = rc.position_wrt_parent().copied().unwrap_or_default();
        let rule = rc.friction_combine_rule();
        let mut entity = world.spawn((
            Collider::from(rc.shared_shape().clone()),
            Transform::from_translation(offset.translation).with_rotation(offset.rotation),
            Friction {
                coefficient: rc.friction(),
                combine_rule: bevy_rule(rule).unwrap_or_default(),
            },
            Restitution {
                coefficient: rc.restitution(),
                combine_rule: bevy_rule(rc.restitution_combine_rule()).unwrap_or_default(),
            },
            ChildOf(body.entity),
        ));
        if bevy_rule(rule).is_none() {
            entity.insert(RapierFrictionRule(rule));
        }
        match spec {
            Some(ColliderSpec { mass: Some(m), .. }) => {
                entity.insert(ColliderMassProperties::Mass(*m as f32))
            }
            // rapier's default density when a scenario gives neither.
            Some(ColliderSpec { density, .. }) => entity.insert(ColliderMassProperties::Density(
                density.unwrap_or(1.0) as f32,
            )),
            None => entity.insert(ColliderMassProperties::Density(rc.density())),
        };
        if c.stickslip {
            // The collider's own material, else the scenario's default (not the plugin's).
            let material = scene
                .stickslip
                .material(c.handle)
                .unwrap_or(scene.stickslip.default_material())
                .clone();
            entity.insert(StickSlipFriction(Some(material)));
        }
        if let Some(v) = scene.stickslip.vibration(c.handle) {
            entity.insert(StickSlipVibration(v.clone()));
        }
        colliders.push(entity.id());
    }
    if region.0.x > region.1.x {
        region = (Vec3::splat(-0.5), Vec3::splat(0.5));
    }

    world.insert_resource(LoadedScenario {
        name: scene.name.clone(),
        description: scenario.description.clone(),
        bodies,
        colliders,
        region,
        gravity: scene.world.gravity.length(),
        steps: scene.steps,
        dt,
        start_time,
        drivers: scene.drivers,
    });
    Ok(())
}

/// The fixed timestep for a scenario's `dt`: a whole number of nanoseconds that bevy's
/// `delta_secs()` turns into exactly the f32 `dt` rapier gets in `stickslip run`.
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

/// The friction rules bevy_rapier's `Friction` cannot carry, onto the new rapier colliders.
fn combine_rules(
    new: Query<(&RapierColliderHandle, &RapierFrictionRule), Added<RapierColliderHandle>>,
    mut context: Query<&mut RapierContextColliders, With<DefaultRapierContext>>,
) {
    let Ok(mut colliders) = context.single_mut() else {
        return;
    };
    for (handle, rule) in &new {
        if let Some(c) = colliders.colliders.get_mut(handle.0) {
            c.set_friction_combine_rule(rule.0);
        }
    }
}

/// The scenario's drivers, at the scenario's time (t = 0 when it was spawned), on the rapier
/// bodies of its entities, before the frame's step (one step of the scenario's dt).
fn drive(
    loaded: Option<Res<LoadedScenario>>,
    state: Res<StickSlipRapier>,
    handles: Query<&RapierRigidBodyHandle>,
    mut context: Query<&mut RapierRigidBodySet, With<DefaultRapierContext>>,
) {
    let Some(loaded) = loaded else {
        return;
    };
    let Ok(mut set) = context.single_mut() else {
        return;
    };
    if loaded.drivers.is_empty() {
        return;
    }
    let t = state.modifier.time() - loaded.start_time;
    let bodies: Vec<RigidBodyHandle> = loaded
        .bodies
        .iter()
        .map(|b| {
            handles
                .get(b.entity)
                .map_or(RigidBodyHandle::invalid(), |h| h.0)
        })
        .collect();
    apply_drivers(
        &loaded.drivers,
        &mut set.bodies,
        |i| bodies[i],
        t,
        loaded.dt as f64,
    );
}
