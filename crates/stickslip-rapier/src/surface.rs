//! Moving surfaces: a collider whose surface moves relative to its body (a conveyor belt, a
//! treadmill, a turntable's rim treated as a belt), and vibrating or moving surfaces keeping
//! what they carry awake.
//!
//! A surface velocity is the solver's target tangent velocity of the pair: collider 2's
//! surface points are to move at s₁ − s₂ relative to collider 1's (rapier's
//! `tangent_velocity`), projected onto each contact's tangent plane. It applies on every
//! pair of the collider — with or without stickslip's friction — after the user's own hooks
//! (which may add theirs), and the law's slip is measured relative to it. Such a surface is
//! never at rest, though rapier sees no force on what it carries: the bodies touching a
//! moving or vibrating surface are kept awake (a part conveyed at a few cm/s would otherwise
//! fall asleep under rapier's sleep threshold and stop dead).

use crate::collider_map::ColliderMap;
use rapier::prelude::*;

/// The target tangent velocity of collider 2 relative to collider 1 for the surface
/// velocities in `surfaces` (zero when neither moves), with its normal part removed.
pub(crate) fn surface_target(
    surfaces: &ColliderMap<Vector>,
    (c1, c2): (ColliderHandle, ColliderHandle),
    normal: Vector,
) -> Vector {
    let v = surfaces.get(c1).copied().unwrap_or(Vector::ZERO)
        - surfaces.get(c2).copied().unwrap_or(Vector::ZERO);
    v - normal * normal.dot(v)
}

/// Keeps the dynamic bodies in contact with any collider of `drivers` awake.
pub(crate) fn wake_carried(
    drivers: impl Iterator<Item = ColliderHandle>,
    narrow_phase: &NarrowPhase,
    colliders: &ColliderSet,
    bodies: &mut RigidBodySet,
) {
    for driver in drivers {
        for pair in narrow_phase.contact_pairs_with(driver) {
            if !pair.has_any_active_contact() {
                continue;
            }
            let other = if pair.collider1 == driver {
                pair.collider2
            } else {
                pair.collider1
            };
            let Some(parent) = colliders.get(other).and_then(|c| c.parent()) else {
                continue;
            };
            // Strongly: that restarts the body's sleep timer, so it never falls asleep (and
            // stops dead) between two wakings. Only once the timer has run half way: taking
            // the body mutably marks it changed, and rapier then re-registers it in its
            // islands (8–12 allocations a step on a vibrating plane of boxes).
            let due = bodies.get(parent).is_some_and(|b| {
                let a = b.activation();
                b.is_dynamic()
                    && (b.is_sleeping() || !(a.time_since_can_sleep < 0.5 * a.time_until_sleep))
            });
            if due && let Some(body) = bodies.get_mut(parent) {
                body.wake_up(true);
            }
        }
    }
}
