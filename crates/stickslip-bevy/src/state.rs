//! What the plugin keeps (the modifier and its bookkeeping) and what it tells the app after
//! each rapier step (contacts as entities, regime changes).

use bevy::prelude::*;
use bevy_rapier3d::rapier::geometry::{ColliderHandle, ColliderSet};
use std::collections::HashMap;
use stickslip_core::law::Regime;
use stickslip_rapier_035::{ContactReport, StickSlip};

/// The modifier of the app's default rapier context.
#[derive(Resource)]
pub struct StickSlipRapier {
    /// The contact modifier (materials, vibration sources, contact state, reports).
    pub modifier: StickSlip,
    /// Whether stickslip steps the world (false when bevy_rapier's step system could not be
    /// taken over: see the error logged at startup).
    pub active: bool,
    pub(crate) attached: HashMap<Entity, ColliderHandle>,
    pub(crate) vibrating: HashMap<Entity, ColliderHandle>,
    pub(crate) surface_entities: HashMap<Entity, ColliderHandle>,
}

impl StickSlipRapier {
    pub(crate) fn new(modifier: StickSlip) -> Self {
        StickSlipRapier {
            modifier,
            active: true,
            attached: HashMap::new(),
            vibrating: HashMap::new(),
            surface_entities: HashMap::new(),
        }
    }

    /// Whether the collider of `entity` is attached to stickslip.
    pub fn is_attached(&self, entity: Entity) -> bool {
        self.attached.contains_key(&entity)
    }

    /// How many colliders are attached (a despawned one is forgotten in the next frame).
    pub fn attached_count(&self) -> usize {
        self.attached.len()
    }
}

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

/// The contacts of the last rapier step, as entities (empty unless the modifier reads
/// contacts back: `StickSlipRapier::modifier.set_read_back(ReadBack::Contacts)`).
#[derive(Resource, Debug, Default)]
pub struct StickSlipContacts(pub Vec<EntityContact>);

impl StickSlipContacts {
    /// The contacts of the collider `entity`.
    pub fn of(&self, entity: Entity) -> impl Iterator<Item = &EntityContact> {
        self.0
            .iter()
            .filter(move |c| c.entity1 == entity || c.entity2 == entity)
    }

    /// The most slippery regime among the contacts of the collider `entity` (sliding over
    /// stick-slip over sticking), or `None` without contacts: e.g. to colour a part.
    pub fn regime_of(&self, entity: Entity) -> Option<Regime> {
        Regime::most_slippery(self.of(entity).map(|c| c.report.regime))
    }
}

/// A pair of entities whose contact changed regime (sticking, stick-slip, sliding) in a
/// rapier step, or began (with contact read-back on). A pair with several manifolds counts as
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
pub(crate) struct LastRegimes(pub(crate) HashMap<(Entity, Entity), Regime>);

/// After a rapier step: the modifier's reports as entities, and the regime changes.
pub(crate) fn publish_reports(
    state: &StickSlipRapier,
    colliders: &ColliderSet,
    contacts: &mut StickSlipContacts,
    last: &mut LastRegimes,
    changed: &mut MessageWriter<RegimeChanged>,
) {
    contacts.0.clear();
    let Ok(reports) = state.modifier.reports() else {
        return;
    };
    // bevy_rapier keeps each collider's entity in its user_data.
    let entity = |h: ColliderHandle| {
        colliders
            .get(h)
            .map(|c| Entity::from_bits(c.user_data as u64))
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
