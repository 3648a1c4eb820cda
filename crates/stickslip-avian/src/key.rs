//! Which contact a friction state belongs to. avian rebuilds a pair's manifolds every tick,
//! with no id that survives; the pair's collider entities (with their generations: no stale
//! reuse) and, on a pair with several manifolds (a composite shape: trimesh, heightfield,
//! compound), the direction of the manifold's normal in collider 1's frame name it.

use bevy::prelude::*;

/// Cell size of the normal's direction (about 1.1°): manifolds of one face of a composite
/// shape share a state, as rapier's adapter clusters its patches.
const NORMAL_CELL: f32 = 0.02;

/// A part of a pair's contact.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) enum Part {
    /// The pair's only manifold (two convex shapes).
    Whole,
    /// The manifolds of a pair with several whose normals, in collider 1's frame, fall in one
    /// cell.
    Cluster([i16; 3]),
}

/// One contact's key: avian's pair order, and the part.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) struct ContactKey {
    pub collider1: Entity,
    pub collider2: Entity,
    pub part: Part,
}

impl Part {
    /// The part of a manifold on a pair of `manifolds` manifolds, its normal `local` in
    /// collider 1's frame.
    pub(crate) fn of(manifolds: usize, local: Vec3) -> Part {
        if manifolds <= 1 {
            return Part::Whole;
        }
        let cell = |x: f32| (x / NORMAL_CELL).round().clamp(-100.0, 100.0) as i16;
        Part::Cluster([cell(local.x), cell(local.y), cell(local.z)])
    }
}
