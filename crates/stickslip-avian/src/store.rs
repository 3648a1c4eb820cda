//! The friction state of every contact stickslip steps, and what the last solve measured.

use crate::key::ContactKey;
use bevy::prelude::*;
use std::collections::HashMap;
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
            published: REGIME_NONE,
        }
    }
}

/// Every contact's record, and this tick's manifolds (avian's contact id and manifold index)
/// with the key they were stepped under.
#[derive(Resource, Default)]
pub(crate) struct ContactStore {
    pub records: HashMap<ContactKey, Record>,
    pub stepped: HashMap<(u32, usize), ContactKey>,
    pub tick: u64,
}
