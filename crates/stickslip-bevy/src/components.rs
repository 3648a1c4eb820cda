//! The bridge's components, named after bevy_rapier's (`RigidBody`, `Collider`, `Velocity`,
//! `ExternalForce`, `Friction`) so that code reads the same, and the handles the plugin adds.

use bevy::prelude::*;
use rapier3d::prelude as rp;

/// A rigid body. Its entity's `Transform` is its pose: put bodies at the top level of the
/// hierarchy (rapier ignores scale).
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
#[require(Transform, Velocity)]
pub enum RigidBody {
    /// Moved by forces, contacts and gravity.
    Dynamic,
    /// Never moves (unless its `Transform` is set, which teleports it).
    Fixed,
    /// Follows its `Transform`, which the user animates; rapier derives its velocity, so
    /// what it carries feels a moving surface.
    KinematicPositionBased,
    /// Follows its `Velocity`, which the user sets.
    KinematicVelocityBased,
}

impl RigidBody {
    pub(crate) fn rapier_type(self) -> rp::RigidBodyType {
        match self {
            RigidBody::Dynamic => rp::RigidBodyType::Dynamic,
            RigidBody::Fixed => rp::RigidBodyType::Fixed,
            RigidBody::KinematicPositionBased => rp::RigidBodyType::KinematicPositionBased,
            RigidBody::KinematicVelocityBased => rp::RigidBodyType::KinematicVelocityBased,
        }
    }
}

/// A collision shape: on a `RigidBody` entity, on an entity any number of levels below one
/// (the `Transform`s from the body down to it are then its offset), or below no body (a fixed
/// collider where the whole hierarchy's `Transform`s put it). Replacing it changes the rapier
/// shape in place.
#[derive(Component, Clone)]
#[require(Transform)]
pub struct Collider {
    /// The shape (parry's).
    pub shape: rp::SharedShape,
}

impl Collider {
    /// A box with half extents.
    pub fn cuboid(hx: f32, hy: f32, hz: f32) -> Self {
        rp::SharedShape::cuboid(hx, hy, hz).into()
    }
    /// A ball.
    pub fn ball(radius: f32) -> Self {
        rp::SharedShape::ball(radius).into()
    }
    /// A capsule along the local y axis (half height of its cylinder part, radius).
    pub fn capsule_y(half_height: f32, radius: f32) -> Self {
        rp::SharedShape::capsule_y(half_height, radius).into()
    }
    /// A capsule between two local points.
    pub fn capsule(a: Vec3, b: Vec3, radius: f32) -> Self {
        use crate::convert::to_rapier;
        rp::SharedShape::capsule(to_rapier(a), to_rapier(b), radius).into()
    }
    /// A cylinder along the local y axis.
    pub fn cylinder(half_height: f32, radius: f32) -> Self {
        rp::SharedShape::cylinder(half_height, radius).into()
    }
}

impl From<rp::SharedShape> for Collider {
    fn from(shape: rp::SharedShape) -> Self {
        Collider { shape }
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

/// rapier's own Coulomb friction coefficient of a collider whose contacts are not under
/// stickslip (default 0.5), e.g. a trough's side walls.
#[derive(Component, Debug, Clone, Copy, PartialEq)]
pub struct Friction(pub f32);

/// How a collider's friction combines with another's (rapier's `friction_combine_rule`; the
/// rule stickslip combines materials by too). Without it: average, rapier's default.
#[derive(Component, Debug, Clone, Copy, PartialEq, Default)]
pub struct FrictionCombine(pub stickslip_rapier::core::law::CombineRule);

impl FrictionCombine {
    /// rapier's rule.
    pub fn rapier_rule(self) -> rapier3d::prelude::CoefficientCombineRule {
        use rapier3d::prelude::CoefficientCombineRule as R;
        use stickslip_rapier::core::law::CombineRule as C;
        match self.0 {
            C::Average => R::Average,
            C::Min => R::Min,
            C::Multiply => R::Multiply,
            C::Max => R::Max,
            C::ClampedSum => R::ClampedSum,
            C::GeometricMean => R::GeometricMean,
        }
    }
}

/// Mass of a collider (kg), instead of a [`Density`]: sets its body's mass.
#[derive(Component, Debug, Clone, Copy, PartialEq)]
pub struct ColliderMass(pub f32);

/// Restitution of a collider's contacts (0: no bounce, the default).
#[derive(Component, Debug, Clone, Copy, PartialEq, Default)]
pub struct Restitution(pub f32);

/// Velocity damping of a body (1/s): linear and angular.
#[derive(Component, Debug, Clone, Copy, PartialEq, Default)]
pub struct Damping {
    /// Linear damping (1/s).
    pub linear: f32,
    /// Angular damping (1/s).
    pub angular: f32,
}

/// Continuous collision detection for a fast body (no tunnelling through thin colliders).
#[derive(Component, Debug, Clone, Copy, PartialEq, Default)]
pub struct Ccd;

/// Lets a body fall asleep when slow. Off by default: rapier puts bodies to sleep below
/// ~0.4 m/s, which would freeze parts a vibrating conveyor carries at a few cm/s.
#[derive(Component, Debug, Clone, Copy, PartialEq, Default)]
pub struct AllowSleep;

/// Locks a dynamic body's rotations (a point-mass-like part).
#[derive(Component, Debug, Clone, Copy, PartialEq, Default)]
pub struct LockRotations;

/// The rapier handle of an entity's body (added by the plugin, removed with the body).
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
pub struct RapierBody(pub rp::RigidBodyHandle);

/// The rapier handle of an entity's collider (added by the plugin, removed with the collider).
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
pub struct RapierCollider(pub rp::ColliderHandle);
