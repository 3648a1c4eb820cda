//! The components a bevy_rapier app puts on its colliders to use stickslip.

use bevy::prelude::*;
use stickslip_rapier_035::{FrictionMaterial, VibrationSource};

/// Puts a collider under stickslip: its pairs get stickslip's friction, with this material
/// (`None`: the plugin's default material).
#[derive(Component, Debug, Clone, PartialEq)]
pub struct StickSlipFriction(pub Option<FrictionMaterial>);

/// A vibration source on a stickslip collider: its contacts feel it (Popov's reduced static
/// and sliding friction, elliptical drives; see `stickslip_rapier::VibrationSource`).
#[derive(Component, Debug, Clone)]
pub struct StickSlipVibration(pub VibrationSource);

/// The velocity of a collider's surface relative to its body (a conveyor belt, m/s, world
/// axes): its contacts' target tangent velocity, on any pair (with or without stickslip).
#[derive(Component, Debug, Clone, Copy, PartialEq)]
pub struct SurfaceVelocity(pub Vec3);
