//! The friction state of every contact stickslip steps, and what the last solve measured.

use crate::key::ContactKey;
use bevy::platform::collections::HashMap;
use bevy::prelude::*;
use stickslip_core::contact::{ContactState, REGIME_NONE, World};

/// What the solver did at a contact in its last solve, for the law: the contact as it is at
/// the end of the tick (its last substep), where a saturated friction means it slips now. A
/// tick's sums would count the braking of a landing (a box put down on a slope slides for a
/// few ticks before it holds) as the force the contact carries.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Measured {
    /// Normal force (N): the last substep's accumulated normal impulse over its length.
    pub normal_force: f64,
    /// Friction over normal impulse, μ⃗ with F_f(body 2) = −F_n μ⃗ (world axes).
    pub mu: World,
    /// The last substep's normal impulse (N·s), for the next tick's warm-start share.
    pub normal_impulse: f32,
    /// Whether some loaded points, but not all, ended the solve at their own clamp.
    pub partly_clamped: bool,
}

/// What the solver did at a contact over the whole tick, for the read-back: all substeps'
/// impulses and restitution's, over the tick.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct TickForces {
    /// Normal force (N).
    pub normal_force: f64,
    /// Friction force on body 2 (N, world).
    pub friction: Vec3,
}

/// Sums over the substeps of the tick being solved.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct TickImpulses {
    /// Σ normal impulse (N·s).
    pub normal: f32,
    /// Σ friction impulse on body 2 (N·s, world).
    pub friction: Vec3,
    /// The last substep's normal impulse, before restitution adds to it.
    pub last_normal: f32,
}

/// A stepped manifold's constraint in this tick's solve.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Solved {
    /// Its graph colour and index there.
    pub color: usize,
    pub index: usize,
    pub key: ContactKey,
    pub impulses: TickImpulses,
}

/// One contact's record.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Record {
    pub state: ContactState,
    pub measured: Measured,
    /// The tick's forces, for the read-back.
    pub tick_forces: TickForces,
    /// The solver's friction basis of the last solve (`tangent1`, normal), in which avian
    /// keeps the warm start (see `measure::carry_warm_start`; 3D only).
    #[cfg(not(dim2))]
    pub basis: Option<(Vec3, Vec3)>,
    /// Whether the solver gets headroom per point while the law holds (see `apply`).
    pub headroom: bool,
    /// The tick it was last stepped in.
    pub tick: u64,
    /// The slip velocity it was stepped with (m/s, world), for the read-back.
    pub slip: Vec3,
    /// Where it was (the mean of its points, world) and its normal, for the read-back.
    pub point: Vec3,
    pub normal: Vec3,
    /// The regime code last published (see `report`).
    pub published: u8,
}

impl Default for Record {
    fn default() -> Self {
        Record {
            state: ContactState::default(),
            measured: Measured::default(),
            tick_forces: TickForces::default(),
            #[cfg(not(dim2))]
            basis: None,
            headroom: false,
            tick: 0,
            slip: Vec3::ZERO,
            point: Vec3::ZERO,
            normal: Vec3::ZERO,
            published: REGIME_NONE,
        }
    }
}

/// The friction state of every contact stickslip steps (a resource): one record per contact,
/// kept while the contact lasts (or its pair sleeps) and dropped in the tick it is gone in.
#[derive(Resource, Default)]
pub struct ContactStore {
    pub(crate) records: HashMap<ContactKey, Record>,
    /// This tick's manifolds (avian's contact id and manifold index) and their keys.
    pub(crate) stepped: HashMap<(u32, usize), ContactKey>,
    /// This tick's solver constraints of stepped manifolds, where they are in avian's
    /// constraint graph, and their impulses so far.
    pub(crate) solved: Vec<Solved>,
    pub(crate) tick: u64,
}

impl ContactStore {
    /// How many contacts have a friction state.
    pub fn len(&self) -> usize {
        self.records.len()
    }

    /// Whether no contact has a friction state.
    pub fn is_empty(&self) -> bool {
        self.records.is_empty()
    }

    /// How many contacts of the collider `entity` have a friction state.
    pub fn count_of(&self, entity: Entity) -> usize {
        self.records
            .keys()
            .filter(|k| k.collider1 == entity || k.collider2 == entity)
            .count()
    }
}
