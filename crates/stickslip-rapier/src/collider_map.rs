//! Dense per-collider storage indexed by the collider handle's arena slot: a lookup in the
//! contact hook is one bounds check and a generation compare, no hashing and no lock.

use rapier::prelude::ColliderHandle;

/// Largest arena index accepted (16.7 million colliders): the map is dense, so an index from
/// an invalid or forged handle must not size it.
pub(crate) const MAX_INDEX: u32 = 1 << 24;

/// Values attached to colliders.
#[derive(Debug, Clone)]
pub(crate) struct ColliderMap<T> {
    slots: Vec<Option<(u32, T)>>,
    /// Occupied slots (the hook asks for emptiness once per manifold).
    len: usize,
}

impl<T> Default for ColliderMap<T> {
    fn default() -> Self {
        ColliderMap {
            slots: Vec::new(),
            len: 0,
        }
    }
}

impl<T> ColliderMap<T> {
    pub fn insert(&mut self, handle: ColliderHandle, value: T) -> Option<T> {
        let (i, generation) = handle.0.into_raw_parts();
        if i >= MAX_INDEX {
            // Not a collider of any set this process can hold: never allocate by it.
            return None;
        }
        let i = i as usize;
        if self.slots.len() <= i {
            reserve_slack(&mut self.slots, i);
            self.slots.resize_with(i + 1, || None);
        }
        let old = self.slots[i].replace((generation, value));
        if old.is_none() {
            self.len += 1;
        }
        old.filter(|(g, _)| *g == generation).map(|(_, v)| v)
    }

    pub fn remove(&mut self, handle: ColliderHandle) -> Option<T> {
        let (i, generation) = handle.0.into_raw_parts();
        let slot = self.slots.get_mut(i as usize)?;
        match slot {
            Some((g, _)) if *g == generation => {
                self.len -= 1;
                slot.take().map(|(_, v)| v)
            }
            _ => None,
        }
    }

    pub fn get(&self, handle: ColliderHandle) -> Option<&T> {
        let (i, generation) = handle.0.into_raw_parts();
        match self.slots.get(i as usize)? {
            Some((g, v)) if *g == generation => Some(v),
            _ => None,
        }
    }

    /// Heap bytes held (capacity included).
    pub fn heap_bytes(&self) -> usize {
        crate::heap::vec_bytes(&self.slots)
    }

    /// Whether no collider has a value.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The entries, by increasing arena index.
    pub fn iter(&self) -> impl Iterator<Item = (ColliderHandle, &T)> {
        self.slots.iter().enumerate().filter_map(|(i, s)| {
            s.as_ref()
                .map(|(g, v)| (ColliderHandle::from_raw_parts(i as u32, *g), v))
        })
    }
}

/// Makes room for index `i` of a dense per-collider vector with 1/32 to spare, not double:
/// such vectors cover every collider of a world.
pub(crate) fn reserve_slack<T>(v: &mut Vec<T>, i: usize) {
    if v.capacity() <= i {
        v.reserve_exact(i + 1 + (i + 1) / 32 - v.len());
    }
}

/// Pushes `x`, growing `v` by 1/32 when it is full, not doubling it: buffers refilled every
/// step to about the last step's length (the contact patches seen and measured).
pub(crate) fn push_slack<T>(v: &mut Vec<T>, x: T) {
    let n = v.len();
    if n == v.capacity() {
        reserve_slack(v, n);
    }
    v.push(x);
}

/// A set of colliders as one bit per arena index (the pile of 10 000 attached boxes costs
/// 1.25 kB, not 80). Generations are not kept: callers give the live handle, and a collider is
/// detached before it is removed (or its bits apply to the next collider reusing its index).
#[derive(Debug, Clone, Default)]
pub(crate) struct ColliderBits {
    words: Vec<u64>,
}

impl ColliderBits {
    fn index(handle: ColliderHandle) -> Option<usize> {
        let i = handle.0.into_raw_parts().0;
        (i < MAX_INDEX).then_some(i as usize)
    }

    /// Sets or clears the bit of `handle`'s index.
    pub fn set(&mut self, handle: ColliderHandle, on: bool) {
        let Some(i) = Self::index(handle) else { return };
        let (w, b) = (i / 64, i % 64);
        if on {
            if self.words.len() <= w {
                reserve_slack(&mut self.words, w);
                self.words.resize(w + 1, 0);
            }
            self.words[w] |= 1 << b;
        } else if let Some(word) = self.words.get_mut(w) {
            *word &= !(1 << b);
        }
    }

    /// Heap bytes held (capacity included).
    pub fn heap_bytes(&self) -> usize {
        crate::heap::vec_bytes(&self.words)
    }

    /// Clears every bit (keeping the memory).
    pub fn clear(&mut self) {
        self.words.fill(0);
    }

    /// Whether the bit of `handle`'s index is set.
    pub fn contains(&self, handle: ColliderHandle) -> bool {
        Self::index(handle)
            .and_then(|i| self.words.get(i / 64).map(|w| w >> (i % 64) & 1 == 1))
            .unwrap_or(false)
    }

    /// Whether the bit of arena index `i` is set.
    pub fn contains_index(&self, i: u32) -> bool {
        let i = i as usize;
        self.words
            .get(i / 64)
            .is_some_and(|w| w >> (i % 64) & 1 == 1)
    }

    /// How many bits are set.
    pub fn count(&self) -> usize {
        self.words.iter().map(|w| w.count_ones() as usize).sum()
    }

    /// The set indices, increasing.
    pub fn indices(&self) -> impl Iterator<Item = u32> + '_ {
        self.words.iter().enumerate().flat_map(|(w, &word)| {
            (0..64)
                .filter(move |b| word >> b & 1 == 1)
                .map(move |b| (w * 64 + b) as u32)
        })
    }
}

/// [`ColliderBits`] that threads set concurrently (the contact hook runs on rapier's worker
/// threads with the `parallel` feature). Sized outside the step ([`Self::cover`]); a bit
/// beyond the size is dropped, never allocated for.
#[derive(Debug, Default)]
pub(crate) struct AtomicColliderBits {
    words: Vec<std::sync::atomic::AtomicU64>,
}

impl AtomicColliderBits {
    /// Heap bytes held (capacity included).
    pub fn heap_bytes(&self) -> usize {
        crate::heap::vec_bytes(&self.words)
    }

    /// Makes room for `handle`'s bit.
    pub fn cover(&mut self, handle: ColliderHandle) {
        if let Some(i) = ColliderBits::index(handle)
            && self.words.len() <= i / 64
        {
            reserve_slack(&mut self.words, i / 64);
            self.words.resize_with(i / 64 + 1, Default::default);
        }
    }

    /// Sets the bit of `handle`'s index (if covered).
    pub fn set(&self, handle: ColliderHandle) {
        let Some(i) = ColliderBits::index(handle) else {
            return;
        };
        if let Some(w) = self.words.get(i / 64) {
            w.fetch_or(1 << (i % 64), std::sync::atomic::Ordering::Relaxed);
        }
    }

    /// Whether the bit of `handle`'s index is set.
    pub fn contains(&mut self, handle: ColliderHandle) -> bool {
        ColliderBits::index(handle)
            .and_then(|i| {
                self.words
                    .get_mut(i / 64)
                    .map(|w| *w.get_mut() >> (i % 64) & 1 == 1)
            })
            .unwrap_or(false)
    }

    /// Clears every bit.
    pub fn clear(&mut self) {
        for w in &mut self.words {
            *w.get_mut() = 0;
        }
    }
}
