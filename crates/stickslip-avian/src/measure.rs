//! Right after avian's solver stored its impulses: each stepped manifold's normal force and
//! friction from the solver's own constraints, the read-back, and the records of contacts
//! that are gone.
//!
//! The constraint keeps the last substep's accumulated impulses and the tick's tangent basis
//! (`tangent1`, `tangent1 × normal`); the manifold in avian's contact graph keeps only the
//! impulses, so the direction of the friction is read here, not at the next tick.

use crate::report::{AvianContact, RegimeChanged, StickSlipContacts};
use crate::store::{ContactStore, Measured};
use avian3d::dynamics::solver::constraint_graph::ConstraintGraph;
use avian3d::prelude::*;
use bevy::prelude::*;
use stickslip_core::contact::REGIME_NONE;
use stickslip_core::law::Regime;

/// Measures the stepped manifolds, publishes them and forgets the contacts that are gone.
#[allow(clippy::too_many_arguments)]
pub(crate) fn measure(
    constraints: Res<ConstraintGraph>,
    graph: Res<ContactGraph>,
    mut store: ResMut<ContactStore>,
    substeps: Res<SubstepCount>,
    time: Res<Time>,
    sleeping: Query<(), With<Sleeping>>,
    mut contacts: ResMut<StickSlipContacts>,
    mut changed: MessageWriter<RegimeChanged>,
) {
    let store = &mut *store;
    contacts.0.clear();
    let h = time.delta_secs_f64() / substeps.0.max(1) as f64;
    if h > 0.0 && !store.stepped.is_empty() {
        for color in &constraints.colors {
            for c in &color.contact_constraints {
                let Some(key) = store.stepped.get(&(c.contact_id.0, c.manifold_index)) else {
                    continue;
                };
                let Some(record) = store.records.get_mut(key) else {
                    continue;
                };
                let t2 = c.tangent1.cross(c.normal);
                let (normal, tangent) = c.points.iter().fold((0.0f32, Vec3::ZERO), |(n, t), p| {
                    let lt = p.tangent_part.as_ref().map_or(Vec2::ZERO, |t| t.impulse);
                    (n + p.normal_part.impulse, t + lt.x * c.tangent1 + lt.y * t2)
                });
                // The impulse on body 2 is +λ_t: μ⃗ = −Σλ_t / Σλ_n.
                let mu = if normal > 0.0 {
                    (-tangent / normal).to_array()
                } else {
                    [0.0; 3]
                };
                record.measured = Measured {
                    normal_force: normal as f64 / h,
                    mu,
                    normal_impulse: normal,
                };
            }
        }
    }
    let tick = store.tick;
    for (key, record) in store.records.iter_mut() {
        if record.tick != tick {
            continue;
        }
        let regime = record.state.regime();
        let f_n = record.measured.normal_force;
        contacts.0.push(AvianContact {
            entity1: key.collider1,
            entity2: key.collider2,
            regime,
            normal_force: f_n,
            friction: -Vec3::from_array(record.measured.mu) * f_n as f32,
            limit: record.state.limit,
            slip_speed: record.slip_speed,
            point: record.point,
            normal: record.normal,
        });
        if let Some(to) = regime
            && record.published != to.code()
        {
            let from =
                (record.published != REGIME_NONE).then(|| Regime::from_code(record.published));
            changed.write(RegimeChanged {
                entity1: key.collider1,
                entity2: key.collider2,
                from,
                to,
            });
            record.published = to.code();
        }
    }
    // A contact not stepped this tick is gone (separated, despawned, its material removed)
    // unless its pair sleeps: it then keeps its state for when it wakes.
    store.records.retain(|key, record| {
        record.tick == tick
            || graph
                .get(key.collider1, key.collider2)
                .is_some_and(|(_, pair)| {
                    [pair.body1, pair.body2]
                        .into_iter()
                        .flatten()
                        .any(|b| sleeping.contains(b))
                })
    });
}
