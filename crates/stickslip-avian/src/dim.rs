//! The one place where avian's vectors (2D or 3D: the package stickslip-avian2d builds these
//! sources with cfg `dim2`) meet stickslip's: world vectors as the kernel's `[f32; 3]` and the
//! read-back's `Vec3` (z = 0 in 2D), a contact's tangent plane (3D) or line (2D), a body's
//! velocity at a point, a manifold's surface velocity and a constraint's friction impulse.

use avian::dynamics::solver::contact::ContactConstraint;
use avian::math::Vector;
use avian::prelude::*;
use bevy::prelude::*;
use stickslip_core::contact::{TangentBasis, World};

/// A body's angular velocity: a vector in 3D, a rate about z in 2D.
#[cfg(not(dim2))]
pub(crate) type Angular = Vec3;
/// A body's angular velocity: a vector in 3D, a rate about z in 2D.
#[cfg(dim2)]
pub(crate) type Angular = f32;

/// A world vector in 3D (z = 0 in 2D).
#[inline]
pub(crate) fn lift(v: Vector) -> Vec3 {
    #[cfg(not(dim2))]
    {
        v
    }
    #[cfg(dim2)]
    {
        v.extend(0.0)
    }
}

/// avian's form of a kernel world vector.
#[inline]
pub(crate) fn vector(w: World) -> Vector {
    #[cfg(not(dim2))]
    {
        Vec3::from_array(w)
    }
    #[cfg(dim2)]
    {
        Vec2::new(w[0], w[1])
    }
}

/// The tangent plane (3D) or line (2D) of a contact with unit normal `n`.
#[inline]
pub(crate) fn basis(n: Vector) -> TangentBasis {
    #[cfg(not(dim2))]
    {
        TangentBasis::plane(n.to_array(), n.any_orthonormal_vector().to_array())
    }
    #[cfg(dim2)]
    {
        TangentBasis::line(n.to_array())
    }
}

/// The velocity of a body's material point at `r` from its centre of mass.
#[inline]
pub(crate) fn point_velocity(linear: Vector, angular: Angular, r: Vector) -> Vector {
    #[cfg(not(dim2))]
    {
        linear + angular.cross(r)
    }
    #[cfg(dim2)]
    {
        linear + angular * r.perp()
    }
}

/// avian's friction direction of a 2D contact with normal `n` (`tangent_directions`).
#[cfg(dim2)]
#[inline]
fn tangent(n: Vector) -> Vector {
    Vec2::new(n.y, -n.x)
}

/// The manifold's tangent velocity (what the solver drives v₂ − v₁ plus it to zero).
#[inline]
pub(crate) fn surface(m: &ContactManifold) -> Vector {
    #[cfg(not(dim2))]
    {
        m.tangent_velocity
    }
    #[cfg(dim2)]
    {
        m.tangent_speed * tangent(m.normal)
    }
}

/// Writes the manifold's tangent velocity (its part along the tangent, in 2D).
#[inline]
pub(crate) fn set_surface(m: &mut ContactManifold, v: Vector) {
    #[cfg(not(dim2))]
    {
        m.tangent_velocity = v;
    }
    #[cfg(dim2)]
    {
        m.tangent_speed = v.dot(tangent(m.normal));
    }
}

/// A world normal in the frame of a collider turned by `rotation` (3D, z = 0 in 2D).
#[inline]
pub(crate) fn local_normal(rotation: Option<&Rotation>, n: Vector) -> Vec3 {
    #[cfg(not(dim2))]
    {
        rotation.map_or(n, |r| r.0.inverse() * n)
    }
    #[cfg(dim2)]
    {
        let (cos, sin) = rotation.map_or((1.0, 0.0), |r| (r.cos, r.sin));
        Vec3::new(cos * n.x + sin * n.y, -sin * n.x + cos * n.y, 0.0)
    }
}

/// The constraint's normal impulse and friction impulse on body 2 (world) as they stand.
pub(crate) fn impulses(c: &ContactConstraint) -> (f32, Vec3) {
    #[cfg(not(dim2))]
    {
        let t2 = c.tangent1.cross(c.normal);
        c.points.iter().fold((0.0, Vec3::ZERO), |(n, t), p| {
            let lt = p.tangent_part.as_ref().map_or(Vec2::ZERO, |t| t.impulse);
            (n + p.normal_part.impulse, t + lt.x * c.tangent1 + lt.y * t2)
        })
    }
    #[cfg(dim2)]
    {
        let t1 = tangent(c.normal);
        let (n, t) = c.points.iter().fold((0.0, 0.0), |(n, t), p| {
            let lt = p.tangent_part.as_ref().map_or(0.0, |t| t.impulse);
            (n + p.normal_part.impulse, t + lt)
        });
        (n, lift(t * t1))
    }
}

/// The size of a point's friction impulse in the current substep.
#[inline]
pub(crate) fn friction_impulse(
    p: &avian::dynamics::solver::contact::ContactConstraintPoint,
) -> f32 {
    p.tangent_part.as_ref().map_or(0.0, |t| {
        #[cfg(not(dim2))]
        {
            t.impulse.length()
        }
        #[cfg(dim2)]
        {
            t.impulse.abs()
        }
    })
}

/// An upper bound of a body's largest inverse principal inertia (1/(kg m²)): in 3D the
/// largest absolute row sum of its inverse tensor (no eigenvalue exceeds it).
pub(crate) fn largest_inverse_inertia(i: &ComputedAngularInertia) -> f32 {
    #[cfg(not(dim2))]
    {
        let m = i.inverse();
        let row = |a: f32, b: f32, c: f32| a.abs() + b.abs() + c.abs();
        row(m.m00, m.m01, m.m02)
            .max(row(m.m01, m.m11, m.m12))
            .max(row(m.m02, m.m12, m.m22))
    }
    #[cfg(dim2)]
    {
        i.inverse()
    }
}
