//! The one place that knows bevy's glam (0.32) and rapier's glam (0.33) are different types:
//! conversions by value through arrays (a register move, no layout assumptions).

use bevy::prelude::{Quat, Transform, Vec3};
use rapier3d::prelude as rp;

/// bevy vector → rapier vector.
pub fn to_rapier(v: Vec3) -> rp::Vector {
    rp::Vector::from_array(v.to_array())
}

/// rapier vector → bevy vector.
pub fn to_bevy(v: rp::Vector) -> Vec3 {
    Vec3::from_array(v.to_array())
}

/// bevy rotation → rapier rotation.
pub fn rot_to_rapier(q: Quat) -> rp::Rotation {
    rp::Rotation::from_array(q.to_array())
}

/// rapier rotation → bevy rotation.
pub fn rot_to_bevy(q: rp::Rotation) -> Quat {
    Quat::from_array(q.to_array())
}

/// A `Transform`'s translation and rotation as a rapier pose (scale is ignored by rapier).
pub fn pose_of(t: &Transform) -> rp::Pose {
    rp::Pose::from_parts(to_rapier(t.translation), rot_to_rapier(t.rotation))
}
