//! The friction state of every contact stickslip steps, and what the last solve measured.

use crate::key::ContactKey;
use bevy::platform::collections::HashMap;
use bevy::prelude::*;
use stickslip_core::contact::{ContactState, REGIME_NONE, World};

/// What the solver did at a contact in its last solve.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Measured {
    /// Normal force (N): the last substep's accumulated normal impulse over its length.
    pub normal_force: f64,
    /// Friction over normal impulse, μ⃗ with F_f(body 2) = −F_n μ⃗ (world axes).
    pub mu: World,
    /// The last substep's normal impulse (N·s), for the next tick's warm-start share.
    pub normal_impulse: f32,
}

/// One contact's record.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Record {
    pub state: ContactState,
    pub measured: Measured,
    /// The tick it was last stepped in.
    pub tick: u64,
    /// The slip speed it was stepped with (m/s), for the read-back.
    pub slip_speed: f32,
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
            tick: 0,
            slip_speed: 0.0,
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
