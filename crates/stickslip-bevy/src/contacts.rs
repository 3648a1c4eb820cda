//! Contact read-back: every stickslip contact of the last step mapped to entities, world
//! totals, and a message whenever a contact's regime changes.

use crate::world::StickSlipWorld;
use bevy::prelude::*;
use std::collections::HashMap;
use stickslip_core::law::Regime;
use stickslip_rapier::{ContactReport, WorldTotals};

/// One contact (manifold) of the last step.
#[derive(Debug, Clone, Copy)]
pub struct Contact {
    /// Entity of the first collider.
    pub collider1: Entity,
    /// Entity of the second collider.
    pub collider2: Entity,
    /// The contact point (m, world): the centroid of the manifold's solver contacts, midway
    /// between the two surfaces, taken from rapier's manifold after the step (world poses of
    /// its local points).
    pub point: Vec3,
    /// The contact normal (world, from collider 1 towards collider 2).
    pub normal: Vec3,
    /// What stickslip reports for it (regime, μ state, forces, slip, dissipated power).
    pub report: ContactReport,
}

impl Contact {
    /// Whether `entity` is one of the contact's colliders.
    pub fn involves(&self, entity: Entity) -> bool {
        self.collider1 == entity || self.collider2 == entity
    }
}

/// The last step's stickslip contacts (every `ContactReport` of the modifier, mapped to
/// entities) and world totals. Updated after every physics step; poll it from any system.
#[derive(Resource, Debug, Default)]
pub struct ContactReports {
    /// Every contact with stickslip friction.
    pub contacts: Vec<Contact>,
    /// World totals (counts by regime, forces, dissipated power and energy).
    pub totals: WorldTotals,
    /// Simulated time at the end of the step (s).
    pub time: f64,
    last: HashMap<(Entity, Entity), Regime>,
}

impl ContactReports {
    /// Contacts involving the collider `entity`.
    pub fn of(&self, entity: Entity) -> impl Iterator<Item = &Contact> {
        self.contacts.iter().filter(move |c| c.involves(entity))
    }

    /// The most slippery regime among the contacts of the collider `entity` (sliding over
    /// stick-slip over sticking), or `None` without contacts: e.g. to colour a part.
    pub fn regime_of(&self, entity: Entity) -> Option<Regime> {
        self.of(entity)
            .map(|c| c.report.regime)
            .max_by_key(|r| rank(*r))
    }
}

fn rank(r: Regime) -> u8 {
    match r {
        Regime::Sticking => 0,
        Regime::StickSlip => 1,
        Regime::Sliding => 2,
    }
}

/// A contact between two colliders changed regime, or appeared (`from: None`). Written in the
/// physics schedule; read it in `Update` with a `MessageReader<RegimeChanged>`.
#[derive(Message, Debug, Clone, Copy, PartialEq)]
pub struct RegimeChanged {
    /// Entity of the first collider.
    pub collider1: Entity,
    /// Entity of the second collider.
    pub collider2: Entity,
    /// Regime before (None: a new contact).
    pub from: Option<Regime>,
    /// Regime now.
    pub to: Regime,
}

/// Maps the modifier's reports to entities and writes `RegimeChanged` messages. A pair of
/// colliders with several manifolds counts as one contact here: its first manifold's regime.
pub(crate) fn read_back(
    w: Res<StickSlipWorld>,
    mut out: ResMut<ContactReports>,
    mut changed: MessageWriter<RegimeChanged>,
) {
    let out = &mut *out;
    out.contacts.clear();
    let mut now = HashMap::with_capacity(out.last.len());
    for r in w.friction.reports().unwrap_or_default() {
        let (Some(e1), Some(e2)) = (
            w.collider_entity(r.collider1),
            w.collider_entity(r.collider2),
        ) else {
            continue;
        };
        out.contacts.push(Contact {
            collider1: e1,
            collider2: e2,
            point: Vec3::from_array(r.point),
            normal: Vec3::from_array(r.normal),
            report: *r,
        });
        if now.contains_key(&(e1, e2)) {
            continue;
        }
        now.insert((e1, e2), r.regime);
        let from = out.last.get(&(e1, e2)).copied();
        if from != Some(r.regime) {
            changed.write(RegimeChanged {
                collider1: e1,
                collider2: e2,
                from,
                to: r.regime,
            });
        }
    }
    out.last = now;
    out.totals = w.friction.totals().unwrap_or_default();
    out.time = w.friction.time();
}
