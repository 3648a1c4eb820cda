//! The solve of each stepped manifold, from avian's own constraints: before the substeps its
//! friction warm start is carried into the tick's tangent basis (`carry_warm_start`), after
//! each substep its impulses are added up (`accumulate`), and after the solver stored its
//! impulses the tick's normal force and friction make the read-back (`measure`), and the
//! records of contacts that are gone are dropped.
//!
//! avian keeps only the current substep's accumulated impulses on a constraint, and a point's
//! friction impulse as coordinates in the tick's tangent basis (`tangent1`,
//! `tangent1 × normal`), which it picks again every tick from the bodies' relative velocity.
//! For a held contact that velocity is solver noise, so the basis turns at random from tick
//! to tick, and avian's warm start (last tick's coordinates, applied in the new basis) pushes
//! the held friction off its direction: the hold creeps downhill by millimetres a second.
//! Carried over as the world impulse it was (as rapier keeps it), the warm start holds the
//! contact still.

use crate::dim::{friction_impulse, impulses};
use crate::store::{ContactStore, Measured, Solved, TickForces, TickImpulses};
use avian::dynamics::solver::constraint_graph::ConstraintGraph;
use avian::dynamics::solver::contact::ContactConstraint;
use avian::prelude::*;
use bevy::prelude::*;
use stickslip_bevy::{ContactReport, RegimeChanged, StickSlipContacts};
use stickslip_core::contact::REGIME_NONE;
use stickslip_core::law::Regime;

/// How many of the constraint's points carry a normal impulse, and how many of those ended
/// the substep with their friction at their own clamp, μ times their own normal impulse (to
/// the kernel's saturation share).
fn clamped(c: &ContactConstraint) -> (usize, usize) {
    let share = 1.0 - stickslip_core::contact::SATURATION as f32;
    c.points
        .iter()
        .filter(|p| p.normal_part.impulse > 0.0)
        .fold((0, 0), |(loaded, clamped), p| {
            let at_clamp = p.tangent_part.is_some()
                && friction_impulse(p) >= share * c.friction * p.normal_part.impulse;
            (loaded + 1, clamped + usize::from(at_clamp))
        })
}

/// Before the substeps: finds this tick's constraints of the stepped manifolds and turns
/// each point's friction warm start from last tick's basis into this tick's, keeping it the
/// same world impulse (less any part along the new normal).
pub(crate) fn carry_warm_start(
    mut constraints: ResMut<ConstraintGraph>,
    mut store: ResMut<ContactStore>,
) {
    let store = &mut *store;
    store.solved.clear();
    if store.stepped.is_empty() {
        return;
    }
    for (color, graph_color) in constraints.colors.iter_mut().enumerate() {
        for (index, c) in graph_color.contact_constraints.iter_mut().enumerate() {
            let Some(&key) = store.stepped.get(&(c.contact_id.0, c.manifold_index)) else {
                continue;
            };
            if !store.records.contains_key(&key) {
                continue;
            }
            store.solved.push(Solved {
                color,
                index,
                key,
                impulses: TickImpulses::default(),
            });
            // In 2D the friction direction is the normal's perpendicular and the warm start
            // one number along it: nothing turns.
            #[cfg(not(dim2))]
            if let Some(old) = store.records.get(&key).and_then(|r| r.basis) {
                turn_warm_start(c, old);
            }
        }
    }
}

/// Turns the constraint's friction warm start from the basis `(t1_old, n_old)` it was
/// accumulated in into the constraint's own, as the same world impulse (less its part along
/// the new normal).
#[cfg(not(dim2))]
fn turn_warm_start(c: &mut ContactConstraint, (t1_old, n_old): (Vec3, Vec3)) {
    let t2_old = t1_old.cross(n_old);
    let (t1, n) = (c.tangent1, c.normal);
    let t2 = t1.cross(n);
    for part in c.points.iter_mut().filter_map(|p| p.tangent_part.as_mut()) {
        let w = part.impulse.x * t1_old + part.impulse.y * t2_old;
        let w = w - n * n.dot(w);
        part.impulse = Vec2::new(w.dot(t1), w.dot(t2));
    }
}

/// After each substep's relax pass: its impulses added to the tick's.
pub(crate) fn accumulate(constraints: Res<ConstraintGraph>, mut store: ResMut<ContactStore>) {
    for s in store.solved.iter_mut() {
        let Some(c) = constraints
            .colors
            .get(s.color)
            .and_then(|g| g.contact_constraints.get(s.index))
        else {
            continue;
        };
        let (normal, friction) = impulses(c);
        s.impulses.normal += normal;
        s.impulses.friction += friction;
        s.impulses.last_normal = normal;
    }
}

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
    let dt = time.delta_secs_f64();
    let h = dt / substeps.0.max(1) as f64;
    if dt > 0.0 {
        for s in &store.solved {
            let Some(c) = constraints
                .colors
                .get(s.color)
                .and_then(|g| g.contact_constraints.get(s.index))
            else {
                continue;
            };
            let Some(record) = store.records.get_mut(&s.key) else {
                continue;
            };
            // The law's measurement: the last substep (restitution's share included).
            let (normal, friction) = impulses(c);
            let (loaded, at_clamp) = clamped(c);
            let all_clamped = loaded > 0 && at_clamp == loaded;
            // The impulse on body 2 is +λ_t: μ⃗ = −Σλ_t / Σλ_n.
            let mu = if normal > 0.0 {
                let mu = -friction / normal;
                // avian clamps each point's friction at its own share of the limit: a solve
                // that held every point at its clamp reached the limit, although the
                // points' sum can fall a little short of it (a landing braked at 0.998).
                let length = mu.length();
                if all_clamped && length > 0.0 {
                    (mu * (c.friction / length)).to_array()
                } else {
                    mu.to_array()
                }
            } else {
                [0.0; 3]
            };
            record.measured = Measured {
                normal_force: normal as f64 / h,
                mu,
                normal_impulse: normal,
                partly_clamped: at_clamp > 0 && !all_clamped,
            };
            // The read-back: the whole tick. Restitution, after the substeps, adds to the
            // last substep's normal impulses.
            let tick_normal = s.impulses.normal + (normal - s.impulses.last_normal);
            record.tick_forces = TickForces {
                normal_force: tick_normal.max(0.0) as f64 / dt,
                friction: s.impulses.friction / dt as f32,
            };
            #[cfg(not(dim2))]
            {
                record.basis = Some((c.tangent1, c.normal));
            }
        }
    }
    let tick = store.tick;
    for (key, record) in store.records.iter_mut() {
        if record.tick != tick {
            continue;
        }
        let regime = record.state.regime();
        let f_n = record.tick_forces.normal_force;
        let friction = record.tick_forces.friction;
        let mut report = ContactReport::new(key.collider1, key.collider2);
        report.point = record.point.to_array();
        report.normal = record.normal.to_array();
        report.regime = regime.unwrap_or(Regime::Sticking);
        report.mu = if f_n > 0.0 {
            stickslip_core::contact::length(record.state.force) as f64 / f_n
        } else {
            0.0
        };
        report.limit = record.state.limit as f64;
        report.normal_force = f_n;
        report.friction_force = friction.to_array();
        report.slip_velocity = record.slip.to_array();
        report.dissipated_power = (-(friction.dot(record.slip)) as f64).max(0.0);
        report.reset = regime.is_none();
        contacts.0.push(report);
        if let Some(to) = regime
            && record.published != to.code()
        {
            let from =
                (record.published != REGIME_NONE).then(|| Regime::from_code(record.published));
            changed.write(RegimeChanged {
                collider1: key.collider1,
                collider2: key.collider2,
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
