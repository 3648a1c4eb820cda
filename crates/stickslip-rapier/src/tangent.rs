//! The one place where rapier's `Vec3` (f32) meets the core's tangent-plane `[f64; 2]`.

use rapier3d::prelude::Vector;
use stickslip_core::vec2::Vec2;

/// An orthonormal basis (t1, t2) of the plane normal to `n`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct TangentBasis {
    pub t1: Vector,
    pub t2: Vector,
    pub n: Vector,
}

impl TangentBasis {
    /// Basis for unit normal `n` (any orientation of t1 works: the law is isotropic).
    pub fn new(n: Vector) -> Self {
        let t1 = n.any_orthonormal_vector();
        TangentBasis {
            t1,
            t2: n.cross(t1),
            n,
        }
    }

    /// Tangential components of a world vector.
    pub fn project(&self, v: Vector) -> Vec2 {
        [v.dot(self.t1) as f64, v.dot(self.t2) as f64]
    }

    /// World vector from tangential components.
    pub fn lift(&self, v: Vec2) -> Vector {
        self.t1 * v[0] as f32 + self.t2 * v[1] as f32
    }

    /// `v` with its normal component removed.
    pub fn tangential(&self, v: Vector) -> Vector {
        v - self.n * v.dot(self.n)
    }
}
