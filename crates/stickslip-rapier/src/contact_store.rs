//! Per-contact friction state that lives as long as its contact manifold.
//!
//! Lookup is cheap: a manifold's `user_data` holds its slot index (+1) and an 8-bit
//! generation, so the hook reaches its record with one uncontended read lock and one
//! uncontended per-slot mutex, never a global map under one lock per contact. Only manifolds
//! whose `user_data` is 0 — new ones, and rapier's merged "cluster" manifolds whose
//! `user_data` is reset every step — go through a map keyed by the collider pair and the
//! first point's feature ids (which persist). Rapier does not report vanished manifolds, so
//! [`ContactStore::sweep`] drops every record not touched during the step: memory tracks the
//! active contacts (manifolds of sleeping pairs, which rapier keeps, are touched by the
//! modifier's end-of-step read-back and keep their state), and a recycled slot gets a new generation so stale `user_data` never
//! reaches another contact's state.

use rapier3d::prelude::{ColliderHandle, Vector};
use std::collections::HashMap;
use std::sync::{Mutex, RwLock};

/// What identifies a manifold across steps.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub(crate) struct ContactKey {
    pub c1: ColliderHandle,
    pub c2: ColliderHandle,
    /// Packed feature ids of the manifold's first point (and sub-shapes).
    pub features: u64,
}

/// The state kept per active contact manifold: 76 bytes.
#[derive(Debug, Clone, Copy)]
pub(crate) struct ContactRecord {
    pub c1: ColliderHandle,
    pub c2: ColliderHandle,
    /// Friction-law state s⃗ (tangential spring force, N) in world coordinates.
    pub force: Vector,
    /// Friction-law break-away progress σ (elasto-plastic law; 0 otherwise).
    pub slide: f32,
    /// The friction coefficient limit given to the solver last step (0: none yet).
    pub limit: f32,
    /// Slip speed seen last step (m/s; 0 while holding).
    pub slip_speed: f32,
    /// Stick anchor on collider 1, in collider 1's frame.
    pub anchor1: Vector,
    /// Stick anchor on collider 2, in collider 2's frame.
    pub anchor2: Vector,
    /// The wrapped user hook's own `user_data` for this manifold (we own the field).
    pub inner_user_data: u32,
    /// Mean normal force (N), low-pass filtered: sets the law's tangential stiffness.
    pub mean_normal_force: f32,
    /// Low 16 bits of the step counter at the last touch (for the sweep; every live record
    /// is touched or swept each step, so wrapping is harmless).
    pub touched: u16,
    /// Regime code (see `Regime`), 255 until the law has run.
    pub regime: u8,
    /// Whether the anchors are valid.
    pub anchored: bool,
}

impl ContactRecord {
    pub(crate) fn new(key: &ContactKey) -> Self {
        ContactRecord {
            c1: key.c1,
            c2: key.c2,
            force: Vector::ZERO,
            slide: 0.0,
            limit: 0.0,
            slip_speed: 0.0,
            anchor1: Vector::ZERO,
            anchor2: Vector::ZERO,
            inner_user_data: 0,
            mean_normal_force: 0.0,
            touched: 0,
            regime: u8::MAX,
            anchored: false,
        }
    }
}

#[derive(Debug)]
pub(crate) struct Slot {
    pub generation: u8,
    pub live: bool,
    pub record: ContactRecord,
}

/// Slab of contact records.
#[derive(Debug, Default)]
pub(crate) struct ContactStore {
    pub(crate) slots: RwLock<Vec<Mutex<Slot>>>,
    pub(crate) by_key: Mutex<HashMap<ContactKey, u32>>,
    pub(crate) free: Mutex<Vec<u32>>,
}

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

impl ContactStore {
    /// Runs `f` on the record of the manifold with `key`, creating it if needed; `f` learns
    /// whether the record is new and the encoded `user_data`. Updates `user_data` to point at the record.
    pub fn with_record<R>(
        &self,
        user_data: &mut u32,
        key: &ContactKey,
        step: u32,
        f: impl FnOnce(&mut ContactRecord, bool, u32) -> R,
    ) -> R {
        let slots = self.slots.read().unwrap_or_else(|e| e.into_inner());
        let try_slot =
            |index: u32, generation: Option<u8>| -> Option<std::sync::MutexGuard<'_, Slot>> {
                let slot = lock(slots.get(index as usize)?);
                let ok = slot.live
                    && generation.is_none_or(|g| g == slot.generation)
                    && slot.record.c1 == key.c1
                    && slot.record.c2 == key.c2;
                ok.then_some(slot)
            };
        if let Some((index, generation)) = decode(*user_data)
            && let Some(mut slot) = try_slot(index, Some(generation))
        {
            slot.record.touched = step as u16;
            return f(&mut slot.record, false, *user_data);
        }
        let known = lock(&self.by_key).get(key).copied();
        if let Some(index) = known
            && let Some(mut slot) = try_slot(index, None)
        {
            *user_data = encode(index, slot.generation);
            slot.record.touched = step as u16;
            return f(&mut slot.record, false, *user_data);
        }
        drop(slots);
        // New contact: allocate under the write lock (rare: only when contacts appear).
        let mut slots = self.slots.write().unwrap_or_else(|e| e.into_inner());
        let index = lock(&self.free).pop().unwrap_or_else(|| {
            slots.push(Mutex::new(Slot {
                generation: 0,
                live: false,
                record: ContactRecord::new(key),
            }));
            (slots.len() - 1) as u32
        });
        let mut slot = lock(&slots[index as usize]);
        slot.generation = slot.generation.wrapping_add(1);
        slot.live = true;
        slot.record = ContactRecord::new(key);
        slot.record.touched = step as u16;
        lock(&self.by_key).insert(*key, index);
        *user_data = encode(index, slot.generation);
        f(&mut slot.record, true, *user_data)
    }

    /// Drops every record not touched at `step`.
    pub fn sweep(&mut self, step: u32) {
        let slots = self.slots.get_mut().unwrap_or_else(|e| e.into_inner());
        let free = self.free.get_mut().unwrap_or_else(|e| e.into_inner());
        let mut dropped = false;
        for (i, slot) in slots.iter_mut().enumerate() {
            let slot = slot.get_mut().unwrap_or_else(|e| e.into_inner());
            if slot.live && slot.record.touched != step as u16 {
                slot.live = false;
                free.push(i as u32);
                dropped = true;
            }
        }
        if dropped {
            let by_key = self.by_key.get_mut().unwrap_or_else(|e| e.into_inner());
            by_key.retain(|_, &mut i| slots[i as usize].get_mut().map(|s| s.live).unwrap_or(false));
        }
    }

    /// Drops every record of a contact involving `collider`.
    pub fn remove_collider(&mut self, collider: ColliderHandle) {
        let slots = self.slots.get_mut().unwrap_or_else(|e| e.into_inner());
        let free = self.free.get_mut().unwrap_or_else(|e| e.into_inner());
        for (i, slot) in slots.iter_mut().enumerate() {
            let slot = slot.get_mut().unwrap_or_else(|e| e.into_inner());
            if slot.live && (slot.record.c1 == collider || slot.record.c2 == collider) {
                slot.live = false;
                free.push(i as u32);
            }
        }
        let by_key = self.by_key.get_mut().unwrap_or_else(|e| e.into_inner());
        by_key.retain(|k, _| k.c1 != collider && k.c2 != collider);
    }

    /// The live records.
    pub fn live(&mut self) -> impl Iterator<Item = &ContactRecord> {
        self.slots
            .get_mut()
            .unwrap_or_else(|e| e.into_inner())
            .iter_mut()
            .filter_map(|s| {
                let s = s.get_mut().unwrap_or_else(|e| e.into_inner());
                s.live.then_some(&s.record)
            })
    }

    /// The live record `user_data` points at, if it belongs to the pair `(c1, c2)`; marks it
    /// alive at `step` (a sleeping manifold keeps its state while rapier keeps the manifold).
    pub fn touch(
        &mut self,
        user_data: u32,
        c1: ColliderHandle,
        c2: ColliderHandle,
        step: u32,
    ) -> Option<&ContactRecord> {
        let (index, generation) = decode(user_data)?;
        let slots = self.slots.get_mut().unwrap_or_else(|e| e.into_inner());
        let slot = slots
            .get_mut(index as usize)?
            .get_mut()
            .unwrap_or_else(|e| e.into_inner());
        let ok = slot.live
            && slot.generation == generation
            && slot.record.c1 == c1
            && slot.record.c2 == c2;
        if ok {
            slot.record.touched = step as u16;
        }
        ok.then_some(&slot.record)
    }

    /// Number of live records.
    pub fn len(&mut self) -> usize {
        self.live().count()
    }

    /// Slots allocated (live or free).
    pub fn capacity(&mut self) -> usize {
        self.slots
            .get_mut()
            .unwrap_or_else(|e| e.into_inner())
            .len()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rapier3d::prelude::ColliderHandle;

    fn key(a: u32, b: u32) -> ContactKey {
        ContactKey {
            c1: ColliderHandle::from_raw_parts(a, 0),
            c2: ColliderHandle::from_raw_parts(b, 0),
            features: 0,
        }
    }

    #[test]
    fn record_is_76_bytes() {
        assert!(std::mem::size_of::<ContactRecord>() <= 76);
    }

    #[test]
    fn persists_sweeps_and_never_reuses_stale_user_data() {
        let mut store = ContactStore::default();
        let (mut ud_a, mut ud_b) = (0u32, 0u32);
        assert!(store.with_record(&mut ud_a, &key(1, 2), 1, |_, new, _| new));
        assert!(store.with_record(&mut ud_b, &key(3, 4), 1, |_, new, _| new));
        store.with_record(&mut ud_a, &key(1, 2), 1, |r, new, _| {
            assert!(!new);
            r.inner_user_data = 7;
        });
        // Step 2: only A is touched, B is swept.
        store.with_record(&mut ud_a, &key(1, 2), 2, |r, _, _| {
            assert_eq!(r.inner_user_data, 7)
        });
        store.sweep(2);
        assert_eq!(store.len(), 1);
        // A new contact C takes B's slot; B's stale user_data must not reach it.
        let mut ud_c = 0;
        store.with_record(&mut ud_c, &key(5, 6), 3, |r, _, _| r.inner_user_data = 3);
        assert_eq!(ud_c & INDEX_MASK, ud_b & INDEX_MASK, "slot reused");
        assert_ne!(ud_c, ud_b, "generation bumped");
        let fresh = store.with_record(&mut ud_b, &key(3, 4), 3, |r, new, _| {
            (new, r.inner_user_data)
        });
        assert_eq!(fresh, (true, 0));
        // Cluster manifolds: user_data reset to 0 every step still finds the record.
        let mut ud = 0;
        store.with_record(&mut ud, &key(1, 2), 3, |r, new, _| {
            assert!(!new);
            assert_eq!(r.inner_user_data, 7);
        });
        store.sweep(3);
        assert_eq!(store.len(), 3);
        store.sweep(4);
        assert_eq!(store.len(), 0);
        assert_eq!(store.capacity(), 3);
    }
}
