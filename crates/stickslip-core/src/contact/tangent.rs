//! Where an engine's world vectors meet the kernel's tangent-plane components: an orthonormal
//! basis of the contact's tangent plane (3D) or tangent line (2D), in world coordinates.
//!
//! World vectors are `[f32; 3]` (the engines' precision; a 2D engine's `(x, y)` is
//! `[x, y, 0]`), tangential components [`Vec2`] (f64). A 2D contact has one tangent: its basis
//! has `t2 = 0`, so every tangential vector the kernel sees has a zero second component and
//! the plane law reduces exactly to the law on a line.

use crate::vec2::Vec2;

/// A world vector as the kernel stores it: `[x, y, z]`, z = 0 in 2D.
pub type World = [f32; 3];

/// An orthonormal basis (t1, t2) of the plane normal to `n` (`t2 = 0` on a 2D tangent line).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TangentBasis {
    /// First tangent.
    pub t1: World,
    /// Second tangent (zero in 2D).
    pub t2: World,
    /// Unit normal.
    pub n: World,
}

/// The dot product of two world vectors, summed in x, y, z order as the engines' vector
/// types do.
#[inline]
pub fn dot(a: World, b: World) -> f32 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// The length of a world vector.
#[inline]
pub fn length(a: World) -> f32 {
    dot(a, a).sqrt()
}

impl TangentBasis {
    /// The basis of a 3D contact plane: `t1` any unit vector normal to the unit normal `n`,
    /// `t2 = n × t1` (the law is isotropic: any orientation of t1 works).
    pub fn plane(n: World, t1: World) -> Self {
        let t2 = [
            n[1] * t1[2] - n[2] * t1[1],
            n[2] * t1[0] - n[0] * t1[2],
            n[0] * t1[1] - n[1] * t1[0],
        ];
        TangentBasis { t1, t2, n }
    }

    /// The basis of a 2D contact's tangent line: `t1 = (−n_y, n_x)`, no second tangent.
    pub fn line(n: [f32; 2]) -> Self {
        TangentBasis {
            t1: [-n[1], n[0], 0.0],
            t2: [0.0; 3],
            n: [n[0], n[1], 0.0],
        }
    }

    /// Whether the contact has a single tangent (2D).
    pub fn is_line(&self) -> bool {
        self.t2 == [0.0; 3]
    }

    /// Tangential components of a world vector.
    #[inline]
    pub fn project(&self, v: World) -> Vec2 {
        [dot(v, self.t1) as f64, dot(v, self.t2) as f64]
    }

    /// World vector from tangential components.
    #[inline]
    pub fn lift(&self, v: Vec2) -> World {
        let (a, b) = (v[0] as f32, v[1] as f32);
        [
            self.t1[0] * a + self.t2[0] * b,
            self.t1[1] * a + self.t2[1] * b,
            self.t1[2] * a + self.t2[2] * b,
        ]
    }

    /// `v` with its normal component removed.
    #[inline]
    pub fn tangential(&self, v: World) -> World {
        let k = dot(v, self.n);
        [
            v[0] - self.n[0] * k,
            v[1] - self.n[1] * k,
            v[2] - self.n[2] * k,
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_plane_basis_round_trips_tangential_vectors_and_drops_the_normal() {
        let s = 0.5f32.sqrt();
        let b = TangentBasis::plane([0.0, s, s], [1.0, 0.0, 0.0]);
        assert!(dot(b.t2, b.n).abs() < 1e-7);
        assert!((length(b.t2) - 1.0).abs() < 1e-6);
        let v = [0.3, -0.2, 0.2];
        let t = b.tangential(v);
        let back = b.lift(b.project(v));
        for i in 0..3 {
            assert!((back[i] - t[i]).abs() < 1e-6, "{back:?} {t:?}");
        }
    }

    #[test]
    fn a_line_basis_keeps_one_component() {
        let b = TangentBasis::line([0.0, 1.0]);
        assert!(b.is_line());
        assert_eq!(b.project([2.0, 5.0, 0.0]), [-2.0, 0.0]);
        assert_eq!(b.lift([-2.0, 7.0]), [2.0, 0.0, 0.0]);
    }
}
