//! The read-back of one manifold after a step: its [`ContactReport`] in world space.

use crate::contact_store::ContactRecord;
use crate::measure::{measure, point_velocity, world_centroid};
use crate::report::ContactReport;
use rapier::prelude::*;
use stickslip_core::law::Regime;

/// The read-back of one manifold after the step (`moving_surfaces`: whether the wrapped hook
/// gives surfaces velocities, see `StickSlip::moving_surfaces`).
pub(crate) fn report(
    m: &ContactManifold,
    rec: &ContactRecord,
    (c1, c2): (ColliderHandle, ColliderHandle),
    bodies: &RigidBodySet,
    colliders: &ColliderSet,
    dt: f64,
    moving_surfaces: bool,
) -> ContactReport {
    if rec.state.was_reset() {
        return reset_report(rec, c1, c2);
    }
    let Some((p, targets)) = world_centroid(m, colliders, (c1, c2)) else {
        return reset_report(rec, c1, c2);
    };
    // The target velocities hold stickslip's own (Regul's creep,
    // vibration drive) besides a wrapped hook's surface velocity; without such a hook they
    // are not a surface's motion at all.
    let surface = if moving_surfaces {
        targets
    } else {
        Vector::ZERO
    };
    // After the solve: the warm start it started from is the one the hook remembered.
    let meas = measure(
        m,
        &m.data.solver_contacts,
        dt,
        crate::rapier_compat::warm_before(rec),
    );
    let n = m.data.normal;
    let tangential = |v: Vector| v - n * v.dot(n);
    let slip = tangential(
        point_velocity(bodies, m.data.rigid_body2, p)
            - point_velocity(bodies, m.data.rigid_body1, p)
            - surface,
    );
    let friction = tangential(meas.mu) * -(meas.normal_force as f32);
    let f_n = meas.normal_force;
    let mut report = ContactReport::new(c1, c2);
    report.point = p.to_array();
    report.normal = n.to_array();
    report.regime = Regime::from_code(rec.state.regime);
    report.mu = if f_n > 0.0 {
        stickslip_core::contact::length(rec.state.force) as f64 / f_n
    } else {
        0.0
    };
    report.limit = m.data.friction as f64;
    report.normal_force = f_n;
    report.friction_force = friction.to_array();
    report.slip_velocity = slip.to_array();
    report.dissipated_power = (-(friction.dot(slip)) as f64).max(0.0);
    // Inputs that turned non-finite after the hook ran (the solve itself overflowed).
    let numbers = [
        report.mu,
        report.limit,
        report.normal_force,
        report.dissipated_power,
    ];
    let vectors = [
        report.point,
        report.normal,
        report.friction_force,
        report.slip_velocity,
    ];
    if numbers.iter().all(|x| x.is_finite()) && vectors.iter().flatten().all(|x| x.is_finite()) {
        report
    } else {
        reset_report(rec, c1, c2)
    }
}

/// The report of a contact whose inputs were not usable: zeros, flagged.
fn reset_report(rec: &ContactRecord, c1: ColliderHandle, c2: ColliderHandle) -> ContactReport {
    let mut report = ContactReport::new(c1, c2);
    report.limit = rec.state.limit as f64;
    report.reset = true;
    report
}
