//! What recycling keeps between steps (see the `recycle` module for what it decides and
//! why): the quiet colliders, where their bodies were when they went quiet, and the shares of
//! the limit and of rapier's recycle window that decide it.

use crate::collider_map::{AtomicColliderBits, ColliderBits, MAX_INDEX, reserve_slack};
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
    pub poses: QuietPoses,
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

/// The quiet poses by collider arena index, 32 bytes a slot: the pose and the low 16 bits of
/// the collider handle's generation (a slot is empty without a pose). Like the quiet
/// bits, the map expects a collider to be detached before it is removed; the generation's
/// low bits keep a pose from reaching a collider that took its index without (unless the
/// index was reused 65 536 times in between: that collider's drift is then measured from
/// the pose, and it is hooked again when it moves).
#[derive(Debug, Clone, Default)]
pub(crate) struct QuietPoses {
    slots: Vec<QuietSlot>,
}

#[derive(Debug, Clone, Copy, Default)]
struct QuietSlot {
    pose: Option<QuietPose>,
    generation: u16,
}

impl QuietPoses {
    pub fn insert(&mut self, handle: ColliderHandle, pose: QuietPose) {
        let (i, generation) = handle.0.into_raw_parts();
        if i >= MAX_INDEX {
            return;
        }
        let i = i as usize;
        if self.slots.len() <= i {
            reserve_slack(&mut self.slots, i);
            self.slots.resize(i + 1, QuietSlot::default());
        }
        self.slots[i] = QuietSlot {
            pose: Some(pose),
            generation: generation as u16,
        };
    }

    pub fn remove(&mut self, handle: ColliderHandle) {
        if self.get(handle).is_some() {
            let i = handle.0.into_raw_parts().0 as usize;
            self.slots[i].pose = None;
        }
    }

    pub fn get(&self, handle: ColliderHandle) -> Option<QuietPose> {
        let (i, generation) = handle.0.into_raw_parts();
        let slot = self.slots.get(i as usize)?;
        slot.pose.filter(|_| slot.generation == generation as u16)
    }

    /// The poses kept: arena index, low 16 bits of the generation, pose; by increasing index.
    pub fn iter(&self) -> impl Iterator<Item = (u32, u16, QuietPose)> + '_ {
        self.slots
            .iter()
            .enumerate()
            .filter_map(|(i, s)| Some((i as u32, s.generation, s.pose?)))
    }
}

/// Where a quiet collider's body (or the collider, without one) was when its flag went off,
/// and the collider's reach from that pose's origin (m), in 30 bytes: a quiet pose is kept
/// for every collider of a resting pile, beside each contact's 35-byte record (with a
/// SIMD-aligned `Pose` the map's slot was 80 bytes).
///
/// The pose is kept exactly (f32 bits: a ground's reach is tens of metres, where a rotation
/// packed to 1e-4 rad would move its rim by millimetres, beyond the drift allowed). The reach
/// is rounded up to 8 significant bits (bfloat16), so the drift it measures is never less than
/// the exact reach's.
// Packed to 2-byte alignment: 30 bytes, and an empty slot (`None`, by the reach's niche) and
// the generation fit in 32.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[repr(C, packed(2))]
pub(crate) struct QuietPose {
    /// x y z (z = 0 in 2D), f32 bits.
    translation: [u32; 3],
    /// Unit quaternion x y z w (in 2D: the unit complex, re im, then 0 0), f32 bits.
    rotation: [u32; 4],
    /// bfloat16 bits of the reach (m), never 0.
    reach: std::num::NonZeroU16,
}

impl QuietPose {
    pub fn new(pose: &Pose, reach: f32) -> Self {
        let [x, y, z] = crate::tangent::world(pose.translation);
        let q = pose.rotation;
        #[cfg(not(dim2))]
        let rotation = [q.x, q.y, q.z, q.w];
        #[cfg(dim2)]
        let rotation = [q.re, q.im, 0.0, 0.0];
        QuietPose {
            translation: [x.to_bits(), y.to_bits(), z.to_bits()],
            rotation: rotation.map(f32::to_bits),
            reach: reach_up(reach),
        }
    }

    /// The pose kept.
    pub fn pose(&self) -> Pose {
        let [x, y, z] = self.translation.map(f32::from_bits);
        let [a, b, c, d] = self.rotation.map(f32::from_bits);
        #[cfg(not(dim2))]
        let rotation = Rotation::from_xyzw(a, b, c, d);
        #[cfg(dim2)]
        let rotation = {
            let _ = (c, d);
            Rotation::from_cos_sin_unchecked(a, b)
        };
        Pose::from_parts(crate::tangent::vector([x, y, z]), rotation)
    }

    /// The reach kept (m): the one given, rounded up to 8 significant bits.
    pub fn reach(&self) -> f32 {
        f32::from_bits(({ self.reach }.get() as u32) << 16)
    }

    /// The stored form (for snapshots): translation, rotation, bfloat16 bits of the reach.
    pub fn stored(&self) -> ([f32; 3], [f32; 4], u16) {
        (
            self.translation.map(f32::from_bits),
            self.rotation.map(f32::from_bits),
            { self.reach }.get(),
        )
    }

    /// The pose of a stored form (from [`Self::stored`]); `None` for a reach of 0 bits.
    pub fn from_stored(translation: [f32; 3], rotation: [f32; 4], reach: u16) -> Option<Self> {
        Some(QuietPose {
            translation: translation.map(f32::to_bits),
            rotation: rotation.map(f32::to_bits),
            reach: std::num::NonZeroU16::new(reach)?,
        })
    }
}

/// The bfloat16 bits of `reach` rounded up (never 0: the smallest positive value).
fn reach_up(reach: f32) -> std::num::NonZeroU16 {
    let bits = reach.max(0.0).to_bits();
    let mut high = (bits >> 16) as u16;
    if bits & 0xFFFF != 0 && reach.is_finite() {
        high = high.saturating_add(1);
    }
    std::num::NonZeroU16::new(high).unwrap_or(std::num::NonZeroU16::MIN)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stored_poses_come_back_exactly() {
        #[cfg(not(dim2))]
        let r = Rotation::from_axis_angle(Vector::new(0.3, -0.4, 0.5).normalize(), 2.9);
        #[cfg(dim2)]
        let r = Rotation::new(2.9);
        let pose = Pose::from_parts(crate::tangent::vector([1.25, -2.5, 1e4]), r);
        let q = QuietPose::new(&pose, 0.7);
        assert_eq!(q.pose(), pose);
        let (t, r, reach) = q.stored();
        assert_eq!(QuietPose::from_stored(t, r, reach), Some(q));
        assert_eq!(QuietPose::from_stored(t, r, 0), None);
    }

    #[test]
    fn reach_is_rounded_up() {
        for reach in [0.0f32, 1e-30, 0.3, 0.7, 1.0, 2.5, 123.456, 1e20] {
            let kept = QuietPose::new(&Pose::IDENTITY, reach).reach();
            assert!(
                kept >= reach && kept <= reach * (1.0 + 1.0 / 128.0) + 1e-38,
                "{reach} {kept}"
            );
        }
    }

    #[test]
    fn a_slot_of_the_quiet_map_is_32_bytes() {
        assert_eq!(std::mem::size_of::<QuietSlot>(), 32);
    }

    #[test]
    fn the_quiet_map_tells_colliders_apart() {
        let mut poses = QuietPoses::default();
        let a = ColliderHandle::from_raw_parts(5, 1);
        let pose = QuietPose::new(&Pose::IDENTITY, 0.5);
        poses.insert(a, pose);
        assert_eq!(poses.get(a), Some(pose));
        // Another collider at the same index, one at another index, one beyond the map.
        assert_eq!(poses.get(ColliderHandle::from_raw_parts(5, 2)), None);
        assert_eq!(poses.get(ColliderHandle::from_raw_parts(6, 1)), None);
        poses.insert(ColliderHandle::from_raw_parts(MAX_INDEX, 0), pose);
        assert_eq!(poses.slots.len(), 6);
        assert_eq!(poses.iter().collect::<Vec<_>>(), [(5, 1, pose)]);
        poses.remove(ColliderHandle::from_raw_parts(5, 2));
        assert_eq!(poses.get(a), Some(pose));
        poses.remove(a);
        assert_eq!(poses.get(a), None);
        assert_eq!(poses.iter().count(), 0);
    }
}
