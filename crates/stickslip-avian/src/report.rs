//! What the app reads back after each physics tick: the contacts stickslip stepped, by
//! entity, and the regime changes.

use bevy::prelude::*;
use stickslip_core::law::Regime;

/// A contact (one manifold, or one face of a composite shape) stickslip stepped in the last
/// physics tick, after the solve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AvianContact {
    /// avian's first collider of the pair.
    pub entity1: Entity,
    /// avian's second collider of the pair.
    pub entity2: Entity,
    /// Sticking, stick-slip or sliding (`None`: the law has not run on it yet).
    pub regime: Option<Regime>,
    /// Normal force the solver applied (N).
    pub normal_force: f64,
    /// Friction force on collider 2's body (N, world axes).
    pub friction: Vec3,
    /// The friction limit the solver had (the law's coefficient at this tick).
    pub limit: f32,
    /// Slip speed of the touching points at the start of the tick (m/s).
    pub slip_speed: f32,
    /// Where the contact is: the mean of its points (world, m).
    pub point: Vec3,
    /// Its normal (world, unit), from collider 1 towards collider 2.
    pub normal: Vec3,
}

/// The contacts stickslip stepped in the last physics tick.
#[derive(Resource, Debug, Default)]
pub struct StickSlipContacts(pub Vec<AvianContact>);

impl StickSlipContacts {
    /// The contacts of the collider `entity`.
    pub fn of(&self, entity: Entity) -> impl Iterator<Item = &AvianContact> {
        self.0
            .iter()
            .filter(move |c| c.entity1 == entity || c.entity2 == entity)
    }

    /// The most slippery regime among the contacts of the collider `entity` (sliding over
    /// stick-slip over sticking), or `None`: e.g. to colour a part.
    pub fn regime_of(&self, entity: Entity) -> Option<Regime> {
        Regime::most_slippery(self.of(entity).filter_map(|c| c.regime))
    }
}

/// A contact whose regime (sticking, stick-slip, sliding) changed in a physics tick, or that
/// began.
#[derive(Message, Debug, Clone, Copy, PartialEq)]
pub struct RegimeChanged {
    /// avian's first collider of the pair.
    pub entity1: Entity,
    /// avian's second collider of the pair.
    pub entity2: Entity,
    /// The regime before (`None`: a new contact).
    pub from: Option<Regime>,
    /// The regime now.
    pub to: Regime,
}
