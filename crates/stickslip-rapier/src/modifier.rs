//! [`StickSlip`]: the contact modifier users add to their rapier world.

use crate::collider_map::{ColliderBits, ColliderMap};
use crate::contact_store::ContactStore;
use crate::measure::measure;
use crate::pair_law::PairLaws;
use crate::quiet::Recycling;
use crate::report::{ContactReport, WorldTotals};
use crate::warnings::{Warned, Warning};
use rapier::prelude::*;
use serde::{Deserialize, Serialize};
use std::sync::atomic::{AtomicBool, Ordering};
use stickslip_core::FrictionMaterial;
use stickslip_core::ParamError;
use stickslip_core::contact::VibrationSource;
use stickslip_core::error::positive;
use stickslip_core::law::Law;

/// Tuning of the rapier realization (validated with [`StickSlipConfig::validate`]).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct StickSlipConfig {
    /// Averaging time (s) of the mean normal force F̄ that sets a compliant law's tangential
    /// stiffness k_t = c·F̄, so that a vibrating load changes the friction limit but not the
    /// stiffness (Popov's constant k_x). Contacts with a vibration source of frequency f
    /// average over at least 5/f whatever this is; the default 1 s covers loads that
    /// oscillate by themselves at ≥ 2 Hz to a few percent. The stiffness only sets the elastic
    /// range g_ba, never the friction limit, so a slow average costs nothing.
    pub stiffness_time: f64,
}

impl Default for StickSlipConfig {
    fn default() -> Self {
        StickSlipConfig {
            stiffness_time: 1.0,
        }
    }
}

impl StickSlipConfig {
    /// Checks the values.
    pub fn validate(&self) -> Result<(), ParamError> {
        positive("stiffness_time", self.stiffness_time)?;
        Ok(())
    }
}

/// The longest time step (s) the modifier steps: beyond it no contact is resolved, and a
/// step of 1e30 s only turns every position infinite.
pub const MAX_DT: f64 = 1.0;

/// The shortest time step (s) the modifier steps: rates like 1/dt stay inside f32 (a
/// subnormal dt would make them infinite), and 1 ns is far below any time-resolved
/// vibration's needs.
pub const MIN_DT: f64 = 1e-9;

/// Whether `dt` is a time step the modifier steps: in [[`MIN_DT`], [`MAX_DT`]].
pub fn valid_dt(dt: f64) -> bool {
    (MIN_DT..=MAX_DT).contains(&dt)
}

/// Step timing the hook needs (rapier does not pass it).
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct Clock {
    pub time: f64,
    pub dt: f64,
    pub step: u32,
    /// Whether rapier clusters a composite pair's manifolds for the solver this step
    /// (`IntegrationParameters::contact_clustering`): then a composite pair's records are
    /// keyed by contact patch, not by sub-shape pair.
    pub clustering: bool,
    /// Sweeps of the contact store so far; the hook marks the records it touches with the
    /// next sweep's number.
    pub sweeps: u32,
    /// Between `begin_step` and `end_step`: the hook may run.
    pub open: bool,
}

impl Clock {
    /// The mark of records touched now (the number of the next sweep).
    pub fn mark(&self) -> u32 {
        self.sweeps.wrapping_add(1)
    }
}

/// Whether rapier holds a manifold carrying `user_data` between the colliders at arena
/// indices `c1` and `c2` (a sleeping contact keeps its state; a vanished one does not).
fn holds_manifold(
    narrow_phase: &NarrowPhase,
    colliders: &ColliderSet,
    c1: u32,
    c2: u32,
    user_data: u32,
) -> bool {
    let (Some((_, h1)), Some((_, h2))) =
        (colliders.get_unknown_gen(c1), colliders.get_unknown_gen(c2))
    else {
        return false;
    };
    narrow_phase.contact_pair(h1, h2).is_some_and(|pair| {
        pair.solver_manifolds()
            .iter()
            .any(|m| m.data.user_data == user_data)
    })
}

/// What was asked of [`StickSlip::reports`] or [`StickSlip::totals`] is not read back: the
/// modifier's [`ReadBack`] is below what it needs (an empty slice or zero totals would be
/// indistinguishable from a world without contacts).
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
#[error(
    "stickslip does not read this back: it needs ReadBack::{needed:?}, read-back is \
     ReadBack::{set:?} (set it with StickSlip::set_read_back)"
)]
pub struct NotReadBack {
    /// The read-back the accessor needs.
    pub needed: ReadBack,
    /// The read-back that is set.
    pub set: ReadBack,
}

/// What [`StickSlip::end_step`] reads back from the solver after each step.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Default, Serialize, Deserialize)]
pub enum ReadBack {
    /// Nothing: [`StickSlip::totals`] and [`StickSlip::reports`] return [`NotReadBack`], and the
    /// end-of-step pass over the narrow phase (which also drops the state of vanished contacts
    /// and keeps that of sleeping ones) runs only every [`SWEEP_INTERVAL`] steps (sooner
    /// where contacts come and go: once the store has made records for 1/16 of its slots). The
    /// friction itself is the same in every mode; this is the cheapest (default).
    #[default]
    Off,
    /// [`StickSlip::totals`] after every step (contacts by regime, forces, dissipated power
    /// and energy).
    Totals,
    /// The totals and a [`ContactReport`] per contact manifold ([`StickSlip::reports`]), ~100
    /// bytes a contact.
    Contacts,
}

/// Steps between two sweeps of the contact store when nothing is read back
/// ([`ReadBack::Off`]): the state of a vanished contact lingers at most this many steps.
#[doc(hidden)]
pub const SWEEP_INTERVAL: u32 = 8;

/// The stickslip contact modifier: implements rapier's [`PhysicsHooks`], replacing plain
/// Coulomb friction by a [`stickslip_core::law::Law`] on the pairs with an attached collider
/// ([`Self::attach`]; materials combine like rapier's coefficients, see
/// [`Self::set_pair_material`]), with vibration sources, and optionally wrapping the user's
/// own hooks `H` (filters, one-way platforms, conveyors), which run first. Pairs without an
/// attached collider go to `H` untouched.
///
/// Per step: [`StickSlip::begin_step`], `pipeline.step(.., &modifier, ..)`,
/// [`StickSlip::end_step`] — or [`StickSlip::step`] on a [`PhysicsWorld`], which does all three.
pub struct StickSlip<H = ()> {
    pub(crate) config: StickSlipConfig,
    /// Materials, per-pair overrides and combined laws (see `pair_law`).
    pub(crate) laws: PairLaws,
    /// Colliders attached (their pairs are stickslip's), default material or not.
    pub(crate) attached: ColliderBits,
    pub(crate) vibrations: ColliderMap<VibrationSource>,
    /// Surface velocities (see `surface`).
    pub(crate) surfaces: ColliderMap<Vector>,
    /// Colliders whose hook flag `attach` turned on.
    pub(crate) flagged: ColliderBits,
    pub(crate) warned: Warned,
    pub(crate) store: ContactStore,
    pub(crate) clock: Clock,
    pub(crate) inner: H,
    /// Whether the wrapped hook gave any contact a surface velocity (a conveyor) this step;
    /// if not, the reports' slip subtracts none (the solver contacts' target velocities after
    /// the step also hold stickslip's own). Reset by `begin_step`: a function of the step.
    pub(crate) moving_surfaces: AtomicBool,
    /// What [`Self::end_step`] reads back (nothing by default).
    pub(crate) read_back: ReadBack,
    pub(crate) reports: Vec<ContactReport>,
    pub(crate) totals: WorldTotals,
    /// Contact patches of composite shapes the hook saw this step (pair and our `user_data`):
    /// rapier rebuilds a clustered manifold every step and carries its impulses over by
    /// nearest position, stale points' included, so the next hook cannot read the last solve
    /// from it; `end_step` measures these right after the solve instead. The colliders by
    /// arena index (12 bytes a patch, not 20): the manifold's `user_data` tells it apart.
    pub(crate) patches_seen: std::sync::Mutex<Vec<(u32, u32, u32)>>,
    /// What `end_step` measured for those patches, by `user_data`.
    pub(crate) patches_measured: crate::patches::PatchMeasures,
    /// Which attached colliders have their flag off because their contacts are quiet (see
    /// `recycle`).
    pub(crate) recycling: Recycling,
    /// The joints and states of the pairs that resist rolling or spinning (see `rolling`).
    pub(crate) rolling: crate::rolling::Rolling,
}

impl StickSlip<()> {
    /// A modifier whose contacts default to `material`.
    pub fn new(material: impl Into<FrictionMaterial>) -> Self {
        StickSlip::with_hooks(material, ())
    }
}

impl<H> StickSlip<H> {
    /// A modifier wrapping the user's hooks `inner`, called on the pairs rapier would call
    /// them for without stickslip (a `MODIFY_SOLVER_CONTACTS` flag [`Self::attach`] turned on
    /// is stickslip's, not theirs).
    pub fn with_hooks(material: impl Into<FrictionMaterial>, inner: H) -> Self {
        StickSlip {
            config: StickSlipConfig::default(),
            laws: PairLaws::new(material.into()),
            attached: ColliderBits::default(),
            warned: Warned::default(),
            vibrations: ColliderMap::default(),
            surfaces: ColliderMap::default(),
            flagged: ColliderBits::default(),
            store: ContactStore::default(),
            clock: Clock::default(),
            inner,
            moving_surfaces: AtomicBool::new(false),
            read_back: ReadBack::Off,
            reports: Vec::new(),
            totals: WorldTotals::default(),
            patches_seen: Default::default(),
            patches_measured: Default::default(),
            recycling: Recycling::default(),
            rolling: Default::default(),
        }
    }

    /// Sets what is read back after each step (builder form of [`Self::set_read_back`]).
    pub fn with_read_back(mut self, read_back: ReadBack) -> Self {
        self.set_read_back(read_back);
        self
    }

    /// Sets what [`Self::end_step`] reads back: nothing (the default, cheapest), the world
    /// [`Self::totals`], or the totals and a report per contact ([`Self::reports`]). The
    /// friction is the same in every mode. Turning reports off frees their memory.
    pub fn set_read_back(&mut self, read_back: ReadBack) {
        self.read_back = read_back;
        if read_back != ReadBack::Contacts {
            self.reports = Vec::new();
        }
        if read_back == ReadBack::Off {
            self.totals = WorldTotals::default();
        }
    }

    /// What is read back after each step (see [`Self::set_read_back`]).
    pub fn read_back(&self) -> ReadBack {
        self.read_back
    }

    /// Replaces the tuning.
    pub fn with_config(mut self, config: StickSlipConfig) -> Result<Self, ParamError> {
        config.validate()?;
        self.config = config;
        Ok(self)
    }

    /// Replaces the tuning of a running modifier (validated first; nothing changes on error).
    pub fn set_config(&mut self, config: StickSlipConfig) -> Result<(), ParamError> {
        config.validate()?;
        self.config = config;
        self.recycling.wake_all = true;
        Ok(())
    }

    /// The tuning in use.
    pub fn config(&self) -> &StickSlipConfig {
        &self.config
    }

    /// The material of attached colliders that have none of their own.
    pub fn default_material(&self) -> &FrictionMaterial {
        self.laws.default_material()
    }

    /// The material a collider was given (`None`: it uses the default, or is not attached).
    pub fn material(&self, collider: ColliderHandle) -> Option<&FrictionMaterial> {
        self.laws.material(collider)
    }

    /// Whether `collider`'s contacts are quiet and rapier recycles them: stickslip turned its
    /// hook flag off (see [`Self::end_step`]).
    pub fn is_recycled(&self, collider: ColliderHandle) -> bool {
        self.recycling.quiet.contains(collider) && self.attached.contains(collider)
    }

    /// Tests only, not API: `Some(true)` makes the pass after each step judge only the pairs
    /// of the colliders that may go quiet (found through rapier's adjacency lists),
    /// `Some(false)` every contact pair, `None` (the default) whichever reads fewer pairs. The
    /// decisions are the same either way.
    #[doc(hidden)]
    pub fn set_pass_walks_pairs(&mut self, walk: Option<bool>) {
        self.recycling.walk = walk;
    }

    /// Whether stickslip decides the friction of the pair: one of them was attached.
    pub(crate) fn owns(&self, c1: ColliderHandle, c2: ColliderHandle) -> bool {
        self.attached.contains(c1) || self.attached.contains(c2)
    }

    /// The law stickslip gives the pair `(a, b)` of `colliders` (the pair's own material, or
    /// the two sides combined; see [`StickSlip::attach`]); `None` when neither is attached
    /// (the pair is rapier's and the wrapped hooks'). The same whichever is first.
    pub fn pair_law(
        &self,
        colliders: &ColliderSet,
        a: ColliderHandle,
        b: ColliderHandle,
    ) -> Option<Law> {
        self.owns(a, b).then(|| {
            self.laws
                .with_pair_law(&self.attached, colliders, (a, b), &self.warned, Law::clone)
        })
    }

    /// Whether `collider` is attached ([`Self::attach`]): its pairs are stickslip's.
    pub fn is_attached(&self, collider: ColliderHandle) -> bool {
        self.attached.contains(collider)
    }

    /// Gives the pair `(a, b)` its own material, whatever the two colliders' materials and
    /// combine rules are (a per-pair table, as Box2D and Godot users ask for). The pair must
    /// have an attached collider to be stickslip's. Order does not matter.
    pub fn set_pair_material(
        &mut self,
        a: ColliderHandle,
        b: ColliderHandle,
        material: impl Into<FrictionMaterial>,
    ) {
        self.laws.set_pair(a, b, material.into());
        self.recycling.wake(a);
        self.recycling.wake(b);
    }

    /// Removes a pair's own material (it combines its colliders' again).
    pub fn remove_pair_material(
        &mut self,
        a: ColliderHandle,
        b: ColliderHandle,
    ) -> Option<FrictionMaterial> {
        self.recycling.wake(a);
        self.recycling.wake(b);
        self.laws.remove_pair(a, b)
    }

    /// A pair's own material ([`Self::set_pair_material`]).
    pub fn pair_material(&self, a: ColliderHandle, b: ColliderHandle) -> Option<&FrictionMaterial> {
        self.laws.pair(a, b)
    }

    /// The wrapped hooks.
    pub fn inner(&self) -> &H {
        &self.inner
    }

    /// The wrapped hooks, mutably.
    pub fn inner_mut(&mut self) -> &mut H {
        &mut self.inner
    }

    /// Opts `collider` in: its pairs become stickslip's. Turns on its
    /// `MODIFY_SOLVER_CONTACTS` hook and gives it `material` (or the default when `None`).
    ///
    /// A pair's law: its own material if [`Self::set_pair_material`] gave it one; else the two
    /// sides combined by the higher of their rapier `friction_combine_rule`s (rapier's order),
    /// an attached side bringing its material, an unattached side its rapier `friction` as
    /// plain Coulomb (see `stickslip_core::law::CombineRule` for how each coefficient, the
    /// stiffness and the law kind combine). Pairs without an attached collider are never
    /// touched: they go to the wrapped hooks with rapier's friction.
    pub fn attach(
        &mut self,
        colliders: &mut ColliderSet,
        collider: ColliderHandle,
        material: Option<FrictionMaterial>,
    ) {
        // A handle that is not in the set is a no-op (never an allocation by its index).
        if !colliders.contains(collider) {
            return;
        }
        if let Some(c) = colliders.get_mut(collider) {
            // Ours to turn off again in `detach` if we turn it on; a flag the user set stays
            // theirs (their wrapped hook runs on its pairs). Attaching again (a new material)
            // keeps what was decided when the collider was first attached, unless the flag
            // has been turned off since (then stickslip's again). (The set keeps no
            // generations: detach a collider before removing it.)
            let theirs = c
                .active_hooks()
                .contains(ActiveHooks::MODIFY_SOLVER_CONTACTS)
                && !self.flagged.contains(collider);
            if !self.attached.contains(collider) || !theirs {
                self.flagged.set(collider, !theirs);
            }
            c.set_active_hooks(c.active_hooks() | ActiveHooks::MODIFY_SOLVER_CONTACTS);
        }
        // The flag is on again: its pairs are hooked next step.
        self.recycling.quiet.set(collider, false);
        self.recycling.poses.remove(collider);
        self.recycling.active.cover(collider);
        self.attached.set(collider, true);
        match material {
            Some(m) => self.laws.set_material(collider, m),
            None => self.laws.clear_material(collider),
        }
    }

    /// Says whether the `MODIFY_SOLVER_CONTACTS` flag of an attached collider or a moving
    /// surface is also the user's — their own hooks need it on every step — for integrations
    /// that learn it only after [`Self::attach`] or [`Self::set_surface_velocity`] (bevy's
    /// `ActiveHooks` component, which bevy_rapier writes into rapier's collider whenever it
    /// changes). stickslip is the one owner of that answer: the user's hooks run on the pairs
    /// of colliders whose flag is the user's, and only there. When it is the user's, stickslip
    /// keeps the flag on and the collider's pairs are never recycled; when it is not, the flag
    /// is stickslip's, which turns it off while the collider's contacts are quiet (see the
    /// `recycle` module) and off in [`Self::detach`] or [`Self::remove_surface_velocity`] once
    /// nothing of stickslip's needs it. Either way the flag is on now and the collider's pairs
    /// are hooked in the next step. Any other collider is left alone.
    pub fn set_user_hook_flag(
        &mut self,
        colliders: &mut ColliderSet,
        collider: ColliderHandle,
        users: bool,
    ) {
        if !self.attached.contains(collider) && self.surfaces.get(collider).is_none() {
            return;
        }
        let Some(c) = colliders.get_mut(collider) else {
            return;
        };
        c.set_active_hooks(c.active_hooks() | ActiveHooks::MODIFY_SOLVER_CONTACTS);
        self.flagged.set(collider, !users);
        self.recycling.quiet.set(collider, false);
        self.recycling.poses.remove(collider);
        self.recycling.active.cover(collider);
    }

    /// Takes `collider` back out of stickslip: drops its material, vibration source, every
    /// contact state and report involving it, and turns its `MODIFY_SOLVER_CONTACTS` hook off
    /// again if [`Self::attach`] turned it on (a flag the user had set stays, for their own
    /// hooks). Its contacts then behave exactly as in plain rapier.
    pub fn detach(&mut self, colliders: &mut ColliderSet, collider: ColliderHandle) {
        if let Some(c) = colliders.get_mut(collider) {
            // A moving surface keeps the flag its velocity needs.
            if self.flagged.contains(collider) && self.surfaces.get(collider).is_none() {
                self.flagged.set(collider, false);
                c.set_active_hooks(c.active_hooks() - ActiveHooks::MODIFY_SOLVER_CONTACTS);
            }
            // Without hooks rapier may recycle the pair's manifolds next step, keeping the
            // friction coefficient this modifier wrote: mark the collider's groups changed
            // (same value) so that its pairs get a full update with rapier's own friction.
            let groups = c.solver_groups();
            c.set_solver_groups(InteractionGroups::none());
            c.set_solver_groups(groups);
        }
        self.attached.set(collider, false);
        self.recycling.quiet.set(collider, false);
        self.recycling.poses.remove(collider);
        self.laws.remove_collider(collider);
        self.vibrations.remove(collider);
        self.store.remove_collider(collider);
        self.reports
            .retain(|r| r.collider1 != collider && r.collider2 != collider);
    }

    /// Sets the material of a collider (it takes effect once the collider is attached, see
    /// [`Self::attach`]). A handle whose index no collider set of this process could hold
    /// (≥ 2²⁴) is ignored.
    pub fn set_material(&mut self, collider: ColliderHandle, material: FrictionMaterial) {
        self.laws.set_material(collider, material);
        self.recycling.wake(collider);
    }

    /// Gives `collider`'s surface a velocity relative to its body (m/s, world axes; a
    /// conveyor belt): the target tangent velocity of each of its contacts, on every pair —
    /// stickslip's or not — after the user's own hooks (see the `surface` module). Turns the
    /// collider's `MODIFY_SOLVER_CONTACTS` hook on (stickslip's, off again with
    /// [`Self::remove_surface_velocity`] unless the collider is attached or the flag was the
    /// user's), and keeps the bodies it carries awake ([`Self::wake_driven`]). A zero velocity
    /// removes it. A handle not in `colliders` is a no-op.
    pub fn set_surface_velocity(
        &mut self,
        colliders: &mut ColliderSet,
        collider: ColliderHandle,
        velocity: Vector,
    ) {
        if velocity == Vector::ZERO || !velocity.is_finite() {
            self.remove_surface_velocity(colliders, collider);
            return;
        }
        let Some(c) = colliders.get_mut(collider) else {
            return;
        };
        if !c
            .active_hooks()
            .contains(ActiveHooks::MODIFY_SOLVER_CONTACTS)
        {
            c.set_active_hooks(c.active_hooks() | ActiveHooks::MODIFY_SOLVER_CONTACTS);
            self.flagged.set(collider, true);
        }
        self.surfaces.insert(collider, velocity);
        self.recycling.wake(collider);
    }

    /// Stops `collider`'s surface (see [`Self::set_surface_velocity`]); returns the velocity
    /// it had.
    pub fn remove_surface_velocity(
        &mut self,
        colliders: &mut ColliderSet,
        collider: ColliderHandle,
    ) -> Option<Vector> {
        let v = self.surfaces.remove(collider)?;
        if !self.attached.contains(collider)
            && self.flagged.contains(collider)
            && let Some(c) = colliders.get_mut(collider)
        {
            c.set_active_hooks(c.active_hooks() - ActiveHooks::MODIFY_SOLVER_CONTACTS);
            self.flagged.set(collider, false);
        }
        self.recycling.wake(collider);
        Some(v)
    }

    /// The surface velocity of `collider` ([`Self::set_surface_velocity`]).
    pub fn surface_velocity(&self, collider: ColliderHandle) -> Option<Vector> {
        self.surfaces.get(collider).copied()
    }

    /// Wakes the dynamic bodies touching a moving surface or a collider with a vibration
    /// source: such a surface is never at rest, though rapier sees no force on what it
    /// carries. [`Self::step`] does it before every step; call it before
    /// [`Self::begin_step`] when stepping rapier yourself.
    pub fn wake_driven(
        &self,
        narrow_phase: &NarrowPhase,
        colliders: &ColliderSet,
        bodies: &mut RigidBodySet,
    ) {
        if self.surfaces.is_empty() && self.vibrations.is_empty() {
            return;
        }
        let drivers = self
            .surfaces
            .iter()
            .map(|(h, _)| h)
            .chain(self.vibrations.iter().map(|(h, _)| h));
        crate::surface::wake_carried(drivers, narrow_phase, colliders, bodies);
    }

    /// Attaches a vibration source to a collider; its contacts feel it. A handle whose index no
    /// collider set could hold (≥ 2²⁴, e.g. `ColliderHandle::invalid()`) is ignored.
    pub fn set_vibration(&mut self, collider: ColliderHandle, source: VibrationSource) {
        self.recycling.wake(collider);
        self.vibrations.insert(collider, source);
    }

    /// Removes a collider's vibration source.
    pub fn remove_vibration(&mut self, collider: ColliderHandle) -> Option<VibrationSource> {
        self.recycling.wake(collider);
        self.vibrations.remove(collider)
    }

    /// The vibration source of a collider.
    pub fn vibration(&self, collider: ColliderHandle) -> Option<&VibrationSource> {
        self.vibrations.get(collider)
    }

    /// Call before each step with the step's parameters and the world's bodies and colliders
    /// (stickslip hooks again, through their flags, the quiet contacts whose material,
    /// source or pose changed since the last step; see [`Self::end_step`]).
    ///
    /// A step whose `dt` is not a time step ([`valid_dt`]: non-finite, or outside
    /// [[`MIN_DT`], [`MAX_DT`]]) is skipped by the modifier: no contact state, clock or total changes
    /// (rapier's own step with such a dt is the caller's; [`Self::step`] skips both); one that
    /// is not 0 (a pause) logs a one-time warning.
    ///
    /// stickslip realizes its law with one friction constraint per manifold
    /// (`FrictionModel::Simplified`, rapier's 3D default); a world with another friction model
    /// is stepped all the same, with a one-time warning through `log`.
    pub fn begin_step(
        &mut self,
        params: &IntegrationParameters,
        bodies: &RigidBodySet,
        colliders: &mut ColliderSet,
    ) {
        // 2D has one friction model: Coulomb friction per contact point along one tangent.
        #[cfg(not(dim2))]
        if params.friction_model != FrictionModel::Simplified {
            self.warned.once(
                Warning::FrictionModel,
                &format!(
                    "stickslip: the world uses {:?}; stickslip keeps one friction state per \
                     contact manifold and needs FrictionModel::Simplified (rapier's 3D \
                     default): friction and reports of this world are approximate",
                    params.friction_model
                ),
            );
        }
        self.clock.open = true;
        let dt = params.dt as f64;
        // dt = 0 is a paused game (bevy's time scale 0): nothing to say.
        if !valid_dt(dt) && dt != 0.0 {
            self.warned.once(
                Warning::StepDt,
                &format!(
                    "stickslip: a step of dt = {dt} s is outside [{MIN_DT}, {MAX_DT}] s; \
                     stickslip leaves such steps to rapier's friction"
                ),
            );
        }
        // A skipped step (dt 0) leaves the step count, and `end_step` everything else, as is.
        let dt = if valid_dt(dt) { dt } else { 0.0 };
        if dt != self.clock.dt && dt > 0.0 {
            // `end_step` did the recycled contacts' step with the last dt.
            self.recycling.wake_all = true;
        }
        self.clock.dt = dt;
        if dt > 0.0 {
            self.clock.step = self.clock.step.wrapping_add(1);
        }
        self.clock.clustering = params.contact_clustering;
        *self.moving_surfaces.get_mut() = false;
        self.recycling.window = crate::rapier_compat::recycle_window(params);
        // Contact detections inside a step (CCD passes) see velocities the judgement after
        // a step cannot bound: no pair is then taken to stay apart.
        self.recycling.prediction = if params.max_ccd_substeps > 1 {
            f32::INFINITY
        } else {
            params.prediction_distance()
        };
        self.wake_before_step(bodies, colliders);
    }

    /// Call after each step: lets rapier recycle the pairs whose contacts are all quiet
    /// (holding well inside their limit, nothing driving them: the hook would write the same
    /// again) by turning stickslip's hook flag off on their colliders, and on again on those
    /// that stop being quiet (see the `recycle` module docs); sums the totals and builds the
    /// reports (as [`Self::read_back`] asks) and drops the state of contacts whose manifold
    /// rapier no longer holds (rapier never says when one disappears; with nothing read back,
    /// every [`SWEEP_INTERVAL`] steps, or sooner where contacts come and go).
    pub fn end_step(
        &mut self,
        narrow_phase: &NarrowPhase,
        bodies: &RigidBodySet,
        colliders: &mut ColliderSet,
    ) {
        let dt = self.clock.dt;
        self.clock.open = false;
        if !(dt > 0.0) {
            // A skipped step (see `begin_step`): no state, total or report changes.
            return;
        }
        self.clock.time += dt;
        self.measure_patches(narrow_phase, dt);
        // Reports first: they tell the step just solved, and settling does the next step of
        // the contacts it lets rapier recycle.
        // Settling marks the records it reads as touched in this step, as the hook does.
        let mark = self.clock.mark();
        self.read_back_step(narrow_phase, bodies, colliders, dt);
        self.settle_after_step(narrow_phase, bodies, colliders, mark);
        // Settling measured more patches: sorted for the next step's hooks.
        self.patches_measured.seal();
    }

    /// The totals and reports of the step just solved (as [`Self::read_back`] asks), and the
    /// sweep of records whose manifold rapier no longer holds.
    fn read_back_step(
        &mut self,
        narrow_phase: &NarrowPhase,
        bodies: &RigidBodySet,
        colliders: &ColliderSet,
        dt: f64,
    ) {
        let read_back = self.read_back;
        let mark = self.clock.mark();
        if read_back == ReadBack::Off {
            if self.clock.step.is_multiple_of(SWEEP_INTERVAL) || self.store.churned() {
                // Nothing to read back: only the records the hook did not see since the last
                // sweep (sleeping or vanished contacts) are looked up in the narrow phase.
                self.store.sweep_untouched(mark, |c1, c2, user_data| {
                    holds_manifold(narrow_phase, colliders, c1, c2, user_data)
                });
                self.clock.sweeps = mark;
            }
            return;
        }
        self.reports.clear();
        let mut totals = WorldTotals {
            dissipated_energy: self.totals.dissipated_energy,
            ..WorldTotals::default()
        };
        let records = self.store.records();
        for pair in narrow_phase.contact_pairs() {
            for m in pair.solver_manifolds() {
                // Marks the record alive (a sleeping pair's manifold keeps its state).
                let Some(rec) =
                    records.touch(m.data.user_data, pair.collider1, pair.collider2, mark)
                else {
                    continue;
                };
                if m.data.solver_contacts.is_empty() || !(dt > 0.0) {
                    continue;
                }
                let report = crate::read_back::report(
                    m,
                    &rec,
                    (pair.collider1, pair.collider2),
                    bodies,
                    colliders,
                    dt,
                    self.moving_surfaces.load(Ordering::Relaxed),
                );
                totals.contacts += 1;
                totals.reset += usize::from(report.reset);
                match report.regime {
                    stickslip_core::law::Regime::Sticking => totals.sticking += 1,
                    stickslip_core::law::Regime::StickSlip => totals.stick_slip += 1,
                    stickslip_core::law::Regime::Sliding => totals.sliding += 1,
                }
                totals.normal_force += report.normal_force;
                totals.friction_force += report.effective_mu() * report.normal_force;
                totals.dissipated_power += report.dissipated_power;
                if read_back == ReadBack::Contacts {
                    self.reports.push(report);
                }
            }
        }
        // Everything rapier no longer holds a manifold for goes now.
        self.store.sweep(mark);
        self.clock.sweeps = mark;
        totals.dissipated_energy += totals.dissipated_power * dt;
        self.totals = totals;
    }

    /// Measures the contact patches of composite shapes the hook saw, right after the solve.
    fn measure_patches(&mut self, narrow_phase: &NarrowPhase, dt: f64) {
        let seen = self
            .patches_seen
            .get_mut()
            .unwrap_or_else(|e| e.into_inner());
        self.patches_measured.clear();
        for (c1, c2, user_data) in seen.drain(..) {
            let Some(pair) = narrow_phase.contact_pair_unknown_gen(c1, c2) else {
                continue;
            };
            if let Some(m) = pair
                .solver_manifolds()
                .iter()
                .find(|m| m.data.user_data == user_data)
            {
                self.patches_measured
                    .insert(user_data, measure(m, &m.data.solver_contacts, dt, None));
            }
        }
        // Sorted now: settling measures some of these again (see `PatchMeasures::insert`).
        self.patches_measured.seal();
    }

    /// Rolling and spinning resistance for the coming step (see
    /// [`FrictionMaterial::with_rolling`]): steps the resisting laws of the touching pairs whose
    /// materials ask for it and sets their joints' motors in `joints` (one impulse joint per
    /// such pair, which stickslip adds and removes; a collider without a body hangs its
    /// joints from one fixed body stickslip adds to `bodies`). [`Self::step`] calls it; when you step
    /// rapier yourself, call it after [`Self::begin_step`] and before rapier's step. Does
    /// nothing (and costs one look over the materials) when no material resists rotation.
    /// In 2D a material resists rolling only (spinning needs a third dimension).
    pub fn resist_rotation(
        &mut self,
        params: &IntegrationParameters,
        joints: &mut ImpulseJointSet,
        narrow_phase: &NarrowPhase,
        bodies: &mut RigidBodySet,
        colliders: &ColliderSet,
    ) {
        let dt = self.clock.dt;
        if !(dt > 0.0) || (self.rolling.is_empty() && !self.laws.any_rotation()) {
            return;
        }
        let (laws, attached) = (&self.laws, &self.attached);
        self.rolling.before_step(
            joints,
            params.num_solver_iterations.max(1),
            narrow_phase,
            bodies,
            colliders,
            dt,
            self.clock.time,
            self.config.stiffness_time,
            |c1, c2| laws.rotation_laws(attached, colliders, (c1, c2)),
        );
    }

    /// What the pairs resisting rolling or spinning did in the last step (see
    /// [`FrictionMaterial::with_rolling`]): regimes, torque caps and the torques the solver
    /// applied (from the motors' impulses of their joints in `joints`, the world's
    /// `impulse_joints`), one report per touching pair whose materials resist, in collider
    /// order. Needs no [`ReadBack`]: it reads what the resistance keeps anyway.
    pub fn rolling_reports(&self, joints: &ImpulseJointSet) -> Vec<crate::RollingReport> {
        self.rolling.reports(joints)
    }

    /// One step of `world` with this modifier (and no event handler of yours: pass one with
    /// [`Self::step_with_events`]).
    pub fn step(&mut self, world: &mut PhysicsWorld)
    where
        H: PhysicsHooks,
    {
        self.step_with_events(world, &());
    }

    /// One step of `world` with this modifier and `events`. A `dt` that is not a time step
    /// ([`valid_dt`]) skips the step: neither rapier nor the modifier changes anything.
    pub fn step_with_events(&mut self, world: &mut PhysicsWorld, events: &dyn EventHandler)
    where
        H: PhysicsHooks,
    {
        if !valid_dt(world.integration_parameters.dt as f64) {
            return;
        }
        self.wake_driven(&world.narrow_phase, &world.colliders, &mut world.bodies);
        self.begin_step(
            &world.integration_parameters,
            &world.bodies,
            &mut world.colliders,
        );
        self.resist_rotation(
            &world.integration_parameters,
            &mut world.impulse_joints,
            &world.narrow_phase,
            &mut world.bodies,
            &world.colliders,
        );
        world.step_with_events(&*self, events);
        self.end_step(&world.narrow_phase, &world.bodies, &mut world.colliders);
    }

    /// Per-contact reports of the last step: one per contact manifold with solver contacts,
    /// in the narrow phase's order. [`NotReadBack`] unless [`ReadBack::Contacts`] is set
    /// ([`Self::set_read_back`]): an empty slice always means no contacts.
    pub fn reports(&self) -> Result<&[ContactReport], NotReadBack> {
        self.needs(ReadBack::Contacts)?;
        Ok(&self.reports)
    }

    /// World totals of the last step. [`NotReadBack`] unless [`Self::read_back`] is
    /// [`ReadBack::Totals`] or [`ReadBack::Contacts`]: zero totals always mean no contacts.
    pub fn totals(&self) -> Result<WorldTotals, NotReadBack> {
        self.needs(ReadBack::Totals)?;
        Ok(self.totals)
    }

    fn needs(&self, needed: ReadBack) -> Result<(), NotReadBack> {
        if self.read_back >= needed {
            Ok(())
        } else {
            Err(NotReadBack {
                needed,
                set: self.read_back,
            })
        }
    }

    /// Simulated time (s) at the end of the last step.
    pub fn time(&self) -> f64 {
        self.clock.time
    }

    /// Sets the simulated time (s), e.g. the phase origin of vibration sources.
    pub fn set_time(&mut self, time: f64) {
        self.clock.time = time;
    }

    /// Number of contacts with friction state.
    pub fn active_contacts(&self) -> usize {
        self.store.len()
    }

    /// Bytes of friction state kept per active contact manifold (the per-contact record:
    /// law state, stick anchors, bookkeeping). A bench instrument, not API.
    #[doc(hidden)]
    pub const STATE_BYTES_PER_CONTACT: usize = std::mem::size_of::<crate::contact_store::Slot>();

    /// Heap bytes of the contact state (slots, free list, key maps), capacity included; the
    /// reports, when on, come on top. A bench instrument, not API.
    #[doc(hidden)]
    pub fn state_heap_bytes(&self) -> usize {
        self.store.heap_bytes()
    }

    /// Slots allocated for contact state (live or reusable): memory tracks this. A bench
    /// instrument, not API.
    #[doc(hidden)]
    pub fn state_capacity(&self) -> usize {
        self.store.capacity()
    }
}
