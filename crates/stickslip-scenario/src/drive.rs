//! Applying [`Driver`]s to rapier bodies: the one implementation the [`crate::Runner`] and
//! other front ends (the bevy plugin's scenario loader) share, so a scenario drives its bodies
//! the same way everywhere.

use crate::build::{Driver, DriverAction};
use rapier3d::prelude::*;

/// Applies `drivers` at time `t` (the start of a step of length `dt`) to the bodies
/// `handle(driver.body)` of `bodies`: resets the forces of force-driven bodies (rapier keeps
/// forces until reset), then sets kinematic velocities and adds spring and profile forces
/// (profiles are sampled at the step's midpoint). Bodies no longer in the set are skipped.
pub fn apply_drivers(
    drivers: &[Driver],
    bodies: &mut RigidBodySet,
    handle: impl Fn(usize) -> RigidBodyHandle,
    t: f64,
    dt: f64,
) {
    // Forces persist in rapier until reset: clear the driven bodies' forces first.
    for d in drivers {
        if !matches!(d.action, DriverAction::Velocity { .. })
            && let Some(b) = bodies.get_mut(handle(d.body))
        {
            b.reset_forces(false);
            b.reset_torques(false);
        }
    }
    let t_mid = t + 0.5 * dt;
    for d in drivers {
        let Some(body) = bodies.get_mut(handle(d.body)) else {
            continue;
        };
        match &d.action {
            DriverAction::Velocity {
                linear,
                angular,
                start,
            } => {
                let on = t + 1e-12 >= *start;
                body.set_linvel(if on { *linear } else { Vector::ZERO }, true);
                body.set_angvel(if on { *angular } else { Vector::ZERO }, true);
            }
            DriverAction::Spring {
                stiffness,
                damping,
                anchor,
                anchor_velocity,
                point,
                axis,
            } => {
                let p = body.position().transform_point(*point);
                let v = body.velocity_at_point(p);
                let mut f = [0.0f64; 3];
                for k in 0..3 {
                    let a = anchor[k] + anchor_velocity[k] * t;
                    f[k] = stiffness * (a - p[k] as f64)
                        + damping * (anchor_velocity[k] - v[k] as f64);
                }
                if let Some(e) = axis {
                    let along = f[0] * e[0] + f[1] * e[1] + f[2] * e[2];
                    f = [along * e[0], along * e[1], along * e[2]];
                }
                let force = Vector::new(f[0] as f32, f[1] as f32, f[2] as f32);
                body.add_force_at_point(force, p, true);
            }
            DriverAction::Force {
                direction,
                profile,
                point,
            } => {
                let m = profile.value(t_mid);
                let force = Vector::new(
                    (direction[0] * m) as f32,
                    (direction[1] * m) as f32,
                    (direction[2] * m) as f32,
                );
                match point {
                    Some(local) => {
                        let p = body.position().transform_point(*local);
                        body.add_force_at_point(force, p, true);
                    }
                    None => body.add_force(force, true),
                }
            }
        }
    }
}
