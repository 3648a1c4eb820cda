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
    /// Scratch: colliders that move with a touching pair found quiet in the step (set by
    /// the threads of the pass over the pairs).
    pub carried: AtomicColliderBits,
    /// Scratch: attached colliders hooked at every step (a source or a moving surface on
    /// them), found once per step.
    pub always: ColliderBits,
    /// Scratch: what the pass over the contact pairs found, one list per part of the pairs
    /// (see `recycle::judge_pairs`).
    pub findings: Vec<Vec<crate::recycle::Finding>>,
    /// Scratch: the contact pairs the pass judges (see `pair_list`).
    pub pairs: crate::pair_list::PairList,
    /// Tests only: `Some(true)` walks the pass's pairs, `Some(false)` judges every pair,
    /// whatever their number (see `pair_list`).
    pub walk: Option<bool>,
}

impl Recycling {
    /// Heap bytes held (capacity included): the poses and every bit set.
    pub fn heap_bytes(&self) -> usize {
        [
            &self.quiet,
            &self.wake,
            &self.next,
            &self.still,
            &self.moving,
            &self.always,
        ]
        .iter()
        .map(|b| b.heap_bytes())
        .sum::<usize>()
            + self.poses.heap_bytes()
            + self.active.heap_bytes()
            + self.carried.heap_bytes()
            + self.pairs.heap_bytes()
            + crate::heap::vec_bytes(&self.findings)
            + self
                .findings
                .iter()
                .map(crate::heap::vec_bytes)
                .sum::<usize>()
    }

    /// Colliders whose contacts must be hooked at the next step.
    pub fn wake(&mut self, collider: ColliderHandle) {
        self.wake.set(collider, true);
    }
}

/// The quiet poses, 23 bytes a quiet collider (the pose and the low 8 bits of the collider
/// handle's generation) and a bit per collider: a pose is found by its collider's rank among
/// those with a pose (a bit set per arena index, and a count per 64 of them), so colliders
/// that are not quiet cost no pose (a drum with 1 000 cubes, 24 of them quiet, kept 23 kB of
/// empty slots as a dense vector). Like the quiet bits, the map expects a collider to be
/// detached before it is removed; the generation's low bits keep a pose from reaching a
/// collider that took its index without (unless the index was reused 256 times in between:
/// that collider's drift is then measured from the pose, and it is hooked again when it
/// moves).
#[derive(Debug, Clone, Default)]
pub(crate) struct QuietPoses {
    /// A bit per arena index: the collider has a pose.
    present: Vec<u64>,
    /// Poses kept below each word of `present`.
    below: Vec<u32>,
    /// The poses, by increasing arena index.
    slots: Vec<QuietSlot>,
}

#[derive(Debug, Clone, Copy)]
struct QuietSlot {
    pose: QuietPose,
    generation: u8,
}

impl QuietPoses {
    /// Heap bytes held (capacity included).
    pub fn heap_bytes(&self) -> usize {
        crate::heap::vec_bytes(&self.present)
            + crate::heap::vec_bytes(&self.below)
            + crate::heap::vec_bytes(&self.slots)
    }

    /// Where the pose of arena index `i` is or would go, and whether it is there.
    fn rank(&self, i: usize) -> (usize, bool) {
        let (w, b) = (i / 64, i % 64);
        match self.present.get(w) {
            Some(&word) => (
                self.below[w] as usize + (word & ((1u64 << b) - 1)).count_ones() as usize,
                word >> b & 1 == 1,
            ),
            None => (self.slots.len(), false),
        }
    }

    pub fn insert(&mut self, handle: ColliderHandle, pose: QuietPose) {
        self.update(handle, |_| pose);
    }

    /// Keeps `pose(kept)` for `handle`, `kept` being the pose it has (one lookup).
    pub fn update(
        &mut self,
        handle: ColliderHandle,
        pose: impl FnOnce(Option<QuietPose>) -> QuietPose,
    ) {
        let (i, generation) = handle.0.into_raw_parts();
        if i >= MAX_INDEX {
            return;
        }
        let i = i as usize;
        let generation = generation as u8;
        let (at, here) = self.rank(i);
        if here {
            let slot = &mut self.slots[at];
            let kept = (slot.generation == generation).then_some(slot.pose);
            *slot = QuietSlot {
                pose: pose(kept),
                generation,
            };
            return;
        }
        let slot = QuietSlot {
            pose: pose(None),
            generation,
        };
        let w = i / 64;
        if self.present.len() <= w {
            reserve_slack(&mut self.present, w);
            reserve_slack(&mut self.below, w);
            let n = self.slots.len() as u32;
            self.present.resize(w + 1, 0);
            self.below.resize(w + 1, n);
        }
        self.present[w] |= 1 << (i % 64);
        for b in &mut self.below[w + 1..] {
            *b += 1;
        }
        let n = self.slots.len();
        if n == self.slots.capacity() {
            reserve_slack(&mut self.slots, n);
        }
        self.slots.insert(at, slot);
    }

    pub fn remove(&mut self, handle: ColliderHandle) {
        if self.get(handle).is_some() {
            let i = handle.0.into_raw_parts().0 as usize;
            self.retain(|k| k as usize != i);
        }
    }

    /// Keeps the poses of the arena indices `keep` says (one pass).
    pub fn retain(&mut self, mut keep: impl FnMut(u32) -> bool) {
        let mut kept = 0;
        let mut at = 0;
        for w in 0..self.present.len() {
            self.below[w] = kept as u32;
            let mut word = self.present[w];
            let mut bits = word;
            while bits != 0 {
                let b = bits.trailing_zeros();
                bits &= bits - 1;
                if keep((w * 64) as u32 + b) {
                    if kept != at {
                        self.slots[kept] = self.slots[at];
                    }
                    kept += 1;
                } else {
                    word &= !(1 << b);
                }
                at += 1;
            }
            self.present[w] = word;
        }
        self.slots.truncate(kept);
        let slack = |v: usize, n: usize| v > n + n / 16 + 16;
        if slack(self.slots.capacity(), kept) {
            self.slots.shrink_to(kept + kept / 32);
        }
    }

    pub fn get(&self, handle: ColliderHandle) -> Option<QuietPose> {
        let (i, generation) = handle.0.into_raw_parts();
        let (at, here) = self.rank(i as usize);
        let slot = self.slots.get(at).filter(|_| here)?;
        (slot.generation == generation as u8).then_some(slot.pose)
    }

    /// The poses kept: arena index, low 8 bits of the generation, pose; by increasing index.
    pub fn iter(&self) -> impl Iterator<Item = (u32, u8, QuietPose)> + '_ {
        let indices = self.present.iter().enumerate().flat_map(|(w, &word)| {
            (0..64)
                .filter(move |b| word >> b & 1 == 1)
                .map(move |b| (w * 64 + b) as u32)
        });
        indices
            .zip(&self.slots)
            .map(|(i, s)| (i, s.generation, s.pose))
    }
}

/// Where a quiet collider's body (or the collider, without one) was when its flag went off,
/// and the collider's reach from that pose's origin (m), in 22 bytes: a quiet pose is kept
/// for every collider of a resting pile, beside each contact's 35-byte record (with a
/// SIMD-aligned `Pose` the map's slot was 80 bytes, with every f32 of the pose 32).
///
/// The translation is kept exactly (f32 bits). In 3D the rotation is packed into 64 bits:
/// the quaternion's largest component is dropped (it is the square root of one minus the
/// others', taken non-negative: q and −q are the same rotation) and the other three kept as
/// multiples of 2⁻¹⁹ (each is at most 1/√2). Each of the three is then within 2⁻²⁰ of the
/// body's, the one dropped (at least 1/2) within 3·2⁻²⁰, the quaternions within 2√3·2⁻²⁰
/// and the rotations within twice that: 4√3·2⁻²⁰ ≈ 6.6 µrad. Drift is measured between two
/// packed poses (the body's packed as it would be kept; first bounded from the packed
/// rotations, [`Self::surely_within`]), so a body that does not move has drifted by exactly
/// nothing whatever its reach (a ground tens of metres wide), and one that moves is measured within
/// twice that error times its reach (0.7 mm at 50 m, against a quarter of rapier's 50 mm
/// window). In 2D the unit complex is kept exactly. The reach is rounded up to 8
/// significant bits (bfloat16), so the drift it measures is never less than the exact
/// reach's.
// Packed to 1-byte alignment: 22 bytes, 23 with the generation.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[repr(C, packed)]
pub(crate) struct QuietPose {
    /// x y z (z = 0 in 2D), f32 bits.
    translation: [u32; 3],
    /// 3D: the packed quaternion (see [`pack_rotation`]); 2D: the unit complex, re im, f32 bits.
    rotation: [u32; 2],
    /// bfloat16 bits of the reach (m), never 0.
    reach: std::num::NonZeroU16,
}

/// Scale of a packed quaternion component: 2¹⁹ units per 1 (a component other than the
/// largest is at most 1/√2, so it fits in 20 bits with its sign).
#[cfg(not(dim2))]
const COMPONENT_SCALE: f32 = (1u32 << 19) as f32;
/// Bits of a packed quaternion component.
#[cfg(not(dim2))]
const COMPONENT_BITS: u32 = 20;

/// A unit quaternion x y z w in 64 bits: the three components other than the largest (in
/// order, negated when the largest is negative) as 20-bit two's-complement multiples of 2⁻¹⁹
/// from bit 0, and the largest's index in bits 60–61.
#[cfg(not(dim2))]
fn pack_rotation(q: [f32; 4]) -> [u32; 2] {
    let mut big = 0;
    for i in 1..4 {
        if q[i].abs() > q[big].abs() {
            big = i;
        }
    }
    let sign = if q[big] < 0.0 { -1.0 } else { 1.0 };
    let limit = 1i64 << (COMPONENT_BITS - 1);
    let mut bits = (big as u64) << 60;
    let mut shift = 0;
    for (i, &v) in q.iter().enumerate() {
        if i == big {
            continue;
        }
        // A saturating cast: a value that is not a number packs to 0, never panics.
        let k = ((v * sign * COMPONENT_SCALE).round() as i64).clamp(-limit, limit - 1);
        bits |= (k as u64 & ((1 << COMPONENT_BITS) - 1)) << shift;
        shift += COMPONENT_BITS;
    }
    [bits as u32, (bits >> 32) as u32]
}

/// The quaternion x y z w of [`pack_rotation`]'s bits (unit to f32 rounding).
#[cfg(not(dim2))]
fn unpack_rotation(packed: [u32; 2]) -> [f32; 4] {
    let bits = packed[0] as u64 | (packed[1] as u64) << 32;
    let big = (bits >> 60) as usize & 3;
    let mut q = [0.0f32; 4];
    let (mut shift, mut sum) = (0, 0.0f32);
    for (i, v) in q.iter_mut().enumerate() {
        if i == big {
            continue;
        }
        let field = ((bits >> shift) as u32) << (32 - COMPONENT_BITS);
        // Sign-extends the field; the multiple of 2⁻¹⁹ is exact in f32.
        *v = ((field as i32) >> (32 - COMPONENT_BITS)) as f32 / COMPONENT_SCALE;
        sum += *v * *v;
        shift += COMPONENT_BITS;
    }
    q[big] = (1.0 - sum).max(0.0).sqrt();
    q
}

impl QuietPose {
    pub fn new(pose: &Pose, reach: f32) -> Self {
        let [x, y, z] = crate::tangent::world(pose.translation);
        let q = pose.rotation;
        #[cfg(not(dim2))]
        let rotation = pack_rotation([q.x, q.y, q.z, q.w]);
        #[cfg(dim2)]
        let rotation = [q.re.to_bits(), q.im.to_bits()];
        QuietPose {
            translation: [x.to_bits(), y.to_bits(), z.to_bits()],
            rotation,
            reach: reach_up(reach),
        }
    }

    /// The pose kept.
    pub fn pose(&self) -> Pose {
        let [x, y, z] = { self.translation }.map(f32::from_bits);
        #[cfg(not(dim2))]
        let rotation = {
            let [a, b, c, d] = unpack_rotation(self.rotation);
            Rotation::from_xyzw(a, b, c, d)
        };
        #[cfg(dim2)]
        let rotation = {
            let [re, im] = { self.rotation }.map(f32::from_bits);
            Rotation::from_cos_sin_unchecked(re, im)
        };
        Pose::from_parts(crate::tangent::vector([x, y, z]), rotation)
    }

    /// Whether the drift from this kept pose to `now` (the body's pose packed the same way:
    /// drift is measured between packed poses) at `reach`, plus `motion`, is surely at most
    /// `limit`, told from the packed rotations without unpacking them: `false` when the bound
    /// cannot tell, and the drift is then measured.
    ///
    /// For unit quaternions a and b, the half-turn sine between them is
    /// √(1 − (a·b)²) = |a − b| |a + b| / 2 ≤ |a − b|. Packed with the same largest component,
    /// the other three differ by whole multiples of 2⁻¹⁹, and the largest ones (each at least
    /// 1/2, so their sum at least 1) by (Σb² − Σa²)/(a_max + b_max), at most |Σb² − Σa²|, the
    /// sums over the other three. The bound, with a margin for the f32 arithmetic of the
    /// measured drift, is at least what that measurement gives: where the bound says
    /// within, the measurement says so too, and the two decide alike.
    #[cfg(not(dim2))]
    pub fn surely_within(&self, now: &QuietPose, reach: f32, motion: f32, limit: f32) -> bool {
        // Slack on the half-turn sine for the rounding of the measured one (a few f32 ulps of
        // quaternion components) and relative margin for the sums in f32.
        const SINE_SLACK: f64 = 1e-6;
        const MARGIN: f64 = 1e-4;
        let bits = |p: [u32; 2]| p[0] as u64 | (p[1] as u64) << 32;
        let (a, b) = (bits(self.rotation), bits(now.rotation));
        if (a >> 60) & 3 != (b >> 60) & 3 {
            return false;
        }
        let (mut diff, mut sum_a, mut sum_b) = (0i64, 0i64, 0i64);
        for i in 0..3 {
            let field = |x: u64| {
                let f = ((x >> (COMPONENT_BITS * i)) as u32) << (32 - COMPONENT_BITS);
                ((f as i32) >> (32 - COMPONENT_BITS)) as i64
            };
            let (ka, kb) = (field(a), field(b));
            diff += (ka - kb) * (ka - kb);
            sum_a += ka * ka;
            sum_b += kb * kb;
        }
        let unit = 1.0 / (COMPONENT_SCALE as f64 * COMPONENT_SCALE as f64);
        let largest = (sum_b - sum_a) as f64 * unit;
        let sine = (diff as f64 * unit + largest * largest).sqrt() + SINE_SLACK;
        let [ta, tb] = [self.translation, now.translation]
            .map(|t| crate::tangent::vector(t.map(f32::from_bits)));
        let translation = (tb - ta).length() as f64;
        let bound = translation + 2.0 * sine * reach as f64 + motion as f64;
        bound <= limit as f64 * (1.0 - MARGIN)
    }

    /// The reach kept (m): the one given, rounded up to 8 significant bits.
    pub fn reach(&self) -> f32 {
        f32::from_bits(({ self.reach }.get() as u32) << 16)
    }

    /// The stored form (for snapshots): translation, the rotation's bits as kept (see
    /// [`QuietPose`]), bfloat16 bits of the reach.
    pub fn stored(&self) -> ([f32; 3], [u32; 2], u16) {
        (
            { self.translation }.map(f32::from_bits),
            self.rotation,
            { self.reach }.get(),
        )
    }

    /// The pose of a stored form (from [`Self::stored`]); `None` for a reach of 0 bits, a
    /// translation or reach that is not finite, or a rotation that is not a unit one.
    pub fn from_stored(translation: [f32; 3], rotation: [u32; 2], reach: u16) -> Option<Self> {
        let pose = QuietPose {
            translation: translation.map(f32::to_bits),
            rotation,
            reach: std::num::NonZeroU16::new(reach)?,
        };
        #[cfg(not(dim2))]
        let unit = unpack_rotation(rotation).iter().map(|v| v * v).sum::<f32>();
        #[cfg(dim2)]
        let unit = rotation
            .map(f32::from_bits)
            .iter()
            .map(|v| v * v)
            .sum::<f32>();
        let finite = translation.iter().all(|v| v.is_finite()) && pose.reach().is_finite();
        (finite && (unit - 1.0).abs() < 1e-4).then_some(pose)
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

/// A fixed sequence of numbers in [−1, 1) from `seed` (xorshift), for the tests.
#[cfg(test)]
pub(crate) fn uniform_sequence(mut seed: u64) -> impl FnMut() -> f32 {
    move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 40) as f32 / (1u64 << 24) as f32 * 2.0 - 1.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The angle (rad) of the rotation between two 3D poses.
    #[cfg(not(dim2))]
    fn angle(a: &Pose, b: &Pose) -> f32 {
        let turn = (b.rotation * a.rotation.inverse()).normalize();
        2.0 * Vector::new(turn.x, turn.y, turn.z).length().min(1.0).asin()
    }

    #[test]
    fn stored_poses_come_back_exactly() {
        #[cfg(not(dim2))]
        let r = Rotation::from_axis_angle(Vector::new(0.3, -0.4, 0.5).normalize(), 2.9);
        #[cfg(dim2)]
        let r = Rotation::new(2.9);
        let pose = Pose::from_parts(crate::tangent::vector([1.25, -2.5, 1e4]), r);
        let q = QuietPose::new(&pose, 0.7);
        assert_eq!(q.pose().translation, pose.translation);
        let (t, r, reach) = q.stored();
        assert_eq!(QuietPose::from_stored(t, r, reach), Some(q));
        assert_eq!(QuietPose::from_stored(t, r, 0), None);
        assert_eq!(QuietPose::from_stored([f32::NAN, 0.0, 0.0], r, reach), None);
        // The body's pose, packed again, is the kept one bit for bit: unmoved, no drift.
        assert_eq!(QuietPose::new(&pose, 0.0).pose(), q.pose());
        // A stored rotation that is not a unit one (untrusted snapshot files) is refused.
        #[cfg(not(dim2))]
        let bad = {
            let max = (1u64 << 19) - 1;
            let bits = max | max << 20 | max << 40;
            [bits as u32, (bits >> 32) as u32]
        };
        #[cfg(dim2)]
        let bad = [0, 0];
        assert_eq!(QuietPose::from_stored(t, bad, reach), None);
    }

    /// Over rotations of every axis and angle (a fixed sequence), and the corner cases of
    /// the packing (a component of ±1, two of equal size, a negative largest one), the pose
    /// kept is within 4√3·2⁻²⁰ rad of the body's (exactly in 2D) and a unit rotation to f32
    /// rounding.
    #[test]
    fn kept_rotations_are_within_the_packing_error() {
        let bound = 4.0 * 3f32.sqrt() / (1u32 << 20) as f32;
        let mut rotations = Vec::new();
        let mut next = uniform_sequence(0x9E37_79B9_7F4A_7C15);
        for _ in 0..20_000 {
            let (x, y, z, a) = (next(), next(), next(), next() * std::f32::consts::PI);
            #[cfg(not(dim2))]
            rotations.push(Rotation::from_axis_angle(
                Vector::new(x, y, z + 1e-3).normalize(),
                a,
            ));
            #[cfg(dim2)]
            {
                let _ = (x, y, z);
                rotations.push(Rotation::new(a));
            }
        }
        #[cfg(not(dim2))]
        {
            let h = std::f32::consts::FRAC_1_SQRT_2;
            for q in [
                [1.0, 0.0, 0.0, 0.0],
                [0.0, -1.0, 0.0, 0.0],
                [0.0, 0.0, 0.0, -1.0],
                [h, h, 0.0, 0.0],
                [0.0, -h, 0.0, h],
                [0.5, -0.5, 0.5, -0.5],
                [-0.1, 0.2, -0.3, -(1.0f32 - 0.14).sqrt()],
            ] {
                rotations.push(Rotation::from_xyzw(q[0], q[1], q[2], q[3]).normalize());
            }
        }
        for r in rotations {
            let pose = Pose::from_parts(crate::tangent::vector([3.0, -1.0, 0.5]), r);
            let q = QuietPose::new(&pose, 1.0);
            let kept = q.pose();
            #[cfg(not(dim2))]
            {
                assert!(
                    angle(&pose, &kept) <= bound,
                    "{r:?}: {}",
                    angle(&pose, &kept)
                );
                assert!((kept.rotation.length() - 1.0).abs() < 1e-6, "{r:?}");
            }
            #[cfg(dim2)]
            {
                let _ = bound;
                assert_eq!(kept, pose);
            }
        }
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
    fn a_slot_of_the_quiet_map_is_23_bytes() {
        assert_eq!(std::mem::size_of::<QuietSlot>(), 23);
    }

    /// Against a map of the same poses, over inserts, replacements, removals and one-pass
    /// retains at indices spread over several words (a fixed sequence): every lookup, the
    /// order of `iter`, and a pose per kept collider only.
    #[test]
    fn the_quiet_map_reads_as_a_map_of_its_poses() {
        let mut poses = QuietPoses::default();
        let mut model = std::collections::BTreeMap::new();
        let mut uniform = uniform_sequence(0x9E37_79B9_7F4A_7C15);
        let mut next = |n: u64| (((uniform() * 0.5 + 0.5) * n as f32) as u64).min(n - 1);
        for round in 0..4000u32 {
            let i = next(700) as u32;
            let generation = next(3) as u32;
            let h = ColliderHandle::from_raw_parts(i, generation);
            match next(10) {
                0..=5 => {
                    let pose = QuietPose::new(&Pose::IDENTITY, 0.1 + round as f32);
                    poses.insert(h, pose);
                    model.insert(i, (generation as u8, pose));
                }
                6..=8 => {
                    poses.remove(h);
                    if model.get(&i).is_some_and(|(g, _)| *g == generation as u8) {
                        model.remove(&i);
                    }
                }
                _ => {
                    let cut = next(700) as u32;
                    poses.retain(|k| k % 3 != 0 || k < cut);
                    model.retain(|k, _| k % 3 != 0 || *k < cut);
                }
            }
            if round % 97 == 0 {
                for k in 0..720u32 {
                    for g in 0..3u32 {
                        let want = model
                            .get(&k)
                            .filter(|(mg, _)| *mg == g as u8)
                            .map(|(_, p)| *p);
                        assert_eq!(poses.get(ColliderHandle::from_raw_parts(k, g)), want);
                    }
                }
                let listed: Vec<_> = poses.iter().collect();
                let expected: Vec<_> = model.iter().map(|(&k, &(g, p))| (k, g, p)).collect();
                assert_eq!(listed, expected);
                assert_eq!(poses.slots.len(), model.len());
            }
        }
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
        assert_eq!(poses.slots.len(), 1);
        assert_eq!(poses.iter().collect::<Vec<_>>(), [(5, 1, pose)]);
        poses.remove(ColliderHandle::from_raw_parts(5, 2));
        assert_eq!(poses.get(a), Some(pose));
        poses.remove(a);
        assert_eq!(poses.get(a), None);
        assert_eq!(poses.iter().count(), 0);
    }
}
