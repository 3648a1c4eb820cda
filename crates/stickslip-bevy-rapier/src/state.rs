//! What the plugin keeps (the modifier and its bookkeeping) and what it tells the app after
//! each rapier step (contacts as entities, regime changes).

use bevy::prelude::*;
use bevy_rapier::rapier::geometry::{ColliderHandle, ColliderSet};
use std::collections::HashMap;
use stickslip_bevy::{RegimeChanged, StickSlipContacts};
use stickslip_core::law::Regime;
use stickslip_rapier::StickSlip;

/// The modifier of the app's default rapier context.
#[derive(Resource)]
pub struct StickSlipRapier {
    pub(crate) modifier: StickSlip,
    pub(crate) active: bool,
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

    /// The contact modifier: its materials, vibration sources, contact state, reports and
    /// snapshots.
    pub fn modifier(&self) -> &StickSlip {
        &self.modifier
    }

    /// The contact modifier, to change its configuration or read-back, or to take or restore
    /// a snapshot. Colliders come and go with the components (`StickSlipFriction`,
    /// `StickSlipVibration`, `SurfaceVelocity`): attaching or detaching here is undone by the
    /// next sync.
    pub fn modifier_mut(&mut self) -> &mut StickSlip {
        &mut self.modifier
    }

    /// Whether stickslip steps the world (false when bevy_rapier's step system could not be
    /// taken over: see the error logged at startup).
    pub fn is_active(&self) -> bool {
        self.active
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
        // In 2D, the plane's contacts in the shared 3D read-back type (z = 0).
        #[cfg(dim2)]
        let r = r.in_3d();
        contacts.0.push(r.with_colliders(entity1, entity2));
        if now.contains_key(&(entity1, entity2)) {
            continue;
        }
        now.insert((entity1, entity2), r.regime);
        let from = last.0.get(&(entity1, entity2)).copied();
        if from != Some(r.regime) {
            changed.write(RegimeChanged {
                collider1: entity1,
                collider2: entity2,
                from,
                to: r.regime,
            });
        }
    }
    last.0 = now;
}
