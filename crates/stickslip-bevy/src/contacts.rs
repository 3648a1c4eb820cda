//! Contact read-back: every stickslip contact of the last step mapped to entities, world
//! totals, and a message whenever a contact's regime changes.

use crate::world::StickSlipWorld;
use bevy::prelude::*;
use std::collections::HashMap;
use stickslip_core::law::Regime;
use stickslip_rapier::{ContactReport, WorldTotals};

/// One contact of the last step.
#[derive(Debug, Clone, Copy)]
pub struct Contact {
    /// Entity of the first collider.
    pub collider1: Entity,
    /// Entity of the second collider.
    pub collider2: Entity,
    /// What stickslip reports for it (regime, μ state, forces, slip, dissipated power).
    pub report: ContactReport,
}

/// The last step's stickslip contacts and totals.
#[derive(Resource, Debug, Default)]
pub struct StickSlipContacts {
    /// Every contact with stickslip friction.
    pub contacts: Vec<Contact>,
    /// World totals (counts by regime, forces, dissipated power and energy).
    pub totals: WorldTotals,
    /// Simulated time at the end of the step (s).
    pub time: f64,
    last: HashMap<(Entity, Entity), Regime>,
}

impl StickSlipContacts {
    /// Contacts involving `entity`.
    pub fn of(&self, entity: Entity) -> impl Iterator<Item = &Contact> {
        self.contacts
            .iter()
            .filter(move |c| c.collider1 == entity || c.collider2 == entity)
    }
}

/// A contact changed regime (or appeared in one); read it in `Update` with a `MessageReader`.
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

/// Maps the modifier's reports to entities and writes `RegimeChanged` messages.
pub(crate) fn read_back(
    w: Res<StickSlipWorld>,
    mut out: ResMut<StickSlipContacts>,
    mut changed: MessageWriter<RegimeChanged>,
) {
    let out = &mut *out;
    out.contacts.clear();
    let mut now = HashMap::with_capacity(out.last.len());
    for r in w.friction.reports() {
        let (Some(e1), Some(e2)) = (
            w.collider_entity(r.collider1),
            w.collider_entity(r.collider2),
        ) else {
            continue;
        };
        out.contacts.push(Contact {
            collider1: e1,
            collider2: e2,
            report: *r,
        });
        let from = out.last.get(&(e1, e2)).copied();
        if from != Some(r.regime) && now.insert((e1, e2), r.regime).is_none() {
            changed.write(RegimeChanged {
                collider1: e1,
                collider2: e2,
                from,
                to: r.regime,
            });
        } else {
            now.insert((e1, e2), r.regime);
        }
    }
    out.last = now;
    out.totals = w.friction.totals();
    out.time = w.friction.time();
}
