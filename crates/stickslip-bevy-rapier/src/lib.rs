//! stickslip as an add-on to bevy_rapier3d 0.36 (bevy 0.19): a bevy_rapier app keeps its
//! `RapierPhysicsPlugin`, components and systems, and gets stickslip's friction on the
//! colliders it marks with [`StickSlipFriction`].
//!
//! ```no_run
//! use bevy::prelude::*;
//! use bevy_rapier3d::prelude::*;
//! use stickslip_bevy_rapier::{StickSlipFriction, StickSlipHooks, StickSlipRapierPlugin};
//!
//! App::new()
//!     .add_plugins(MinimalPlugins)
//!     .add_plugins(TransformPlugin)
//!     // bevy_rapier with stickslip's hooks, stepped one rapier step per frame.
//!     .insert_resource(TimestepMode::Fixed { dt: 1.0 / 60.0, substeps: 1 })
//!     .add_plugins(RapierPhysicsPlugin::<StickSlipHooks>::default())
//!     .add_plugins(StickSlipRapierPlugin::default())
//!     .add_systems(Startup, |mut commands: Commands| {
//!         commands.spawn((RigidBody::Fixed, Collider::cuboid(5.0, 0.1, 5.0), StickSlipFriction(None)));
//!     })
//!     .run();
//! ```
//!
//! What this first version does and does not: every rapier step is bracketed by
//! `StickSlip::begin_step`/`end_step` when bevy_rapier runs exactly one rapier step per frame
//! (`TimestepMode::Fixed` or `Variable` with `substeps: 1`); any other mode is refused at
//! startup with an error message, and stickslip then leaves the world to rapier's friction
//! (never silently wrong). The app's own `BevyPhysicsHooks` go in as
//! `StickSlipHooks<TheirHooks>` (see [`StickSlipHooks`]).

#![warn(missing_docs)]

#[cfg(feature = "debug")]
pub mod debug;

use bevy::ecs::schedule::ScheduleLabel;
use bevy::ecs::system::{StaticSystemParam, SystemParam, SystemParamItem};
use bevy::prelude::*;
use bevy_rapier3d::pipeline::{ContactModificationContextView, PairFilterContextView};
use bevy_rapier3d::plugin::context::{
    RapierContextColliders, RapierContextSimulation, RapierRigidBodySet,
};
use bevy_rapier3d::prelude::*;
use bevy_rapier3d::rapier::geometry::ColliderHandle;
use bevy_rapier3d::rapier::geometry::SolverFlags;
use bevy_rapier3d::rapier::pipeline::{
    ContactModificationContext, PairFilterContext, PhysicsHooks,
};
use std::collections::HashMap;
use stickslip_core::law::Regime;
use stickslip_rapier_035::{ContactReport, FrictionMaterial, StickSlip, VibrationSource};

/// Puts a collider under stickslip: its pairs get stickslip's friction, with this material
/// (`None`: the plugin's default material).
#[derive(Component, Debug, Clone, PartialEq)]
pub struct StickSlipFriction(pub Option<FrictionMaterial>);

/// A vibration source on a stickslip collider: its contacts feel it (Popov's reduced static
/// and sliding friction, elliptical drives; see `stickslip_rapier::VibrationSource`).
#[derive(Component, Debug, Clone)]
pub struct StickSlipVibration(pub VibrationSource);

/// The velocity of a collider's surface relative to its body (a conveyor belt, m/s, world
/// axes): its contacts' target tangent velocity, on any pair (with or without stickslip).
#[derive(Component, Debug, Clone, Copy, PartialEq)]
pub struct SurfaceVelocity(pub Vec3);

/// A contact read back after the step (with `ReadBack::Contacts` on the modifier), its
/// colliders as entities.
#[derive(Debug, Clone, Copy)]
pub struct EntityContact {
    /// The entity of the report's collider 1.
    pub entity1: Entity,
    /// The entity of the report's collider 2.
    pub entity2: Entity,
    /// What stickslip measured (regime, forces, slip, …).
    pub report: ContactReport,
}

/// The contacts of the last step, as entities (empty unless the modifier reads contacts back:
/// `StickSlipRapier::modifier.set_read_back(ReadBack::Contacts)`).
#[derive(Resource, Debug, Default)]
pub struct StickSlipContacts(pub Vec<EntityContact>);

/// A pair of entities whose contact changed regime (sticking, stick-slip, sliding) in the
/// last step, or began (with contact read-back on). A pair with several manifolds counts as
/// one contact: its first manifold's regime.
#[derive(Message, Debug, Clone, Copy, PartialEq)]
pub struct RegimeChanged {
    /// The entity of the first collider.
    pub entity1: Entity,
    /// The entity of the second collider.
    pub entity2: Entity,
    /// The regime before (`None`: a new contact).
    pub from: Option<Regime>,
    /// The regime now.
    pub to: Regime,
}

/// The regime of each pair in the last step (for [`RegimeChanged`]).
#[derive(Resource, Default)]
struct LastRegimes(HashMap<(Entity, Entity), Regime>);

/// The modifier of the app's rapier context.
#[derive(Resource)]
pub struct StickSlipRapier {
    /// The contact modifier (materials, vibration sources, contact state, reports).
    pub modifier: StickSlip,
    /// Whether the timestep mode can be bracketed (checked at startup).
    pub active: bool,
    attached: HashMap<Entity, ColliderHandle>,
    /// Surface velocities by collider.
    surfaces: HashMap<ColliderHandle, Vec3>,
}

impl StickSlipRapier {
    /// Whether the collider of `entity` is attached to stickslip.
    pub fn is_attached(&self, entity: Entity) -> bool {
        self.attached.contains_key(&entity)
    }
}

/// bevy_rapier's hooks for stickslip: `RapierPhysicsPlugin::<StickSlipHooks>`, or
/// `RapierPhysicsPlugin::<StickSlipHooks<MyHooks>>` with the app's own `BevyPhysicsHooks`
/// (a one-way platform, a conveyor): they run first on every pair and alone on the pairs
/// without a `StickSlipFriction` collider.
#[derive(SystemParam)]
pub struct StickSlipHooks<'w, 's, H: SystemParam + 'static = ()> {
    state: Res<'w, StickSlipRapier>,
    user: StaticSystemParam<'w, 's, H>,
}

/// The app's hooks as rapier hooks (for the time of one call), then the surface velocities.
struct UserHooks<'a, T> {
    user: &'a T,
    surfaces: &'a HashMap<ColliderHandle, Vec3>,
}

impl<T: BevyPhysicsHooks> PhysicsHooks for UserHooks<'_, T> {
    fn filter_contact_pair(&self, context: &PairFilterContext) -> Option<SolverFlags> {
        self.user
            .filter_contact_pair(PairFilterContextView { raw: context })
    }

    fn filter_intersection_pair(&self, context: &PairFilterContext) -> bool {
        self.user
            .filter_intersection_pair(PairFilterContextView { raw: context })
    }

    fn modify_solver_contacts(&self, context: &mut ContactModificationContext) {
        let (c1, c2) = (context.collider1, context.collider2);
        self.user
            .modify_solver_contacts(ContactModificationContextView { raw: &mut *context });
        if self.surfaces.is_empty() {
            return;
        }
        // tangent_velocity is the target velocity of collider 2 relative to collider 1.
        let v = self.surfaces.get(&c1).copied().unwrap_or(Vec3::ZERO)
            - self.surfaces.get(&c2).copied().unwrap_or(Vec3::ZERO);
        if v != Vec3::ZERO {
            let n = *context.normal;
            let v = v - n * n.dot(v);
            for c in context.solver_contacts.iter_mut() {
                c.tangent_velocity += v;
            }
        }
    }
}

impl<H> BevyPhysicsHooks for StickSlipHooks<'_, '_, H>
where
    H: SystemParam + 'static,
    for<'w, 's> SystemParamItem<'w, 's, H>: BevyPhysicsHooks,
{
    fn filter_contact_pair(&self, context: PairFilterContextView) -> Option<SolverFlags> {
        (*self.user).filter_contact_pair(context)
    }

    fn filter_intersection_pair(&self, context: PairFilterContextView) -> bool {
        (*self.user).filter_intersection_pair(context)
    }

    fn modify_solver_contacts(&self, context: ContactModificationContextView) {
        let inner = UserHooks {
            user: &*self.user,
            surfaces: &self.state.surfaces,
        };
        self.state
            .modifier
            .modify_solver_contacts_with(context.raw, &inner);
    }
}

/// Adds stickslip to a bevy_rapier app (see the crate docs).
pub struct StickSlipRapierPlugin {
    /// The material of colliders marked `StickSlipFriction(None)`.
    pub default_material: FrictionMaterial,
    /// The schedule bevy_rapier's physics systems run in (`PostUpdate` unless the app chose
    /// another with `RapierPhysicsPlugin::in_schedule`): stickslip's bracketing runs there.
    pub schedule: bevy::ecs::intern::Interned<dyn ScheduleLabel>,
}

impl Default for StickSlipRapierPlugin {
    fn default() -> Self {
        use stickslip_core::law::Law;
        use stickslip_core::sliding_curve::Curve;
        // EP, c 1e5 1/m, μ_ba 0.5 = μ_max = μ_ve: rapier's default coefficient, sticking.
        let law = Curve::constant(0.5)
            .and_then(|c| Law::elasto_plastic(1e5, 0.5, 0.5, c))
            .unwrap_or_else(|_| Law::Coulomb(stickslip_core::law::Coulomb::clamped(0.5)));
        StickSlipRapierPlugin {
            default_material: FrictionMaterial::new(law),
            schedule: PostUpdate.intern(),
        }
    }
}

impl Plugin for StickSlipRapierPlugin {
    fn build(&self, app: &mut App) {
        app.insert_resource(StickSlipRapier {
            modifier: StickSlip::new(self.default_material.clone()),
            active: true,
            attached: HashMap::new(),
            surfaces: HashMap::new(),
        })
        .init_resource::<StickSlipContacts>()
        .init_resource::<LastRegimes>()
        .add_message::<RegimeChanged>()
        .add_systems(PostStartup, check_timestep_mode)
        .add_systems(
            self.schedule,
            (attach, sync_vibrations, sync_surfaces, begin_step)
                .chain()
                .after(PhysicsSet::SyncBackend)
                .before(PhysicsSet::StepSimulation),
        )
        .add_systems(
            self.schedule,
            end_step
                .after(PhysicsSet::StepSimulation)
                .before(PhysicsSet::Writeback),
        );
    }
}

/// Refuses (with an error) the timestep modes whose rapier steps cannot be bracketed.
fn check_timestep_mode(mode: Res<TimestepMode>, mut state: ResMut<StickSlipRapier>) {
    let ok = matches!(
        *mode,
        TimestepMode::Fixed { substeps: 1, .. } | TimestepMode::Variable { substeps: 1, .. }
    );
    if !ok {
        error!(
            "stickslip: bevy_rapier's {:?} runs several rapier steps per frame, which stickslip \
             cannot bracket yet; use TimestepMode::Fixed or Variable with substeps: 1. stickslip \
             is off: this app has rapier's own friction",
            *mode
        );
        state.active = false;
    }
}

/// Attaches marked colliders once bevy_rapier created them; detaches removed ones.
#[allow(clippy::type_complexity)]
fn attach(
    mut commands: Commands,
    mut state: ResMut<StickSlipRapier>,
    marked: Query<
        (
            Entity,
            &StickSlipFriction,
            &RapierColliderHandle,
            Option<&ActiveHooks>,
        ),
        Or<(Added<RapierColliderHandle>, Changed<StickSlipFriction>)>,
    >,
    mut removed: RemovedComponents<StickSlipFriction>,
    mut colliders: Query<&mut RapierContextColliders>,
) {
    let Ok(mut colliders) = colliders.single_mut() else {
        return;
    };
    let state = &mut *state;
    for entity in removed.read() {
        if let Some(h) = state.attached.remove(&entity) {
            state.modifier.detach(&mut colliders.colliders, h);
        }
    }
    for (entity, friction, handle, hooks) in &marked {
        state
            .modifier
            .attach(&mut colliders.colliders, handle.0, friction.0.clone());
        state.attached.insert(entity, handle.0);
        // bevy_rapier writes a collider's hook flags from this component: keep the user's.
        let flags = hooks.copied().unwrap_or(ActiveHooks::empty());
        commands
            .entity(entity)
            .insert(flags | ActiveHooks::MODIFY_SOLVER_CONTACTS);
    }
}

/// The step's parameters, as bevy_rapier's step will use them.
fn begin_step(
    mut state: ResMut<StickSlipRapier>,
    mode: Res<TimestepMode>,
    time: Res<Time>,
    context: Query<&RapierContextSimulation>,
) {
    if !state.active {
        return;
    }
    let Ok(context) = context.single() else {
        return;
    };
    let mut params = context.integration_parameters;
    params.dt = match *mode {
        TimestepMode::Fixed { dt, .. } => dt,
        TimestepMode::Variable {
            max_dt, time_scale, ..
        } => (time.delta_secs() * time_scale).min(max_dt),
        TimestepMode::Interpolated { .. } => return,
    };
    state.modifier.begin_step(&params);
}

fn end_step(
    mut state: ResMut<StickSlipRapier>,
    mut contacts: ResMut<StickSlipContacts>,
    mut last: ResMut<LastRegimes>,
    mut changed: MessageWriter<RegimeChanged>,
    context: Query<(
        &RapierContextSimulation,
        &RapierRigidBodySet,
        &RapierContextColliders,
    )>,
) {
    if !state.active {
        return;
    }
    let Ok((sim, bodies, colliders)) = context.single() else {
        return;
    };
    state
        .modifier
        .end_step(&sim.narrow_phase, &bodies.bodies, &colliders.colliders);
    contacts.0.clear();
    // bevy_rapier keeps each collider's entity in its user_data.
    let entity = |h: ColliderHandle| {
        colliders
            .colliders
            .get(h)
            .map(|c| Entity::from_bits(c.user_data as u64))
    };
    let Ok(reports) = state.modifier.reports() else {
        return;
    };
    let mut now = HashMap::with_capacity(last.0.len());
    for r in reports {
        let (Some(entity1), Some(entity2)) = (entity(r.collider1), entity(r.collider2)) else {
            continue;
        };
        contacts.0.push(EntityContact {
            entity1,
            entity2,
            report: *r,
        });
        if now.contains_key(&(entity1, entity2)) {
            continue;
        }
        now.insert((entity1, entity2), r.regime);
        let from = last.0.get(&(entity1, entity2)).copied();
        if from != Some(r.regime) {
            changed.write(RegimeChanged {
                entity1,
                entity2,
                from,
                to: r.regime,
            });
        }
    }
    last.0 = now;
}

/// Vibration sources onto the colliders' contacts (and off again).
#[allow(clippy::type_complexity)]
fn sync_vibrations(
    mut state: ResMut<StickSlipRapier>,
    changed: Query<
        (&StickSlipVibration, &RapierColliderHandle),
        Or<(Changed<StickSlipVibration>, Added<RapierColliderHandle>)>,
    >,
    all: Query<&RapierColliderHandle>,
    mut removed: RemovedComponents<StickSlipVibration>,
) {
    for (v, h) in &changed {
        state.modifier.set_vibration(h.0, v.0.clone());
    }
    for entity in removed.read() {
        if let Ok(h) = all.get(entity) {
            state.modifier.remove_vibration(h.0);
        }
    }
}

/// Surface velocities for the hooks (and `ActiveHooks` on their colliders).
#[allow(clippy::type_complexity)]
fn sync_surfaces(
    mut commands: Commands,
    mut state: ResMut<StickSlipRapier>,
    surfaces: Query<(
        Entity,
        &SurfaceVelocity,
        &RapierColliderHandle,
        Option<&ActiveHooks>,
    )>,
) {
    state.surfaces.clear();
    for (entity, v, h, hooks) in &surfaces {
        state.surfaces.insert(h.0, v.0);
        let flags = hooks.copied().unwrap_or(ActiveHooks::empty());
        if !flags.contains(ActiveHooks::MODIFY_SOLVER_CONTACTS) {
            commands
                .entity(entity)
                .insert(flags | ActiveHooks::MODIFY_SOLVER_CONTACTS);
        }
    }
}
