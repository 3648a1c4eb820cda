//! The one place where rapier's `Vector` (f32, 3D or 2D) meets the kernel's world vectors
//! (`[f32; 3]`, z = 0 in 2D) and a contact's tangent plane (3D) or tangent line (2D).

use rapier::prelude::Vector;
use stickslip_core::contact::{TangentBasis, World};

/// The kernel's form of a world vector.
#[inline]
pub(crate) fn world(v: Vector) -> World {
    #[cfg(not(dim2))]
    {
        v.to_array()
    }
    #[cfg(dim2)]
    {
        [v.x, v.y, 0.0]
    }
}

/// rapier's form of a kernel world vector.
#[inline]
pub(crate) fn vector(w: World) -> Vector {
    #[cfg(not(dim2))]
    {
        Vector::from_array(w)
    }
    #[cfg(dim2)]
    {
        Vector::new(w[0], w[1])
    }
}

/// The tangent plane (3D) or line (2D) of a contact with unit normal `n`.
#[inline]
pub(crate) fn basis(n: Vector) -> TangentBasis {
    #[cfg(not(dim2))]
    {
        TangentBasis::plane(world(n), world(n.any_orthonormal_vector()))
    }
    #[cfg(dim2)]
    {
        TangentBasis::line([n.x, n.y])
    }
}
