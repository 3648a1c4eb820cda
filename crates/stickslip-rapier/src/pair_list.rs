//! Which contact pairs the pass after each step judges (see `recycle`): every pair rapier
//! keeps, or, when few colliders can go quiet, only the pairs of those colliders.
//!
//! A pair's finding can change something only through a collider that may go quiet (a
//! candidate: its flag is stickslip's, it carries no source or moving surface, nothing hooked
//! it at this step): the pair is hooked otherwise, and a hooked pair is quiet. Or through an
//! attached collider whose flag is the user's, which the user may have turned off. So the
//! pass needs only the pairs with one of those colliders on a side: in a world of thousands of
//! bodies where only a ground or a conveyor is attached, a few hundred pairs, not every pair
//! of the world — found through rapier's adjacency lists, at the price of a walk per collider,
//! so only when such colliders are few (at most one in [`WALK_SHARE`] of the colliders). Either
//! way the pairs are judged and their findings applied in the order of rapier's list, so both
//! ways decide alike, bit for bit.

use crate::collider_map::ColliderBits;
use rapier::prelude::*;

/// The pass walks the pairs of its colliders when they are at most one in this many of the
/// colliders (a walk reads a pair for each of its ends, and each step of it follows a link).
const WALK_SHARE: usize = 8;

/// The pairs the pass judges at a step.
#[derive(Debug, Default)]
pub(crate) struct PairList {
    /// Places in rapier's list of pairs, increasing; used when `all` is false.
    listed: Vec<u32>,
    all: bool,
}

impl PairList {
    /// Heap bytes held (capacity included).
    pub fn heap_bytes(&self) -> usize {
        crate::heap::vec_bytes(&self.listed)
    }

    /// The places to judge: `None` for every pair.
    pub fn places(&self) -> Option<&[u32]> {
        (!self.all).then_some(&self.listed[..])
    }

    /// Chooses the pairs for this step: those with a root on a side, the roots being the
    /// candidates to go quiet in `next` and the attached colliders whose flag is the user's
    /// (`attached` and not `flagged`); every pair when the roots are many, or `walk` says so
    /// (`Some(false)`: every pair, `Some(true)`: the roots' pairs, tests only).
    pub fn choose(
        &mut self,
        narrow_phase: &NarrowPhase,
        colliders: &ColliderSet,
        (next, attached, flagged): (&ColliderBits, &ColliderBits, &ColliderBits),
        walk: Option<bool>,
    ) {
        self.listed.clear();
        self.all = true;
        // The candidates are attached colliders with stickslip's flag.
        let root = |i: u32| {
            attached.contains_index(i) && (next.contains_index(i) || !flagged.contains_index(i))
        };
        let roots = || attached.indices().filter(|&i| root(i));
        let most = colliders.len() / WALK_SHARE;
        let few = roots().take(most + 1).count() <= most;
        if !walk.unwrap_or(few) {
            self.shrink();
            return;
        }
        let edges = narrow_phase.contact_graph().raw_graph().raw_edges();
        let Some(first) = edges.first() else {
            self.all = false;
            return;
        };
        let base = &first.weight as *const ContactPair as usize;
        let stride = std::mem::size_of_val(first);
        // A pair's place in rapier's list, from where it lies in the list's memory (checked).
        let place = |pair: &ContactPair| {
            let at = (pair as *const ContactPair as usize).checked_sub(base)? / stride;
            let there = edges.get(at).is_some_and(|e| std::ptr::eq(&e.weight, pair));
            there.then(|| u32::try_from(at).ok()).flatten()
        };
        for i in roots() {
            let Some((_, h)) = colliders.get_unknown_gen(i) else {
                continue;
            };
            for pair in narrow_phase.contact_pairs_with(h) {
                let other = if pair.collider1 == h {
                    pair.collider2
                } else {
                    pair.collider1
                };
                // A pair of two roots is listed once, from the root of the lower index.
                let j = other.0.into_raw_parts().0;
                if root(j) && j < i {
                    continue;
                }
                match place(pair) {
                    Some(at) => crate::collider_map::push_slack(&mut self.listed, at),
                    // Not where the list keeps its pairs (a rapier that keeps them otherwise):
                    // every pair is judged.
                    None => {
                        self.listed.clear();
                        self.shrink();
                        return;
                    }
                }
            }
        }
        self.listed.sort_unstable();
        self.listed.dedup();
        self.all = false;
        self.shrink();
    }

    /// Gives back what a step with many more pairs left, with room to spare.
    fn shrink(&mut self) {
        if self.listed.capacity() > 4 * self.listed.len() + 256 {
            self.listed.shrink_to(2 * self.listed.len() + 64);
        }
    }
}
