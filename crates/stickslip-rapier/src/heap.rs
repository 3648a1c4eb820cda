//! What stickslip's heap holds, part by part (a bench instrument): every container a
//! [`StickSlip`] owns, counted at its allocated capacity (spare room included), hash maps
//! with their control bytes. What a stored value owns in turn is not followed (a palette
//! material's law owns none; a wrapped user hook's heap is the user's).

use crate::StickSlip;
use std::mem::size_of;

/// Heap bytes of a vector's allocation.
pub(crate) fn vec_bytes<T>(v: &Vec<T>) -> usize {
    v.capacity() * size_of::<T>()
}

/// Heap bytes of a std (hashbrown) map's table: its buckets (a power of two, at most 7/8
/// full; `capacity` is what they hold), one control byte each and a group of 16 more.
pub(crate) fn map_bytes<K, V, S>(m: &std::collections::HashMap<K, V, S>) -> usize {
    let cap = m.capacity();
    let buckets = match cap {
        0 => return 0,
        1..8 => cap + 1,
        _ => (cap / 7 * 8).next_power_of_two(),
    };
    buckets * (size_of::<(K, V)>() + 1) + 16
}

impl<H> StickSlip<H> {
    /// stickslip's heap by part, in bytes (see the module docs): contact records, key map,
    /// free list and the wrapped hook's `user_data` (the store); the quiet colliders' poses
    /// and every per-collider bit set (recycling); materials, per-pair overrides and combined
    /// laws; vibration sources and surface velocities; the contact patches seen and measured
    /// by composite shapes; rolling resistance; per-contact reports. A bench instrument, not
    /// API.
    #[doc(hidden)]
    pub fn heap_parts(&self) -> [(&'static str, usize); 8] {
        let patches_seen = vec_bytes(&crate::contact_store::lock(&self.patches_seen));
        [
            ("store", self.store.heap_bytes()),
            ("recycling", self.recycling.heap_bytes()),
            (
                "colliders",
                self.attached.heap_bytes() + self.flagged.heap_bytes(),
            ),
            ("laws", self.laws.heap_bytes()),
            (
                "sources",
                self.vibrations.heap_bytes() + self.surfaces.heap_bytes(),
            ),
            ("patches", patches_seen + self.patches_measured.heap_bytes()),
            ("rolling", self.rolling.heap_bytes()),
            ("reports", vec_bytes(&self.reports)),
        ]
    }

    /// All of stickslip's heap in bytes: the sum of [`Self::heap_parts`]. A bench
    /// instrument, not API.
    #[doc(hidden)]
    pub fn heap_bytes(&self) -> usize {
        self.heap_parts().iter().map(|(_, b)| b).sum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A map's count is its table: at least its entries and their control bytes, and never
    /// more than twice the room those need plus a group.
    #[test]
    fn a_map_is_counted_by_its_table() {
        let mut m: std::collections::HashMap<u64, u32> = Default::default();
        assert_eq!(map_bytes(&m), 0);
        let entry = size_of::<(u64, u32)>() + 1;
        for n in 1..2000usize {
            m.insert(n as u64, 0);
            let b = map_bytes(&m);
            assert!(b >= n * entry + 16, "{n}: {b}");
            assert!(b <= (2 * n * 8 / 7 + 8) * entry + 16, "{n}: {b}");
        }
    }
}
