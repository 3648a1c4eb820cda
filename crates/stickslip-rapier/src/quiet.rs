//! What recycling keeps between steps (see the `recycle` module for what it decides and
//! why): the quiet colliders, where their bodies were when they went quiet, and the shares of
//! the limit and of rapier's recycle window that decide it.

use crate::collider_map::{AtomicColliderBits, ColliderBits, ColliderMap};
use rapier::prelude::*;

/// Share of the recycle window a quiet body may drift (translation, plus the rotation's chord
/// at the collider's reach) before its contacts are hooked again.
pub(crate) const DRIFT_SHARE: f32 = 0.25;
/// Share of the recycle window a body may move in one step and still be quiet.
pub(crate) const MOTION_SHARE: f32 = 0.05;

/// Which attached colliders have their stickslip flag off, and what decides it.
#[derive(Debug, Default)]
pub(crate) struct Recycling {
    /// Attached colliders whose stickslip hook flag is off: their contacts are quiet.
    pub quiet: ColliderBits,
    /// Where each quiet collider's body (or the collider, without one) was when its flag
    /// went off, and the collider's reach from that pose's origin (m).
    pub poses: ColliderMap<QuietPose>,
    /// Colliders a hooked manifold found not quiet during the step (any thread).
    pub active: AtomicColliderBits,
    /// Colliders to hook again at the next `begin_step` (a material or source changed).
    pub wake: ColliderBits,
    /// Every quiet collider is to be hooked again at the next `begin_step`.
    pub wake_all: bool,
    /// Recycle window (m) of the running step; 0 when rapier does not recycle.
    pub window: f32,
    /// rapier's prediction distance (m) of the running step: shapes closer than this (beyond
    /// their contact skins) get solver contacts. Infinite while rapier runs contact
    /// detections inside a step (`max_ccd_substeps` > 1).
    pub prediction: f32,
    /// Scratch: the quiet set being decided (kept to reuse its memory).
    pub next: ColliderBits,
    /// Scratch: candidates to go quiet whose body is fixed or asleep (or who have none),
    /// found once per step instead of once per pair.
    pub still: ColliderBits,
    /// Scratch: candidates to go quiet that moved more than [`MOTION_SHARE`] of the window in
    /// the step, found once per step instead of once per pair.
    pub moving: ColliderBits,
    /// Scratch: colliders with a touching pair found quiet in the step.
    pub carried: ColliderBits,
}

impl Recycling {
    /// Colliders whose contacts must be hooked at the next step.
    pub fn wake(&mut self, collider: ColliderHandle) {
        self.wake.set(collider, true);
    }
}

/// Where a quiet collider's body (or the collider, without one) was when its flag went off,
/// and the collider's reach from that pose's origin (m): 32 bytes as plain floats, where a
/// `Pose` with its SIMD alignment made the map's slot 80.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct QuietPose {
    /// x y z (z = 0 in 2D).
    pub translation: [f32; 3],
    /// Unit quaternion, x y z w (in 2D: the unit complex, re im, then 0 0).
    pub rotation: [f32; 4],
    pub reach: f32,
}

impl QuietPose {
    pub fn new(pose: &Pose, reach: f32) -> Self {
        let q = pose.rotation;
        #[cfg(not(dim2))]
        let rotation = [q.x, q.y, q.z, q.w];
        #[cfg(dim2)]
        let rotation = [q.re, q.im, 0.0, 0.0];
        QuietPose {
            translation: crate::tangent::world(pose.translation),
            rotation,
            reach,
        }
    }

    pub fn pose(&self) -> Pose {
        #[cfg(not(dim2))]
        let rotation = {
            let [x, y, z, w] = self.rotation;
            Rotation::from_xyzw(x, y, z, w)
        };
        #[cfg(dim2)]
        let rotation = Rotation::from_cos_sin_unchecked(self.rotation[0], self.rotation[1]);
        Pose::from_parts(crate::tangent::vector(self.translation), rotation)
    }
}
