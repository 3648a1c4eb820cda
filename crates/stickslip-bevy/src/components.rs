//! Components users put on entities. Bridge components are named after bevy_rapier's
//! (`RigidBody`, `Collider`, `Velocity`, `ExternalForce`, `Friction`), so code reads the same;
//! the friction layer adds `FrictionLaw`, `Vibration` and `SurfaceVelocity`.

use bevy::prelude::*;
use rapier3d::prelude as rp;
use stickslip_rapier::{FrictionMaterial, VibrationSource};

/// A rigid body. Its entity's `Transform` is its pose (top-level entities; scale is ignored).
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
#[require(Transform, Velocity)]
pub enum RigidBody {
    /// Moved by forces, contacts and gravity.
    Dynamic,
    /// Never moves.
    Fixed,
    /// Follows its `Transform`, which the user animates (velocity derived by rapier).
    KinematicPositionBased,
    /// Follows its `Velocity`, which the user sets.
    KinematicVelocityBased,
}

/// A collision shape. On a `RigidBody` entity, or on a child of one (its `Transform` is then
/// the offset), or alone (a fixed collider at its `Transform`).
#[derive(Component, Clone)]
#[require(Transform)]
pub struct Collider {
    /// The shape (parry's).
    pub shape: rp::SharedShape,
}

impl Collider {
    /// A box with half extents.
    pub fn cuboid(hx: f32, hy: f32, hz: f32) -> Self {
        Collider {
            shape: rp::SharedShape::cuboid(hx, hy, hz),
        }
    }
    /// A ball.
    pub fn ball(radius: f32) -> Self {
        Collider {
            shape: rp::SharedShape::ball(radius),
        }
    }
    /// A capsule along the local y axis.
    pub fn capsule_y(half_height: f32, radius: f32) -> Self {
        Collider {
            shape: rp::SharedShape::capsule_y(half_height, radius),
        }
    }
}

impl std::fmt::Debug for Collider {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Collider")
            .field("shape", &self.shape.shape_type())
            .finish()
    }
}

/// Linear and angular velocity (world frame). Written back after every step; a value the user
/// sets is applied before the next one.
#[derive(Component, Debug, Clone, Copy, PartialEq, Default)]
pub struct Velocity {
    /// Linear velocity (m/s).
    pub linear: Vec3,
    /// Angular velocity (rad/s).
    pub angular: Vec3,
}

/// A force and torque applied at the center of mass at every step while present.
#[derive(Component, Debug, Clone, Copy, PartialEq, Default)]
pub struct ExternalForce {
    /// Force (N).
    pub force: Vec3,
    /// Torque (N·m).
    pub torque: Vec3,
}

/// Density of a collider (kg/m³, default 1000): sets its body's mass.
#[derive(Component, Debug, Clone, Copy, PartialEq)]
pub struct Density(pub f32);

/// rapier's own Coulomb friction coefficient of a collider that is not under stickslip
/// (default 0.5).
#[derive(Component, Debug, Clone, Copy, PartialEq)]
pub struct Friction(pub f32);

/// Lets a body fall asleep when slow. Off by default: rapier puts bodies to sleep below
/// ~0.4 m/s, which would freeze parts a vibrating conveyor carries at a few cm/s.
#[derive(Component, Debug, Clone, Copy, PartialEq, Default)]
pub struct AllowSleep;

/// Locks a dynamic body's rotations (a point-mass-like part).
#[derive(Component, Debug, Clone, Copy, PartialEq, Default)]
pub struct LockRotations;

/// Puts a collider's contacts under stickslip's friction: its own material, or the
/// [`crate::DefaultFriction`] resource's with `FrictionLaw(None)` / `FrictionLaw::default()`.
/// Removing it takes the collider back to plain rapier friction.
#[derive(Component, Debug, Clone, Default, PartialEq)]
pub struct FrictionLaw(pub Option<FrictionMaterial>);

impl FrictionLaw {
    /// A collider with its own material.
    pub fn new(material: impl Into<FrictionMaterial>) -> Self {
        FrictionLaw(Some(material.into()))
    }
}

/// A vibration source on a collider (normal, tangential or transverse; time-resolved or
/// Popov-averaged): every contact of the collider feels it. Insert, change or remove at will.
#[derive(Component, Debug, Clone)]
pub struct Vibration(pub VibrationSource);

/// A moving surface (conveyor belt): the velocity (m/s, world frame) its contacts carry
/// other bodies along with, as rapier's target tangent velocity.
#[derive(Component, Debug, Clone, Copy, PartialEq, Default)]
pub struct SurfaceVelocity(pub Vec3);

/// The rapier handle of an entity's body (inserted by the plugin).
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
pub struct RapierBody(pub rp::RigidBodyHandle);

/// The rapier handle of an entity's collider (inserted by the plugin).
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
pub struct RapierCollider(pub rp::ColliderHandle);
