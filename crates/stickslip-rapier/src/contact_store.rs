//! Per-contact friction state that lives as long as its contact manifold: 35 bytes a contact
//! (39 in rapier 0.35 builds).
//!
//! Lookup is cheap: a manifold's `user_data` holds its slot index (+1) and an 8-bit
//! generation, so the hook reaches its record with one uncontended read lock and one
//! per-slot lock (a one-byte `parking_lot` mutex), never a global map under one lock per
//! contact. Only manifolds whose `user_data` is 0 — new ones, and rapier's merged "cluster"
//! manifolds whose `user_data` is reset every step — go through a map keyed by the collider
//! pair and which of its manifolds it is ([`ManifoldPart`]); a manifold found through its
//! `user_data` leaves that map, so at steady state it holds only the cluster manifolds.
//!
//! **Locking.** [`ContactStore::with_record`] runs the caller's code on a copy of the record
//! while it holds the slot's lock, and stores the copy back when the code returns. The caller
//! is stickslip's own per-manifold step only: the hook runs the wrapped user hook before,
//! with no lock of stickslip's held, so a user hook that is slow or calls back never blocks
//! another contact. A panic (the user hook's, or stickslip's own) leaves no lock held: the
//! guards release on unwind, and an interrupted record keeps its last stored state.
//!
//! Rapier does not report vanished manifolds, so [`ContactStore::sweep`] drops every record
//! not touched during the step: memory tracks the active contacts (manifolds of sleeping
//! pairs, which rapier keeps, are touched by the modifier's end-of-step read-back and keep
//! their state). New records take the lowest free slot and the sweep cuts free slots off the
//! end, so the store shrinks back after churn; a recycled slot gets a new generation so stale
//! `user_data` never reaches another contact's state.
//!
//! The stored form ([`Slot`]) packs the record, byte-aligned: the slip speed of the last step
//! (used only to extrapolate an accelerating slip) is kept as a bfloat16 (8 significant bits),
//! the colliders by arena index on 24 bits each (a pair with a collider beyond 2^24 gets a
//! fresh record every step: see [`ContactStore::with_record`]), and liveness, sweep parity,
//! regime and generation share one 16-bit word. The hook works on the unpacked
//! [`ContactRecord`].

use crate::fast_hash::HashMap;
use rapier::prelude::{ColliderHandle, Vector};
use std::cmp::Reverse;
use std::collections::BinaryHeap;
use std::sync::atomic::{AtomicBool, AtomicU32, Ordering};
use std::sync::{Mutex, RwLock};
use stickslip_core::contact::{ContactState, REGIME_RESET};

/// What identifies a manifold across steps: the collider pair and which of its manifolds.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub(crate) struct ContactKey {
    pub c1: ColliderHandle,
    pub c2: ColliderHandle,
    pub part: ManifoldPart,
}

/// Which manifold of a collider pair. Feature ids are not part of it: a manifold keeps its
/// identity while its points come and go (a box tipping onto an edge, a cube sliding across
/// a mesh's triangles).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub(crate) enum ManifoldPart {
    /// The only manifold of two convex shapes.
    Whole,
    /// The manifold of one sub-shape pair of a composite shape (with contact clustering off).
    Subshapes(u32, u32),
    /// A contact patch of a composite shape: rapier clusters the per-sub-shape manifolds
    /// whose normals agree within ~5° into one solver manifold, rebuilt every step, so the
    /// patch is identified by its normal in collider 1's frame, on a grid of 0.02 per
    /// component (two clusters' normals differ by at least 0.05 in some component).
    Cluster([i8; 3]),
}

impl ManifoldPart {
    /// The cluster cell of a unit normal.
    pub fn cluster(normal: Vector) -> ManifoldPart {
        let cell = |x: f32| (x.clamp(-1.0, 1.0) * 50.0).round() as i8;
        let [x, y, z] = crate::tangent::world(normal);
        ManifoldPart::Cluster([cell(x), cell(y), cell(z)])
    }
}

/// Whether a shape reaches the narrow phase as parts, each pair of parts with its own
/// manifold.
pub(crate) fn is_composite(shape: &dyn rapier::prelude::Shape) -> bool {
    shape.as_composite_shape().is_some()
        || matches!(
            shape.shape_type(),
            rapier::prelude::ShapeType::HeightField | rapier::prelude::ShapeType::Voxels
        )
}

/// The state of one contact manifold, as the hook works on it: the kernel's state and what
/// the adapter keeps beside it.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct ContactRecord {
    /// The friction kernel's state of the contact.
    pub state: ContactState,
    /// The wrapped user hook's own `user_data` for this manifold (we own the field).
    pub inner_user_data: u32,
    /// The record holds the hook's next step already: `end_step` did it for a manifold it
    /// let rapier recycle (see `recycle`).
    pub ahead: bool,
    /// rapier 0.35 only: the warm-start impulse the manifold's points carried into the last
    /// solve (summed), which 0.35 leaves in the impulse it reports (see `rapier_compat`).
    #[cfg(rapier_035)]
    pub warm_start_impulse: f32,
}

/// A value rounded (towards zero) to bfloat16: what the store keeps of a slip speed.
pub(crate) fn to_bf16(x: f32) -> u16 {
    (x.to_bits() >> 16) as u16
}

/// The f32 a bfloat16 stands for.
pub(crate) fn from_bf16(x: u16) -> f32 {
    f32::from_bits((x as u32) << 16)
}

// The metadata word of a slot.
/// `ContactRecord::ahead`.
const AHEAD: u16 = 1;
const LIVE: u16 = 1 << 1;
/// Parity of the step that last touched the record (the sweep runs every step).
const TOUCHED: u16 = 1 << 2;
/// Bit 0 of `ContactRecord::forming` (bit 1 is the sign bit of the stored slip speed, which
/// is never negative).
const FORMING: u16 = 1 << 3;
const SLIP_FORMING: u16 = 1 << 15;
/// The record has an entry in the key map.
const KEYED: u16 = 1 << 7;
const REGIME_SHIFT: u16 = 4;
const REGIME_MASK: u16 = 0b111 << REGIME_SHIFT;
const GENERATION_SHIFT: u16 = 8;

fn pack_regime(code: u8) -> u16 {
    let small = match code {
        0..=2 => code,
        u8::MAX => 3,
        _ => 4, // REGIME_RESET
    };
    (small as u16) << REGIME_SHIFT
}

fn unpack_regime(meta: u16) -> u8 {
    match (meta & REGIME_MASK) >> REGIME_SHIFT {
        c @ 0..=2 => c as u8,
        3 => u8::MAX,
        _ => REGIME_RESET,
    }
}

fn generation_of(meta: u16) -> u8 {
    (meta >> GENERATION_SHIFT) as u8
}

fn parity(step: u32) -> u16 {
    if step & 1 == 1 { TOUCHED } else { 0 }
}

/// Largest collider arena index (exclusive) a record can keep: 24 bits.
const PAIR_LIMIT: u32 = 1 << 24;

/// The arena indices of a pair, 24 bits each (`None` beyond [`PAIR_LIMIT`]).
fn pair_bytes(c1: u32, c2: u32) -> Option<[u8; 6]> {
    if c1 >= PAIR_LIMIT || c2 >= PAIR_LIMIT {
        return None;
    }
    let (a, b) = (c1.to_le_bytes(), c2.to_le_bytes());
    Some([a[0], a[1], a[2], b[0], b[1], b[2]])
}

/// The stored record: 30 bytes, packed (no padding: a slot is an array of them).
#[derive(Debug, Clone, Copy, Default)]
#[repr(C, packed)]
struct Packed {
    force: [f32; 3],
    slide: f32,
    limit: f32,
    mean_normal_force: f32,
    /// Arena indices of the pair's colliders, 24 bits each (a check that `user_data` is this
    /// pair's, and the pair the sweep asks rapier about).
    pair: [u8; 6],
    /// See `ContactRecord::warm_start_impulse`.
    #[cfg(rapier_035)]
    warm_start_impulse: f32,
}

impl Packed {
    fn c1(&self) -> u32 {
        let p = self.pair;
        u32::from_le_bytes([p[0], p[1], p[2], 0])
    }

    fn c2(&self) -> u32 {
        let p = self.pair;
        u32::from_le_bytes([p[3], p[4], p[5], 0])
    }
}

/// What a slot holds: 34 bytes, packed.
#[derive(Debug, Clone, Copy, Default)]
#[repr(C, packed)]
struct SlotData {
    packed: Packed,
    slip_speed: u16,
    meta: u16,
}

/// One slot: its data behind a one-byte mutex, 35 bytes. The lock is held only to copy the
/// record in or out (see the module docs), never while other code runs.
#[derive(Debug, Default)]
pub(crate) struct Slot(parking_lot::Mutex<SlotData>);

impl Slot {
    fn dead(generation: u8) -> Self {
        Slot(parking_lot::Mutex::new(SlotData {
            meta: (generation as u16) << GENERATION_SHIFT,
            ..SlotData::default()
        }))
    }

    fn data(&mut self) -> &mut SlotData {
        self.0.get_mut()
    }

    fn meta(&mut self) -> u16 {
        self.0.get_mut().meta
    }

    fn set_meta(&mut self, meta: u16) {
        self.0.get_mut().meta = meta;
    }
}

fn unpack(p: &Packed, slip: u16, meta: u16) -> ContactRecord {
    ContactRecord {
        state: ContactState {
            force: p.force,
            slide: p.slide,
            limit: p.limit,
            slip_speed: from_bf16(slip & !SLIP_FORMING),
            mean_normal_force: p.mean_normal_force,
            regime: unpack_regime(meta),
            forming: u8::from(meta & FORMING != 0) | u8::from(slip & SLIP_FORMING != 0) << 1,
        },
        inner_user_data: 0,
        ahead: meta & AHEAD != 0,
        #[cfg(rapier_035)]
        warm_start_impulse: p.warm_start_impulse,
    }
}

fn pack(record: &ContactRecord, pair: [u8; 6]) -> (Packed, u16) {
    let r = &record.state;
    (
        Packed {
            force: r.force,
            slide: r.slide,
            limit: r.limit,
            mean_normal_force: r.mean_normal_force,
            pair,
            #[cfg(rapier_035)]
            warm_start_impulse: record.warm_start_impulse,
        },
        (to_bf16(r.slip_speed) & !SLIP_FORMING) | if r.forming & 2 != 0 { SLIP_FORMING } else { 0 },
    )
}

fn with_state(meta: u16, record: &ContactRecord) -> u16 {
    let r = &record.state;
    let forming = if r.forming & 1 != 0 { FORMING } else { 0 };
    let ahead = if record.ahead { AHEAD } else { 0 };
    (meta & !(REGIME_MASK | FORMING | AHEAD)) | pack_regime(r.regime) | forming | ahead
}

/// Whether slot data `d` is a live record of the pair `(c1, c2)` (of `generation`, if given).
fn fits(d: &SlotData, c1: u32, c2: u32, generation: Option<u8>) -> bool {
    d.meta & LIVE != 0
        && generation.is_none_or(|g| g == generation_of(d.meta))
        && d.packed.c1() == c1
        && d.packed.c2() == c2
}

fn index_of(h: ColliderHandle) -> u32 {
    h.0.into_raw_parts().0
}

/// Slab of contact records.
#[derive(Debug, Default)]
pub(crate) struct ContactStore {
    slots: RwLock<Vec<Slot>>,
    by_key: Mutex<HashMap<ContactKey, u32>>,
    /// Free slot indices, lowest first.
    free: Mutex<BinaryHeap<Reverse<u32>>>,
    /// The wrapped hook's `user_data` per slot, for hooks that use it (none by default).
    inner_data: Mutex<HashMap<u32, u32>>,
    /// Whether any inner `user_data` was ever stored (then the hook consults `inner_data`).
    inner_used: AtomicBool,
    /// Generation given to the next slot pushed, so that a slot cut off the end and pushed
    /// again does not restart at the generation stale `user_data` may still carry.
    next_generation: std::sync::atomic::AtomicU8,
    /// Records created since the last sweep (see [`ContactStore::churned`]).
    created: AtomicU32,
    /// No free slot lies below this index (a hint the hook reads without a lock: a record
    /// above a free slot moves down into it, see [`ContactStore::with_record`]).
    free_floor: AtomicU32,
}

/// The lowest free slot of a free list (`u32::MAX` if none): the store's `free_floor`.
fn lowest(free: &BinaryHeap<Reverse<u32>>) -> u32 {
    free.peek().map_or(u32::MAX, |r| r.0)
}

/// A store sweeps before its next regular sweep once it has created this share of its
/// slots since the last one (see [`ContactStore::churned`]).
const CHURN_SHARE: usize = 16;

/// Fewest records created since the last sweep that count as churn (a small world sweeps
/// on its regular interval).
const CHURN_MIN: usize = 8;

pub(crate) const INDEX_BITS: u32 = 24;
const INDEX_MASK: u32 = (1 << INDEX_BITS) - 1;

fn encode(index: u32, generation: u8) -> u32 {
    ((generation as u32) << INDEX_BITS) | (index + 1)
}

fn decode(user_data: u32) -> Option<(u32, u8)> {
    let i = user_data & INDEX_MASK;
    (i != 0).then(|| (i - 1, (user_data >> INDEX_BITS) as u8))
}

pub(crate) fn lock<T>(m: &Mutex<T>) -> std::sync::MutexGuard<'_, T> {
    // A panic elsewhere must not turn every later step into a panic: take the data anyway.
    m.lock().unwrap_or_else(|e| e.into_inner())
}

/// A slot of a [`StoreImage`]: its generation and, while live, the record with its pair
/// (collider arena indices), sweep parity and whether the key map points at it.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct SlotImage {
    pub generation: u8,
    pub live: Option<LiveImage>,
}

/// A live record of a [`StoreImage`].
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct LiveImage {
    pub c1: u32,
    pub c2: u32,
    pub touched_odd: bool,
    pub record: ContactRecord,
}

/// The whole store, exactly (for snapshots): slots in order, key map, free slots.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct StoreImage {
    pub slots: Vec<SlotImage>,
    pub keys: Vec<(ContactKey, u32)>,
    pub next_generation: u8,
    /// Records created since the last sweep.
    pub created: u32,
}

/// The records of a [`ContactStore`] borrowed for a pass over many of them at once
/// (`recycle`'s step ahead of recycled manifolds), which may run on several threads: each
/// record is reached by one thread, and its slot's lock is held only to copy it in and out.
pub(crate) struct Records<'a> {
    slots: &'a [Slot],
}

impl Records<'_> {
    /// The live record `user_data` points at, if it belongs to the pair `(c1, c2)`; marks it
    /// alive at `step` (a sleeping manifold keeps its state while rapier keeps the manifold).
    pub fn touch(
        &self,
        user_data: u32,
        c1: ColliderHandle,
        c2: ColliderHandle,
        step: u32,
    ) -> Option<ContactRecord> {
        self.update(user_data, c1, c2, step, |rec| *rec)
    }

    /// Runs `f` on the live record `user_data` points at, if it belongs to the pair
    /// `(c1, c2)`, stores it back and marks it alive at `step` (a recycled manifold, which
    /// the hook does not see; see `recycle`).
    pub fn update<R>(
        &self,
        user_data: u32,
        c1: ColliderHandle,
        c2: ColliderHandle,
        step: u32,
        f: impl FnOnce(&mut ContactRecord) -> R,
    ) -> Option<R> {
        let (index, generation) = decode(user_data)?;
        let mut d = self.slots.get(index as usize)?.0.lock();
        if !fits(&d, index_of(c1), index_of(c2), Some(generation)) {
            return None;
        }
        let mut rec = unpack(&d.packed, d.slip_speed, d.meta);
        let out = f(&mut rec);
        (d.packed, d.slip_speed) = pack(&rec, d.packed.pair);
        d.meta = (with_state(d.meta, &rec) & !TOUCHED) | parity(step);
        Some(out)
    }
}

impl ContactStore {
    /// Runs `f` on the record of the manifold with `key`, creating it if needed; `f` learns
    /// whether the record is new and the encoded `user_data`. Updates `user_data` to point at
    /// the record.
    pub fn with_record<R>(
        &self,
        user_data: &mut u32,
        key: &ContactKey,
        step: u32,
        f: impl FnOnce(&mut ContactRecord, bool, u32) -> R,
    ) -> R {
        self.with_record_filed(user_data, key, step, |rec, new, ours, _| f(rec, new, ours))
    }

    /// [`Self::with_record`], where `f` also learns the `user_data` the record had when this
    /// step found it, under which the last step filed what it measured at the manifold: not
    /// `ours` when the record moved down to a free slot (see [`Self::move_down`]).
    pub fn with_record_filed<R>(
        &self,
        user_data: &mut u32,
        key: &ContactKey,
        step: u32,
        f: impl FnOnce(&mut ContactRecord, bool, u32, u32) -> R,
    ) -> R {
        {
            let slots = self.slots.read().unwrap_or_else(|e| e.into_inner());
            if let Some((index, mut d)) = self.find(&slots, user_data, key) {
                let filed = *user_data;
                if index > self.free_floor.load(Ordering::Relaxed)
                    && let Some((to, mut moved)) = self.move_down(&slots, index, &mut d, key)
                {
                    drop(d);
                    *user_data = encode(to, generation_of(moved.meta));
                    let run = |rec: &mut ContactRecord, new, ours| f(rec, new, ours, filed);
                    return self.run(to, &mut moved, false, step, *user_data, run);
                }
                let run = |rec: &mut ContactRecord, new, ours| f(rec, new, ours, filed);
                return self.run(index, &mut d, false, step, *user_data, run);
            }
        }
        // New contact: allocate under the write lock (rare: only when contacts appear), then
        // step it under the read lock like any other.
        let Some((index, new)) = self.create(user_data, key) else {
            // A collider beyond the 24 bits a record keeps (16.7 million colliders): the
            // contact is stepped from a fresh state every step (no memory of its own).
            *user_data = 0;
            return f(&mut ContactRecord::default(), true, 0, 0);
        };
        let filed = *user_data;
        let run = |rec: &mut ContactRecord, new, ours| f(rec, new, ours, filed);
        let slots = self.slots.read().unwrap_or_else(|e| e.into_inner());
        match slots.get(index as usize) {
            Some(slot) => self.run(index, &mut slot.0.lock(), new, step, *user_data, run),
            // Unreachable: slots only go away through `&mut self`.
            None => run(&mut ContactRecord::default(), true, *user_data),
        }
    }

    /// The wrapped hook's own `user_data` kept for the manifold whose `user_data` (ours) is
    /// `ours` and whose key is `key` (0 if none: also when `ours` is stale).
    pub fn inner_user_data(&self, ours: u32, key: &ContactKey) -> u32 {
        if !self.inner_used.load(Ordering::Relaxed) {
            return 0;
        }
        let Some((index, generation)) = decode(ours) else {
            return 0;
        };
        let slots = self.slots.read().unwrap_or_else(|e| e.into_inner());
        let mine = slots.get(index as usize).is_some_and(|s| {
            fits(
                &s.0.lock(),
                index_of(key.c1),
                index_of(key.c2),
                Some(generation),
            )
        });
        if !mine {
            return 0;
        }
        lock(&self.inner_data).get(&index).copied().unwrap_or(0)
    }

    /// Steps the record in the locked slot `d`: a copy, marked touched at `step`, goes to `f`
    /// and is stored back when `f` returns (if `f` panics, the guard releases the slot and the
    /// record keeps its last state).
    fn run<R>(
        &self,
        index: u32,
        d: &mut SlotData,
        new: bool,
        step: u32,
        ours: u32,
        f: impl FnOnce(&mut ContactRecord, bool, u32) -> R,
    ) -> R {
        d.meta = (d.meta & !TOUCHED) | parity(step);
        let mut rec = unpack(&d.packed, d.slip_speed, d.meta);
        if self.inner_used.load(Ordering::Relaxed) {
            rec.inner_user_data = lock(&self.inner_data).get(&index).copied().unwrap_or(0);
        }
        let before = rec.inner_user_data;
        let out = f(&mut rec, new, ours);
        (d.packed, d.slip_speed) = pack(&rec, d.packed.pair);
        d.meta = (with_state(d.meta, &rec) & !TOUCHED) | parity(step);
        if rec.inner_user_data != before {
            let mut map = lock(&self.inner_data);
            if rec.inner_user_data == 0 {
                map.remove(&index);
            } else {
                map.insert(index, rec.inner_user_data);
                self.inner_used.store(true, Ordering::Relaxed);
            }
        }
        out
    }

    /// Moves the live record in slot `index` (locked: `d`, the record of `key`) into the
    /// lowest free slot if that lies below, and returns that slot, locked, with its new
    /// generation; `index` becomes free. So records of contacts that outlived many others
    /// do not keep the slot array long: the sweep cuts the free slots they leave at the end
    /// (the platforms bench kept 378 slots for 201 records). The hook points the manifold at
    /// the new slot, and the key map too for a record it holds (a cluster patch, whose
    /// manifold rapier rebuilds every step: what `end_step` measured there was filed under
    /// the old `user_data`, which [`Self::with_record_filed`] tells).
    fn move_down<'s>(
        &self,
        slots: &'s [Slot],
        index: u32,
        d: &mut SlotData,
        key: &ContactKey,
    ) -> Option<(u32, parking_lot::MutexGuard<'s, SlotData>)> {
        // The key map's entry for a keyed record, held until the move is done.
        let mut by_key = (d.meta & KEYED != 0).then(|| lock(&self.by_key));
        if by_key.as_ref().is_some_and(|m| m.get(key) != Some(&index)) {
            return None;
        }
        let mut free = lock(&self.free);
        let to = free.peek().map(|r| r.0).filter(|&to| to < index);
        let target = to.and_then(|to| slots.get(to as usize));
        let (Some(to), Some(target)) = (to, target) else {
            self.free_floor.store(lowest(&free), Ordering::Relaxed);
            return None;
        };
        free.pop();
        let mut t = target.0.lock();
        let generation = generation_of(t.meta).wrapping_add(1);
        *t = SlotData {
            meta: (d.meta & !(0xFF << GENERATION_SHIFT)) | (generation as u16) << GENERATION_SHIFT,
            ..*d
        };
        d.meta &= !(LIVE | KEYED);
        free.push(Reverse(index));
        self.free_floor.store(lowest(&free), Ordering::Relaxed);
        drop(free);
        if let Some(by_key) = by_key.as_mut() {
            by_key.insert(*key, to);
        }
        drop(by_key);
        if self.inner_used.load(Ordering::Relaxed) {
            let mut inner = lock(&self.inner_data);
            if let Some(v) = inner.remove(&index) {
                inner.insert(to, v);
            }
        }
        Some((to, t))
    }

    /// The locked slot of the manifold with `key`, found through `user_data` or the key map
    /// (then `user_data` is pointed at it).
    fn find<'s>(
        &self,
        slots: &'s [Slot],
        user_data: &mut u32,
        key: &ContactKey,
    ) -> Option<(u32, parking_lot::MutexGuard<'s, SlotData>)> {
        let (c1, c2) = (index_of(key.c1), index_of(key.c2));
        if let Some((index, generation)) = decode(*user_data)
            && let Some(slot) = slots.get(index as usize)
        {
            let mut d = slot.0.lock();
            if fits(&d, c1, c2, Some(generation)) {
                // Found through its user_data: the manifold keeps it, the key map can let go.
                if d.meta & KEYED != 0 {
                    let mut by_key = lock(&self.by_key);
                    if by_key.get(key) == Some(&index) {
                        by_key.remove(key);
                        d.meta &= !KEYED;
                    }
                }
                return Some((index, d));
            }
        }
        let index = lock(&self.by_key).get(key).copied()?;
        let d = slots.get(index as usize)?.0.lock();
        if !fits(&d, c1, c2, None) {
            return None;
        }
        *user_data = encode(index, generation_of(d.meta));
        Some((index, d))
    }

    /// The slot for a new manifold with `key` (and whether it is new: another thread may have
    /// made it since the caller looked, which the key map, read again under the write lock,
    /// tells); points `user_data` at it.
    fn create(&self, user_data: &mut u32, key: &ContactKey) -> Option<(u32, bool)> {
        let (c1, c2) = (index_of(key.c1), index_of(key.c2));
        let pair = pair_bytes(c1, c2)?;
        let mut slots = self.slots.write().unwrap_or_else(|e| e.into_inner());
        let known = lock(&self.by_key).get(key).copied();
        if let Some(index) = known
            && let Some(slot) = slots.get_mut(index as usize)
            && fits(slot.data(), c1, c2, None)
        {
            *user_data = encode(index, generation_of(slot.data().meta));
            return Some((index, false));
        }
        let popped = {
            let mut free = lock(&self.free);
            let popped = free.pop();
            self.free_floor.store(lowest(&free), Ordering::Relaxed);
            popped
        };
        let index = match popped {
            Some(Reverse(i)) => i,
            None => {
                if slots.len() == slots.capacity() {
                    // Grow by 1/32, at least 16 slots: the slack stays small (memory per
                    // contact; with at least 64 the rolling bench's 400 contacts sat in 448
                    // slots, 4 B more a contact), the copies amortized.
                    let more = (slots.len() / 32).max(16);
                    slots.reserve_exact(more);
                }
                let generation = self.next_generation.fetch_add(1, Ordering::Relaxed);
                slots.push(Slot::dead(generation));
                (slots.len() - 1) as u32
            }
        };
        let d = slots[index as usize].data();
        let generation = generation_of(d.meta).wrapping_add(1);
        *d = SlotData {
            packed: Packed {
                pair,
                ..Packed::default()
            },
            slip_speed: 0,
            meta: LIVE | KEYED | pack_regime(u8::MAX) | (generation as u16) << GENERATION_SHIFT,
        };
        lock(&self.by_key).insert(*key, index);
        lock(&self.inner_data).remove(&index);
        self.created.fetch_add(1, Ordering::Relaxed);
        *user_data = encode(index, generation);
        Some((index, true))
    }

    /// Marks no record as holding the hook's next step (see `ContactRecord::ahead`): a mark
    /// holds for the one step after the `end_step` that set it.
    pub fn clear_ahead(&mut self) {
        let slots = self.slots.get_mut().unwrap_or_else(|e| e.into_inner());
        for slot in slots.iter_mut() {
            let meta = slot.meta();
            slot.set_meta(meta & !AHEAD);
        }
    }

    /// Whether the store created many records since its last sweep (at least 1/[`CHURN_SHARE`]
    /// of its slots): contacts come and go (rapier re-forms the patches of bodies moving over
    /// a composite shape every step), and the records of those that went are to be dropped
    /// now rather than at the next regular sweep, so that the records kept stay close to the
    /// live contacts.
    pub fn churned(&self) -> bool {
        let created = self.created.load(Ordering::Relaxed) as usize;
        let slots = self.slots.read().unwrap_or_else(|e| e.into_inner()).len();
        created >= CHURN_MIN.max(slots / CHURN_SHARE)
    }

    /// Drops every record not touched at `step`, cuts free slots off the end and gives back
    /// memory the store no longer needs.
    pub fn sweep(&mut self, step: u32) {
        self.sweep_untouched(step, |_, _, _| false);
    }

    /// Like [`Self::sweep`], but a record not touched at `step` survives (and is marked) when
    /// `held(c1, c2, user_data)` says rapier still holds its manifold: the pair's collider
    /// arena indices and the `user_data` that manifold carries if it is this record's. One
    /// pass over the slots; the narrow phase is asked only about untouched records (sleeping
    /// or vanished contacts).
    pub fn sweep_untouched(&mut self, step: u32, mut held: impl FnMut(u32, u32, u32) -> bool) {
        *self.created.get_mut() = 0;
        let slots = self.slots.get_mut().unwrap_or_else(|e| e.into_inner());
        let free = self.free.get_mut().unwrap_or_else(|e| e.into_inner());
        let mut dropped = false;
        for (i, slot) in slots.iter_mut().enumerate() {
            let meta = slot.meta();
            if meta & LIVE == 0 || meta & TOUCHED == parity(step) {
                continue;
            }
            let p = slot.data().packed;
            if held(p.c1(), p.c2(), encode(i as u32, generation_of(meta))) {
                slot.set_meta((meta & !TOUCHED) | parity(step));
            } else {
                slot.set_meta(meta & !(LIVE | KEYED));
                free.push(Reverse(i as u32));
                dropped = true;
            }
        }
        // A record that moved down left its slot free, maybe at the end.
        let dead_end = slots.last().is_some_and(|s| s.0.lock().meta & LIVE == 0);
        if dropped || dead_end {
            self.release(|_| false);
        } else {
            // Key-map entries also leave when their manifold is found through its user_data.
            self.shrink();
        }
    }

    /// After records died: drops their key-map and inner entries, cuts dead slots off the
    /// end, and shrinks what grew far beyond the live contacts. `also_dead(slot)` names slots
    /// to kill now.
    fn release(&mut self, mut also_dead: impl FnMut(&mut Slot) -> bool) {
        let slots = self.slots.get_mut().unwrap_or_else(|e| e.into_inner());
        let free = self.free.get_mut().unwrap_or_else(|e| e.into_inner());
        for (i, slot) in slots.iter_mut().enumerate() {
            if slot.meta() & LIVE != 0 && also_dead(slot) {
                let meta = slot.meta();
                slot.set_meta(meta & !(LIVE | KEYED));
                free.push(Reverse(i as u32));
            }
        }
        let mut n = slots.len();
        while n > 0 && slots[n - 1].meta() & LIVE == 0 {
            n -= 1;
        }
        if n < slots.len() {
            slots.truncate(n);
            free.retain(|&Reverse(i)| (i as usize) < n);
        }
        let live = |i: u32| {
            slots
                .get(i as usize)
                .is_some_and(|s| s.0.lock().meta & LIVE != 0)
        };
        let by_key = self.by_key.get_mut().unwrap_or_else(|e| e.into_inner());
        by_key.retain(|_, i| live(*i));
        let inner = self.inner_data.get_mut().unwrap_or_else(|e| e.into_inner());
        inner.retain(|i, _| live(*i));
        self.shrink();
        let free = self.free.get_mut().unwrap_or_else(|e| e.into_inner());
        *self.free_floor.get_mut() = lowest(free);
    }

    /// Gives memory back once it is well beyond what is live (with hysteresis: no churn of
    /// reallocations at steady state).
    fn shrink(&mut self) {
        let slots = self.slots.get_mut().unwrap_or_else(|e| e.into_inner());
        let free = self.free.get_mut().unwrap_or_else(|e| e.into_inner());
        let by_key = self.by_key.get_mut().unwrap_or_else(|e| e.into_inner());
        let inner = self.inner_data.get_mut().unwrap_or_else(|e| e.into_inner());
        let n = slots.len();
        if slots.capacity() > n + n / 16 + 16 {
            slots.shrink_to(n + n / 32);
        }
        if free.capacity() > 2 * free.len() + 64 {
            free.shrink_to(free.len());
        }
        if by_key.capacity() > 4 * by_key.len() + 64 {
            by_key.shrink_to(by_key.len());
        }
        if inner.capacity() > 4 * inner.len() + 64 {
            inner.shrink_to(inner.len());
        }
    }

    /// Drops every record of a contact involving `collider`.
    pub fn remove_collider(&mut self, collider: ColliderHandle) {
        let c = index_of(collider);
        self.release(|slot| {
            let p = slot.data().packed;
            p.c1() == c || p.c2() == c
        });
    }

    /// The records, for a pass that steps many of them at once (see [`Records`]).
    pub fn records(&mut self) -> Records<'_> {
        Records {
            slots: self.slots.get_mut().unwrap_or_else(|e| e.into_inner()),
        }
    }

    /// Number of live records.
    pub fn len(&self) -> usize {
        self.slots
            .read()
            .unwrap_or_else(|e| e.into_inner())
            .iter()
            .filter(|s| s.0.lock().meta & LIVE != 0)
            .count()
    }

    /// Slots allocated (live or free).
    pub fn capacity(&self) -> usize {
        self.slots.read().unwrap_or_else(|e| e.into_inner()).len()
    }

    /// Heap bytes the store holds (slots, free list, key map, inner `user_data`), counting
    /// allocated capacity.
    pub fn heap_bytes(&self) -> usize {
        let slots = self.slots.read().unwrap_or_else(|e| e.into_inner());
        let free = self.free.lock().unwrap_or_else(|e| e.into_inner());
        let by_key = self.by_key.lock().unwrap_or_else(|e| e.into_inner());
        let inner = self.inner_data.lock().unwrap_or_else(|e| e.into_inner());
        crate::heap::vec_bytes(&slots)
            + free.capacity() * std::mem::size_of::<Reverse<u32>>()
            + crate::heap::map_bytes(&by_key)
            + crate::heap::map_bytes(&inner)
    }

    /// The store, exactly (for snapshots). Takes each slot's lock while reading it, so it is
    /// safe (if not meaningful) during a step.
    pub fn image(&self) -> StoreImage {
        let inner = lock(&self.inner_data).clone();
        let slots = self.slots.read().unwrap_or_else(|e| e.into_inner());
        let slots = slots
            .iter()
            .enumerate()
            .map(|(i, s)| {
                let SlotData {
                    packed: p,
                    slip_speed: slip,
                    meta,
                } = *s.0.lock();
                let live = (meta & LIVE != 0).then(|| LiveImage {
                    c1: p.c1(),
                    c2: p.c2(),
                    touched_odd: meta & TOUCHED != 0,
                    record: ContactRecord {
                        inner_user_data: inner.get(&(i as u32)).copied().unwrap_or(0),
                        ..unpack(&p, slip, meta)
                    },
                });
                SlotImage {
                    generation: generation_of(meta),
                    live,
                }
            })
            .collect();
        let mut keys: Vec<(ContactKey, u32)> =
            lock(&self.by_key).iter().map(|(k, &i)| (*k, i)).collect();
        // The map's order never matters; sorted, equal states give equal images.
        keys.sort_by_key(|(k, i)| {
            let raw = |h: ColliderHandle| h.0.into_raw_parts();
            (raw(k.c1), raw(k.c2), k.part, *i)
        });
        StoreImage {
            slots,
            keys,
            next_generation: self.next_generation.load(Ordering::Relaxed),
            created: self.created.load(Ordering::Relaxed),
        }
    }

    /// The store an image describes, or what is inconsistent in it.
    pub fn from_image(image: &StoreImage) -> Result<ContactStore, String> {
        let n = image.slots.len();
        // Encoded user_data holds slot index + 1 in INDEX_BITS bits.
        if n >= (1usize << INDEX_BITS) {
            return Err(format!("{n} slots"));
        }
        let mut slots = Vec::with_capacity(n);
        let mut free = BinaryHeap::new();
        let mut inner = HashMap::default();
        for (i, s) in image.slots.iter().enumerate() {
            let mut slot = Slot::dead(s.generation);
            match &s.live {
                None => free.push(Reverse(i as u32)),
                Some(l) => {
                    let pair = pair_bytes(l.c1, l.c2)
                        .ok_or_else(|| format!("slot {i}: collider index beyond 24 bits"))?;
                    let (p, slip) = pack(&l.record, pair);
                    slot.data().packed = p;
                    slot.data().slip_speed = slip;
                    let mut meta = with_state(slot.meta(), &l.record) | LIVE;
                    if l.touched_odd {
                        meta |= TOUCHED;
                    }
                    slot.set_meta(meta);
                    if l.record.inner_user_data != 0 {
                        inner.insert(i as u32, l.record.inner_user_data);
                    }
                }
            }
            slots.push(slot);
        }
        let mut by_key = HashMap::with_capacity_and_hasher(image.keys.len(), Default::default());
        for (key, index) in &image.keys {
            let slot = slots
                .get_mut(*index as usize)
                .filter(|s| s.0.lock().meta & LIVE != 0)
                .ok_or_else(|| format!("key map: slot {index} is not a live record"))?;
            let p = slot.data().packed;
            if (p.c1(), p.c2()) != (index_of(key.c1), index_of(key.c2)) {
                return Err(format!("key map: slot {index} is not a record of its pair"));
            }
            if slot.meta() & KEYED != 0 {
                return Err(format!("key map: slot {index} listed twice"));
            }
            let meta = slot.meta();
            slot.set_meta(meta | KEYED);
            if by_key.insert(*key, *index).is_some() {
                return Err("key map: a key is listed twice".into());
            }
        }
        let floor = lowest(&free);
        Ok(ContactStore {
            slots: RwLock::new(slots),
            by_key: Mutex::new(by_key),
            free: Mutex::new(free),
            inner_used: AtomicBool::new(!inner.is_empty()),
            inner_data: Mutex::new(inner),
            next_generation: std::sync::atomic::AtomicU8::new(image.next_generation),
            created: AtomicU32::new(image.created),
            free_floor: AtomicU32::new(floor),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rapier::prelude::ColliderHandle;

    fn key(a: u32, b: u32) -> ContactKey {
        ContactKey {
            c1: ColliderHandle::from_raw_parts(a, 0),
            c2: ColliderHandle::from_raw_parts(b, 0),
            part: ManifoldPart::Whole,
        }
    }

    #[test]
    fn a_slot_is_35_bytes() {
        // rapier 0.35 builds keep one f32 more (see `ContactRecord::warm_start_impulse`).
        let extra = if cfg!(rapier_035) { 4 } else { 0 };
        assert_eq!(std::mem::size_of::<SlotData>(), 34 + extra);
        assert_eq!(std::mem::size_of::<Slot>(), 35 + extra);
    }

    #[test]
    fn a_collider_beyond_24_bits_gets_a_fresh_record_each_step() {
        let store = ContactStore::default();
        let far = key(3, PAIR_LIMIT);
        for step in 1..4 {
            let mut ud = 0;
            let (new, slide) = store.with_record(&mut ud, &far, step, |r, new, _| {
                let before = r.state.slide;
                r.state.slide = 1.0;
                (new, before)
            });
            assert_eq!((new, slide, ud), (true, 0.0, 0));
        }
        assert_eq!(store.len(), 0);
        // The largest index that fits keeps its record.
        let mut ud = 0;
        store.with_record(&mut ud, &key(PAIR_LIMIT - 1, 0), 1, |r, _, _| {
            r.state.slide = 1.0
        });
        let kept = store.with_record(&mut ud, &key(PAIR_LIMIT - 1, 0), 2, |r, new, _| {
            (new, r.state.slide)
        });
        assert_eq!(kept, (false, 1.0));
    }

    #[test]
    fn packing_keeps_the_record() {
        let rec = ContactRecord {
            state: ContactState {
                force: [1.5, -2.0, 3.25],
                slide: 0.75,
                limit: 0.4,
                slip_speed: 0.5,
                mean_normal_force: 9.81,
                regime: 2,
                forming: 0,
            },
            ..ContactRecord::default()
        };
        for regime in [0, 1, 2, u8::MAX, REGIME_RESET] {
            for (forming, ahead) in [(0, false), (1, true), (2, false), (2, true)] {
                let rec = ContactRecord {
                    state: ContactState {
                        regime,
                        forming,
                        ..rec.state
                    },
                    ahead,
                    ..rec
                };
                let (p, slip) = pack(&rec, pair_bytes(3, PAIR_LIMIT - 1).unwrap());
                let meta = with_state(LIVE, &rec);
                assert_eq!(unpack(&p, slip, meta), rec);
            }
        }
        // The slip speed keeps 8 significant bits.
        let x = 0.123_456_f32;
        assert!((from_bf16(to_bf16(x)) - x).abs() <= x / 128.0);
    }

    /// Records that outlive the contacts below them move down as their manifolds find them
    /// (keeping their state and their wrapped hook's user_data; a record in the key map
    /// keeps its key, which then finds it at its new slot, and tells the user_data it was
    /// found with), stale user_data of a moved record reaches nothing, and the sweep then
    /// cuts the slot array back to the live records.
    #[test]
    fn records_move_down_into_free_slots() {
        let mut store = ContactStore::default();
        let mut uds = vec![0u32; 1000];
        for (i, ud) in uds.iter_mut().enumerate() {
            store.with_record(ud, &key(i as u32, 5000), 1, |r, _, _| {
                r.state.slide = i as f32;
                r.inner_user_data = if i % 7 == 0 { i as u32 + 1 } else { 0 };
            });
        }
        let full = store.capacity();
        assert_eq!(full, 1000);
        // Step 2: only the last 100 are touched (found through their user_data, but for
        // one whose manifold resets it every step, as rapier does a cluster's), the others
        // vanish.
        for (i, ud) in uds.iter_mut().enumerate().skip(900) {
            if i == 950 {
                *ud = 0;
            }
            store.with_record(ud, &key(i as u32, 5000), 2, |_, _, _| ());
        }
        store.sweep(2);
        assert_eq!(store.len(), 100);
        // Step 3: each moves down as its manifold finds it, the cluster-like record (user_data
        // reset, found by key) too.
        let stale: Vec<u32> = uds.clone();
        for (i, ud) in uds.iter_mut().enumerate().skip(900) {
            if i == 950 {
                *ud = 0;
            }
            let found = store.with_record_filed(ud, &key(i as u32, 5000), 3, |r, new, _, f| {
                assert!(!new, "record {i} lost");
                (r.state.slide, r.inner_user_data, f)
            });
            assert_eq!(
                found,
                (
                    i as f32,
                    if i % 7 == 0 { i as u32 + 1 } else { 0 },
                    stale[i]
                )
            );
        }
        let mut ud = 0;
        let again = store.with_record_filed(&mut ud, &key(950, 5000), 3, |_, new, ours, f| {
            (new, ours, f)
        });
        assert_eq!(
            again,
            (false, uds[950], uds[950]),
            "the key finds the moved record"
        );
        for (i, (&now, &before)) in uds.iter().zip(&stale).enumerate().skip(900) {
            assert!(
                now & INDEX_MASK <= 100,
                "record {i} still at {}",
                now & INDEX_MASK
            );
            // The old user_data is stale: it reaches no record.
            let k = key(i as u32, 5000);
            assert!(
                store
                    .records()
                    .update(before, k.c1, k.c2, 3, |_| ())
                    .is_none(),
                "record {i}"
            );
            assert!(
                store.records().update(now, k.c1, k.c2, 3, |_| ()).is_some(),
                "record {i}"
            );
        }
        store.sweep(3);
        assert_eq!(store.len(), 100);
        // The slots above the moved records were cut off.
        assert_eq!(store.capacity(), 100);
        let mut image = store.image();
        let back = ContactStore::from_image(&image).expect("image");
        image.created = 0;
        let mut again = back.image();
        again.created = 0;
        assert_eq!(image, again);
    }

    #[test]
    fn persists_sweeps_and_never_reuses_stale_user_data() {
        let mut store = ContactStore::default();
        let (mut ud_a, mut ud_b) = (0u32, 0u32);
        assert!(store.with_record(&mut ud_a, &key(1, 2), 1, |_, new, _| new));
        assert!(store.with_record(&mut ud_b, &key(3, 4), 1, |_, new, _| new));
        // Keep B below a third record so that sweeping B leaves a hole, not a cut tail.
        let mut ud_d = 0;
        store.with_record(&mut ud_d, &key(7, 8), 1, |_, _, _| ());
        store.with_record(&mut ud_a, &key(1, 2), 1, |r, new, _| {
            assert!(!new);
            r.inner_user_data = 7;
        });
        // Step 2: A and D are touched, B is swept.
        store.with_record(&mut ud_a, &key(1, 2), 2, |r, _, _| {
            assert_eq!(r.inner_user_data, 7)
        });
        store.with_record(&mut ud_d, &key(7, 8), 2, |_, _, _| ());
        store.sweep(2);
        assert_eq!(store.len(), 2);
        // A new contact C takes B's slot; B's stale user_data must not reach it.
        let mut ud_c = 0;
        store.with_record(&mut ud_c, &key(5, 6), 3, |r, _, _| r.inner_user_data = 3);
        assert_eq!(ud_c & INDEX_MASK, ud_b & INDEX_MASK, "slot reused");
        assert_ne!(ud_c, ud_b, "generation bumped");
        let fresh = store.with_record(&mut ud_b, &key(3, 4), 3, |r, new, _| {
            (new, r.inner_user_data)
        });
        assert_eq!(fresh, (true, 0));
        // Cluster manifolds: user_data reset to 0 every step still finds the record (A left
        // the key map when found through its user_data, so its key is gone: a new record).
        let mut ud = 0;
        store.with_record(&mut ud, &key(5, 6), 3, |r, new, _| {
            assert!(!new);
            assert_eq!(r.inner_user_data, 3);
        });
        store.with_record(&mut ud_a, &key(1, 2), 3, |_, _, _| ());
        store.with_record(&mut ud_d, &key(7, 8), 3, |_, _, _| ());
        store.sweep(3);
        assert_eq!(store.len(), 4);
        store.sweep(4);
        assert_eq!(store.len(), 0);
        // Everything was cut off the end: nothing left allocated for slots.
        assert_eq!(store.capacity(), 0);
    }

    #[test]
    fn shrinks_back_after_churn() {
        let mut store = ContactStore::default();
        let mut uds = vec![0u32; 10_000];
        for (i, ud) in uds.iter_mut().enumerate() {
            store.with_record(ud, &key(i as u32, 1_000_000), 1, |_, _, _| ());
        }
        let full = store.heap_bytes();
        assert!(full >= 10_000 * std::mem::size_of::<Slot>(), "{full}");
        // Step 2: only the first 100 survive.
        for (i, ud) in uds.iter_mut().enumerate().take(100) {
            store.with_record(ud, &key(i as u32, 1_000_000), 2, |_, _, _| ());
        }
        store.sweep(2);
        assert_eq!(store.len(), 100);
        let after = store.heap_bytes();
        assert!(
            after <= (100 + 64) * std::mem::size_of::<Slot>() + 1024,
            "{after} bytes for 100 contacts"
        );
    }

    #[test]
    fn threads_creating_the_same_records_make_one_each() {
        // Eight threads meet the same 2000 new manifolds (user_data 0: found by key only) at
        // once; each manifold must end with one record, the same for every thread.
        let store = ContactStore::default();
        let keys: Vec<ContactKey> = (0..2000).map(|i| key(i, 5000)).collect();
        let seen: Vec<Vec<u32>> = std::thread::scope(|s| {
            let handles: Vec<_> = (0..8)
                .map(|t| {
                    let (store, keys) = (&store, &keys);
                    s.spawn(move || {
                        let mut out = vec![0; keys.len()];
                        for k in 0..keys.len() {
                            // Threads walk the keys in different orders.
                            let i = (k + t * 251) % keys.len();
                            let mut ud = 0;
                            store.with_record(&mut ud, &keys[i], 1, |r, _, _| r.state.slide += 1.0);
                            out[i] = ud;
                        }
                        out
                    })
                })
                .collect();
            handles.into_iter().map(|h| h.join().unwrap()).collect()
        });
        assert_eq!(store.len(), keys.len(), "records");
        for ud in &seen[1..] {
            assert_eq!(ud, &seen[0], "threads got different records");
        }
        // Two threads on one record (rapier never gives one manifold to two threads; the test
        // does, on purpose) take turns: every update lands.
        let image = store.image();
        for l in image.slots.iter().filter_map(|s| s.live.as_ref()) {
            assert_eq!(l.record.state.slide, 8.0);
        }
    }

    #[test]
    fn images_round_trip() {
        let mut store = ContactStore::default();
        let mut uds = [0u32; 5];
        for (i, ud) in uds.iter_mut().enumerate() {
            store.with_record(ud, &key(i as u32, 9), 1, |r, _, _| {
                r.state.slide = i as f32;
                r.inner_user_data = i as u32;
            });
        }
        for (i, ud) in uds.iter_mut().enumerate().skip(1).step_by(2) {
            store.with_record(ud, &key(i as u32, 9), 2, |_, _, _| ());
        }
        store.sweep(2);
        let image = store.image();
        let back = ContactStore::from_image(&image).unwrap();
        assert_eq!(back.image(), image);
        assert_eq!(image.slots.iter().filter(|s| s.live.is_some()).count(), 2);
        assert_eq!(back.len(), 2);
    }
}
