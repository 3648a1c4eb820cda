//! What a manifold tells after a solve: its normal force and measured friction, the centroid
//! of its solver contacts, and the velocity of a body's material point.

use rapier::prelude::*;

/// Normal and friction measurement of a manifold from the last solve.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Measured {
    /// Normal force over the step (N).
    pub normal_force: f64,
    /// Friction impulse over normal impulse of the last solve: μ⃗ with F_f(body 2) = −F_n μ⃗.
    pub mu: Vector,
    /// The warm-start impulse the points carry now (summed): what the next solve starts
    /// from (rapier 0.35 reports it inside the solve's impulse, see `rapier_compat`).
    pub warm_start_impulse: f64,
}

/// Measures a manifold from the points its solver contacts stand for: before the solve
/// (inside the hook) they carry the last solve's impulses, carried over by rapier (by feature
/// id, or by position into a cluster); after the solve, this solve's. Points the solver did not
/// use may hold stale impulses and are skipped. In 3D friction is one constraint per manifold
/// (`FrictionModel::Simplified`), whose impulse rapier stores on each of its points; in 2D each
/// point has its own friction row along t = (n_y, −n_x) (rapier's tangent of −n), whose
/// impulses add up to the manifold's.
/// `warm_before`: the warm-start impulse that solve started from, where known (only rapier
/// 0.35 needs it).
pub(crate) fn measure(
    m: &ContactManifold,
    contacts: &[SolverContact],
    dt: f64,
    warm_before: Option<f64>,
) -> Measured {
    let (mut impulse, mut warm) = (0.0f64, 0.0f64);
    let mut friction = None;
    for c in contacts {
        let Some(p) = m.points.get(c.contact_indices()[0] as usize) else {
            continue;
        };
        impulse += p.data.impulse as f64;
        warm += p.data.warmstart_impulse as f64;
        #[cfg(not(dim2))]
        if friction.is_none() && p.data.warmstart_impulse != 0.0 {
            friction = Some(p.data.warmstart_tangent_world);
        }
        #[cfg(dim2)]
        {
            let n = m.data.normal;
            let t = Vector::new(n.y, -n.x) * p.data.warmstart_tangent_impulse.x;
            friction = Some(friction.unwrap_or(Vector::ZERO) + t);
        }
    }
    let impulse = crate::rapier_compat::solve_impulse(impulse, warm, warm_before);
    Measured {
        normal_force: if dt > 0.0 { impulse / dt } else { 0.0 },
        mu: match friction {
            Some(f) if warm > 0.0 => f / warm as f32,
            _ => Vector::ZERO,
        },
        warm_start_impulse: warm,
    }
}

pub(crate) fn centroid(contacts: &[SolverContact]) -> (Vector, Vector) {
    let k = contacts.len().max(1) as f32;
    let mut p = Vector::ZERO;
    let mut surface = Vector::ZERO;
    for c in contacts {
        p += (c.anchor1 + c.anchor2) * 0.5;
        surface += c.tangent_velocity;
    }
    (p / k, surface / k)
}

pub(crate) fn point_velocity(
    bodies: &RigidBodySet,
    h: Option<RigidBodyHandle>,
    p: Vector,
) -> Vector {
    h.and_then(|h| bodies.get(h))
        .map(|b| b.velocity_at_point(p))
        .unwrap_or(Vector::ZERO)
}

/// The world-space centroid of a manifold's solver contacts after the step, and their mean
/// target velocity. After the hook, rapier re-expresses a dynamic body's solver anchors in
/// that body's frame, so the anchors are not world points any more; the manifold's local
/// points and the colliders' poses are.
pub(crate) fn world_centroid(
    m: &ContactManifold,
    colliders: &ColliderSet,
    (c1, c2): (ColliderHandle, ColliderHandle),
) -> Option<(Vector, Vector)> {
    let pose = |h: ColliderHandle, sub: Option<&Pose>| {
        let at = *colliders.get(h)?.position();
        Some(sub.map_or(at, |s| at * *s))
    };
    let (pos1, pos2) = (pose(c1, m.subshape_pos1())?, pose(c2, m.subshape_pos2())?);
    let contacts = &m.data.solver_contacts;
    let (mut p, mut surface) = (Vector::ZERO, Vector::ZERO);
    for c in contacts {
        let point = m.points.get(c.contact_indices()[0] as usize)?;
        p += (pos1 * point.local_p1 + pos2 * point.local_p2) * 0.5;
        surface += c.tangent_velocity;
    }
    let k = contacts.len().max(1) as f32;
    Some((p / k, surface / k))
}
