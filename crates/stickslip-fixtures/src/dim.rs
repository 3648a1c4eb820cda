//! What differs between the 3D and the 2D build of the tests (cfg `dim2`), so a test is
//! written once: a body's (and a world's) state as bits, a spin about the plane's normal. (Vectors and
//! cuboids from 3D components: [`crate::v3`], [`crate::cuboid3`].)

use stickslip_rapier::rapier::prelude::*;

/// The bits of a body's pose (translation, rotation) and velocities (linear, angular).
pub fn body_bits(b: &RigidBody) -> Vec<u32> {
    let p = b.position();
    let mut out: Vec<u32> = p.translation.to_array().map(f32::to_bits).to_vec();
    out.extend(b.linvel().to_array().map(f32::to_bits));
    #[cfg(dim2)]
    {
        out.extend([p.rotation.cos(), p.rotation.sin(), b.angvel()].map(f32::to_bits));
    }
    #[cfg(not(dim2))]
    {
        out.extend(p.rotation.to_array().map(f32::to_bits));
        out.extend(b.angvel().to_array().map(f32::to_bits));
    }
    out
}

/// The bits of every body's pose and velocities, in the world's body order.
pub fn world_bits(world: &PhysicsWorld) -> Vec<u32> {
    world
        .bodies
        .iter()
        .flat_map(|(_, b)| body_bits(b))
        .collect()
}

/// An angular velocity of `w` (rad/s) about z, the 2D plane's normal.
pub fn spin(w: f32) -> AngVector {
    #[cfg(dim2)]
    let s = w;
    #[cfg(not(dim2))]
    let s = Vector::new(0.0, 0.0, w);
    s
}

/// A cuboid shape from its 3D half-extents (2D: z dropped).
pub fn cuboid_shape(hx: f32, hy: f32, hz: f32) -> SharedShape {
    #[cfg(dim2)]
    let s = {
        let _ = hz;
        SharedShape::cuboid(hx, hy)
    };
    #[cfg(not(dim2))]
    let s = SharedShape::cuboid(hx, hy, hz);
    s
}

/// A body's angular velocity about z, the 2D plane's normal (rad/s).
pub fn spin_z(b: &RigidBody) -> f32 {
    #[cfg(dim2)]
    let w = b.angvel();
    #[cfg(not(dim2))]
    let w = b.angvel().z;
    w
}

/// The velocity of a body's material point at `p` (world): v + ω × (p − c).
pub fn point_velocity(b: &RigidBody, p: Vector) -> Vector {
    let arm = p - b.center_of_mass();
    #[cfg(dim2)]
    let v = b.linvel() + Vector::new(-arm.y, arm.x) * b.angvel();
    #[cfg(not(dim2))]
    let v = b.linvel() + b.angvel().cross(arm);
    v
}
