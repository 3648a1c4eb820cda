//! What `end_step` measured at the contact patches of composite shapes, by the manifold's
//! `user_data` (see `StickSlip::patches_measured` for why they are measured after the solve).
//!
//! A vector of 32-byte entries (28 in 2D) sorted by `user_data` once a step, not a hash map:
//! it is rebuilt every step and read by the next step's hooks, and a map's buckets (41 bytes,
//! at most 7/8 full) cost more than twice as much per patch — the bulk of stickslip's heap in
//! a heap of compound bodies.

use crate::measure::Measured;
use rapier::prelude::Vector;

/// The measured patches; see the module docs.
#[derive(Debug, Clone, Default)]
pub(crate) struct PatchMeasures {
    /// Sorted by `user_data`, one entry a patch, up to `sealed`; recorded since, after it.
    entries: Vec<PatchEntry>,
    /// Length of the sorted part.
    sealed: usize,
}

// Packed to 4-byte alignment: 32 bytes in 3D, not 40.
#[derive(Debug, Clone, Copy)]
#[repr(C, packed(4))]
struct PatchEntry {
    user_data: u32,
    normal_force: f64,
    warm_start_impulse: f64,
    mu: Vector,
}

impl PatchEntry {
    fn measured(&self) -> Measured {
        Measured {
            normal_force: self.normal_force,
            mu: self.mu,
            warm_start_impulse: self.warm_start_impulse,
        }
    }
}

impl PatchMeasures {
    /// Forgets every patch (keeps the memory for the next step's).
    pub fn clear(&mut self) {
        self.entries.clear();
        self.sealed = 0;
    }

    /// Records `measured` for the patch `user_data`: replaces what the last [`Self::seal`]
    /// kept for it (settling measures a hooked patch again, rapier 0.35's warm start
    /// included), otherwise adds it.
    pub fn insert(&mut self, user_data: u32, measured: Measured) {
        let entry = PatchEntry {
            user_data,
            normal_force: measured.normal_force,
            warm_start_impulse: measured.warm_start_impulse,
            mu: measured.mu,
        };
        match self.find_sealed(user_data) {
            Some(at) => self.entries[at] = entry,
            None => crate::collider_map::push_slack(&mut self.entries, entry),
        }
    }

    /// Sorts what was recorded since the last seal in, for [`Self::get`] (one entry a patch:
    /// of two records of a patch between seals, the one sorted last), and gives back memory
    /// a much larger step left. Never allocates (an unstable sort, in place).
    pub fn seal(&mut self) {
        if self.sealed < self.entries.len() {
            let tail = &mut self.entries[self.sealed..];
            tail.sort_unstable_by_key(|e| e.user_data);
            let mut tail_len = 0;
            for i in 0..tail.len() {
                if tail_len > 0 && tail[tail_len - 1].user_data == tail[i].user_data {
                    tail[tail_len - 1] = tail[i];
                } else {
                    tail[tail_len] = tail[i];
                    tail_len += 1;
                }
            }
            self.entries.truncate(self.sealed + tail_len);
            // The two sorted parts hold different patches: one order sorts them.
            if self.sealed > 0 {
                self.entries.sort_unstable_by_key(|e| e.user_data);
            }
            self.sealed = self.entries.len();
        }
        if self.entries.capacity() > 4 * self.entries.len() + 64 {
            self.entries.shrink_to_fit();
        }
    }

    /// Where the sorted part holds `user_data`.
    fn find_sealed(&self, user_data: u32) -> Option<usize> {
        self.entries[..self.sealed]
            .binary_search_by_key(&user_data, |e| e.user_data)
            .ok()
    }

    /// What was measured for the patch `user_data`, if it was: a binary search (and a scan
    /// of what was recorded since the last seal).
    pub fn get(&self, user_data: u32) -> Option<Measured> {
        let at = match self.find_sealed(user_data) {
            Some(at) => at,
            None => {
                let tail = self.entries[self.sealed..]
                    .iter()
                    .rposition(|e| e.user_data == user_data)?;
                self.sealed + tail
            }
        };
        Some(self.entries[at].measured())
    }

    /// The patches: by increasing `user_data` once sealed.
    pub fn iter(&self) -> impl Iterator<Item = (u32, Measured)> + '_ {
        self.entries.iter().map(|e| (e.user_data, e.measured()))
    }

    /// Heap bytes held (capacity included).
    pub fn heap_bytes(&self) -> usize {
        self.entries.capacity() * std::mem::size_of::<PatchEntry>()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn measured(n: f64) -> Measured {
        Measured {
            normal_force: n,
            mu: Vector::splat(n as f32 * 0.1),
            warm_start_impulse: -n,
        }
    }

    /// Against a map of the same records, over steps as `end_step` records them (measured
    /// patches, sealed, then settling's records, sealed): a record after a seal replaces the
    /// sealed one, before and after the next seal; the sealed patches come out in increasing
    /// order; of two records of a patch between seals, one of them is kept.
    #[test]
    fn patches_read_as_a_map_of_their_last_records() {
        let mut patches = PatchMeasures::default();
        let mut model = std::collections::BTreeMap::new();
        let mut seed = 0x9E37_79B9_7F4A_7C15u64;
        let mut next = |n: u64| {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((seed >> 33) % n) as u32
        };
        for step in 0..20u32 {
            patches.clear();
            model.clear();
            for phase in 0..2u32 {
                // Distinct patches within a phase, half of the second's measured in the first.
                let start = next(100) + phase * 50;
                let mut uds: Vec<u32> = (start..start + 100).collect();
                for i in (1..uds.len()).rev() {
                    uds.swap(i, next(i as u64 + 1) as usize);
                }
                for (k, &ud) in uds.iter().enumerate() {
                    let m = measured((step * 1000 + phase * 100 + k as u32) as f64);
                    patches.insert(ud, m);
                    model.insert(ud, m.normal_force);
                }
                for ud in 0..300 {
                    let got = patches.get(ud).map(|m| m.normal_force);
                    assert_eq!(got, model.get(&ud).copied(), "unsealed, patch {ud}");
                }
                patches.seal();
                for ud in 0..300 {
                    let got = patches.get(ud);
                    assert_eq!(got.map(|m| m.normal_force), model.get(&ud).copied());
                    if let Some(m) = got {
                        assert_eq!(m.warm_start_impulse, -m.normal_force);
                        assert_eq!(m.mu, Vector::splat(m.normal_force as f32 * 0.1));
                    }
                }
                let order: Vec<u32> = patches.iter().map(|(ud, _)| ud).collect();
                assert_eq!(order, model.keys().copied().collect::<Vec<_>>());
            }
        }
        // Two records of one patch between seals: one entry, one of the two.
        patches.clear();
        patches.insert(7, measured(1.0));
        patches.insert(3, measured(3.0));
        patches.insert(7, measured(2.0));
        patches.seal();
        assert_eq!(patches.iter().count(), 2);
        assert!(matches!(
            patches.get(7).map(|m| m.normal_force),
            Some(1.0 | 2.0)
        ));
    }

    /// An entry is 32 bytes in 3D (28 in 2D), and a step of patches that was large once does
    /// not keep its memory for ever.
    #[test]
    fn patches_are_small_and_give_back_memory() {
        #[cfg(not(dim2))]
        assert_eq!(std::mem::size_of::<PatchEntry>(), 32);
        #[cfg(dim2)]
        assert_eq!(std::mem::size_of::<PatchEntry>(), 28);
        let mut patches = PatchMeasures::default();
        for ud in 0..10_000 {
            patches.insert(ud, measured(1.0));
        }
        patches.seal();
        patches.clear();
        patches.insert(1, measured(2.0));
        patches.seal();
        assert!(patches.heap_bytes() <= 68 * std::mem::size_of::<PatchEntry>());
        assert_eq!(patches.get(1).map(|m| m.normal_force), Some(2.0));
    }
}
