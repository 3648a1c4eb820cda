//! What the app reads back after each physics step: the contacts, by entity, and the regime
//! changes. Each add-on fills them in from its engine.

use bevy::prelude::*;
use stickslip_core::law::Regime;

/// A contact (one manifold, or one face of a composite shape) after the last physics step,
/// its colliders as entities: the one read-back type of every stickslip engine (see
/// [`stickslip_core::report::ContactReport`] for its fields); `Vec3::from(r.point)` makes a
/// bevy vector of an array field.
pub type ContactReport = stickslip_core::report::ContactReport<Entity, 3>;

/// The contacts of the last physics step (see the add-on for when it reads them back).
#[derive(Resource, Debug, Default)]
pub struct StickSlipContacts(pub Vec<ContactReport>);

impl StickSlipContacts {
    /// The contacts of the collider `entity`.
    pub fn of(&self, entity: Entity) -> impl Iterator<Item = &ContactReport> {
        self.0
            .iter()
            .filter(move |c| c.collider1 == entity || c.collider2 == entity)
    }

    /// The most slippery regime among the contacts of the collider `entity` (sliding over
    /// stick-slip over sticking), or `None` without contacts: e.g. to colour a part. Contacts
    /// whose inputs were reset do not count.
    pub fn regime_of(&self, entity: Entity) -> Option<Regime> {
        Regime::most_slippery(self.of(entity).filter(|c| !c.reset).map(|c| c.regime))
    }
}

/// A contact whose regime (sticking, stick-slip, sliding) changed in a physics step, or that
/// began. stickslip-bevy-rapier counts a pair with several manifolds as one contact (its first
/// manifold's regime); stickslip-avian tells of each.
#[derive(Message, Debug, Clone, Copy, PartialEq)]
pub struct RegimeChanged {
    /// The first collider of the pair.
    pub collider1: Entity,
    /// The second collider of the pair.
    pub collider2: Entity,
    /// The regime before (`None`: a new contact).
    pub from: Option<Regime>,
    /// The regime now.
    pub to: Regime,
}

/// A pair resisting rolling or spinning (see [`stickslip_core::FrictionMaterial::with_rolling`])
/// after the last physics step, its colliders as entities (see
/// [`stickslip_core::report::RollingReport`] for its fields).
pub type RollingReport = stickslip_core::report::RollingReport<Entity, 3>;

/// The pairs resisting rolling or spinning after the last physics step: their regimes,
/// torque caps and the torques the solver applied.
#[derive(Resource, Debug, Default)]
pub struct StickSlipRolling(pub Vec<RollingReport>);

impl StickSlipRolling {
    /// The resisting pairs of the collider `entity`.
    pub fn of(&self, entity: Entity) -> impl Iterator<Item = &RollingReport> {
        self.0
            .iter()
            .filter(move |c| c.collider1 == entity || c.collider2 == entity)
    }
}
