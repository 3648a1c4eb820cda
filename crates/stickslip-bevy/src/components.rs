//! The components an app puts on its colliders to use stickslip.

use bevy::prelude::*;
use stickslip_core::FrictionMaterial;
use stickslip_core::contact::VibrationSource;

/// Puts a collider under a stickslip material: its pairs get stickslip's law with this
/// material (`None`: the plugin's default material) instead of the engine's friction.
#[derive(Component, Debug, Clone, PartialEq)]
pub struct StickSlipFriction(pub Option<FrictionMaterial>);

/// A vibration source on a collider: its contacts feel it (Popov's reduced static and sliding
/// friction, elliptical drives; see `stickslip_core::contact::VibrationSource`).
#[derive(Component, Debug, Clone)]
pub struct StickSlipVibration(pub VibrationSource);

/// The velocity of a collider's surface relative to its body (a conveyor belt, m/s, world
/// axes): the target tangent velocity of its contacts, on every pair (with or without a
/// stickslip material).
#[derive(Component, Debug, Clone, Copy, PartialEq)]
pub struct SurfaceVelocity(pub Vec3);
