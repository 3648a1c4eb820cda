//! The scenario file format: plain serde types, one per TOML table.
//!
//! Every struct denies unknown fields, so a misspelled key is an error naming it, never a
//! silently ignored setting. Arrays of tables use singular names (`[[body]]`,
//! `[[body.collider]]`, `[[driver]]`); named tables are maps (`[material.NAME]`,
//! `[vibration.NAME]`). Units are SI throughout (m, kg, s, N); angles are in degrees.
//!
//! ```toml
//! name = "block"
//! [world]
//! dt = 0.005
//! [run]
//! duration = 3.0
//! [material.ep]
//! law = "ep"
//! c = 1e4
//! mu_ba = 0.3
//! mu_max = 0.32
//! curve = { kind = "constant", mu = 0.32 }
//! [[body]]
//! name = "ground"
//! kind = "fixed"
//! [[body.collider]]
//! shape = { kind = "cuboid", half_extents = [5.0, 0.1, 5.0] }
//! material = "ep"
//! [[body]]
//! name = "block"
//! position = [0.0, 0.15, 0.0]
//! [[body.collider]]
//! shape = { kind = "cuboid", half_extents = [0.05, 0.05, 0.05] }
//! density = 1000.0
//! [[driver]]
//! kind = "force"
//! body = "block"
//! direction = [1.0, 0.0, 0.0]
//! knots = [[0.0, 0.0], [1.0, 2.0]]
//! ```

use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use stickslip_core::law::Law;
use stickslip_core::waveform::Waveform;
use stickslip_rapier::{Amplitude, VibrationDirection, VibrationMode};

/// A whole scenario file.
#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Scenario {
    /// Short name (used as the rerun application id and in summaries).
    pub name: String,
    /// What the scenario shows and what to look for.
    #[serde(default)]
    pub description: String,
    /// Gravity, time step and solver settings.
    #[serde(default)]
    pub world: WorldSpec,
    /// How long to run and what to log.
    #[serde(default)]
    pub run: RunSpec,
    /// The contact modifier's settings and default material.
    #[serde(default)]
    pub stickslip: StickSlipSpec,
    /// Named friction materials: any core [`Law`] (`law = "ep" | "phys" | "regul" | "coulomb"`).
    #[serde(default, rename = "material")]
    pub materials: BTreeMap<String, Law>,
    /// Named vibration sources, attached to colliders by name.
    #[serde(default, rename = "vibration")]
    pub vibrations: BTreeMap<String, VibrationSpec>,
    /// Rigid bodies with their colliders.
    #[serde(default, rename = "body")]
    pub bodies: Vec<BodySpec>,
    /// Drivers acting on bodies each step.
    #[serde(default, rename = "driver")]
    pub drivers: Vec<DriverSpec>,
}

/// `[world]`: gravity, time step, solver.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct WorldSpec {
    /// Gravity (m/s²).
    pub gravity: [f64; 3],
    /// Time step (s).
    pub dt: f64,
    /// rapier's `num_solver_iterations`.
    pub solver_iterations: usize,
    /// rapier's friction model: `"simplified"` (rapier's 3D default, one friction constraint
    /// per manifold) or `"coulomb"` (per point).
    pub friction_model: FrictionModelSpec,
}

impl Default for WorldSpec {
    fn default() -> Self {
        WorldSpec {
            gravity: [0.0, -9.81, 0.0],
            dt: 1.0 / 60.0,
            solver_iterations: 4,
            friction_model: FrictionModelSpec::Simplified,
        }
    }
}

/// rapier's friction model.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum FrictionModelSpec {
    /// One friction constraint per manifold plus twist.
    #[default]
    Simplified,
    /// One friction constraint per contact point.
    Coulomb,
}

/// `[run]`: length of the run and logging.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct RunSpec {
    /// Number of steps (give this or `duration`, not both).
    pub steps: Option<u64>,
    /// Simulated time (s), rounded up to whole steps.
    pub duration: Option<f64>,
    /// Log every k-th step (1 = every step).
    pub log_every: u64,
    /// Per-contact series are logged for at most this many contacts (the first ones by
    /// collider pair); world and per-body series are always logged.
    pub max_contact_series: usize,
}

impl Default for RunSpec {
    fn default() -> Self {
        RunSpec {
            steps: None,
            duration: None,
            log_every: 1,
            max_contact_series: 16,
        }
    }
}

/// Steps a run without `steps` or `duration` takes.
pub const DEFAULT_STEPS: u64 = 300;

/// `[stickslip]`: modifier settings.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct StickSlipSpec {
    /// Material of stickslip contacts whose colliders name none (a key of `[material]`).
    /// Defaults to the only material when there is exactly one.
    pub default_material: Option<String>,
    /// `StickSlipConfig::stiffness_time` (s).
    pub stiffness_time: Option<f64>,
}

/// `[vibration.NAME]`: a vibration source (see `stickslip_rapier::VibrationSource`): one
/// component given inline (`direction`, `amplitude`, `waveform`, `phase`), or up to three
/// superimposed ones in `components` (Popov's Eq. 9: normal, tangential and transverse
/// oscillation at one frequency, e.g. an elliptical drive), not both.
#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct VibrationSpec {
    /// `{ kind = "normal" }`, `{ kind = "tangential", axis = [..] }` or
    /// `{ kind = "transverse", axis = [..] }` (single-component form).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub direction: Option<VibrationDirection>,
    /// `{ ratio = α }` (of the mean normal force) or `{ force = A }` (N) (single-component
    /// form).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub amplitude: Option<Amplitude>,
    /// Frequency (Hz), shared by every component.
    pub frequency: f64,
    /// Waveform, e.g. `{ kind = "sine" }` (the default), `"sawtooth-right"`, `"square"`, …
    /// (single-component form).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub waveform: Option<Waveform>,
    /// Phase offset (periods; single-component form, default 0).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub phase: Option<f64>,
    /// Superimposed components, `[{ direction = .., amplitude = .., waveform = .., phase =
    /// .. }, ..]` (instead of the single-component fields).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub components: Vec<ComponentSpec>,
    /// `"time-resolved"` (default) or `"averaged"`.
    #[serde(default)]
    pub mode: VibrationMode,
    /// Tangential contact stiffness (N/m) for β in averaged mode.
    #[serde(default)]
    pub tangential_stiffness: Option<f64>,
}

/// One component of `[vibration.NAME] components = [..]`.
#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ComponentSpec {
    /// `{ kind = "normal" }`, `{ kind = "tangential", axis = [..] }` or
    /// `{ kind = "transverse", axis = [..] }`.
    pub direction: VibrationDirection,
    /// `{ ratio = α }` (of the mean normal force) or `{ force = A }` (N).
    pub amplitude: Amplitude,
    /// Waveform (default sine).
    #[serde(default = "default_waveform")]
    pub waveform: Waveform,
    /// Phase offset (periods).
    #[serde(default)]
    pub phase: f64,
}

fn default_waveform() -> Waveform {
    Waveform::Sine
}

/// Rigid-body type.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum BodyKind {
    /// Never moves.
    Fixed,
    /// Simulated.
    #[default]
    Dynamic,
    /// Moved by its velocity (velocity-based kinematic), e.g. a belt or a dragged plate.
    Kinematic,
}

/// `[[body]]`: a rigid body and its colliders.
#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BodySpec {
    /// Unique name (letters, digits, `_`, `-`); drivers refer to it. Repeated bodies are
    /// named `NAME_i` (i from 0) and drivers naming `NAME` act on all of them.
    pub name: String,
    /// `"fixed"`, `"dynamic"` (default) or `"kinematic"`.
    #[serde(default)]
    pub kind: BodyKind,
    /// Position (m).
    #[serde(default)]
    pub position: [f64; 3],
    /// Orientation as Euler angles (degrees): about x, then the new y, then the new z
    /// (intrinsic XYZ).
    #[serde(default)]
    pub rotation_deg: [f64; 3],
    /// Initial linear velocity (m/s).
    #[serde(default)]
    pub linvel: [f64; 3],
    /// Initial angular velocity (rad/s).
    #[serde(default)]
    pub angvel: [f64; 3],
    /// Linear damping (1/s).
    #[serde(default)]
    pub linear_damping: f64,
    /// Angular damping (1/s).
    #[serde(default)]
    pub angular_damping: f64,
    /// Whether the body may fall asleep (off by default so contacts keep being reported).
    #[serde(default)]
    pub can_sleep: bool,
    /// Lock all rotations (a block that only translates).
    #[serde(default)]
    pub lock_rotations: bool,
    /// Continuous collision detection.
    #[serde(default)]
    pub ccd: bool,
    /// Make `count` copies, each shifted by `offset` from the previous one.
    #[serde(default)]
    pub repeat: Option<RepeatSpec>,
    /// Colliders attached to the body.
    #[serde(default, rename = "collider")]
    pub colliders: Vec<ColliderSpec>,
}

/// `repeat = { count = N, offset = [dx, dy, dz] }`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RepeatSpec {
    /// Number of bodies (≥ 1).
    pub count: u32,
    /// Shift between consecutive copies (m).
    pub offset: [f64; 3],
}

/// `[[body.collider]]`: a collider.
#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ColliderSpec {
    /// The shape.
    pub shape: ShapeSpec,
    /// Position relative to the body (m).
    #[serde(default)]
    pub offset: [f64; 3],
    /// Orientation relative to the body, Euler angles (degrees, intrinsic XYZ).
    #[serde(default)]
    pub rotation_deg: [f64; 3],
    /// Density (kg/m³); rapier's default 1 when neither this nor `mass` is given.
    #[serde(default)]
    pub density: Option<f64>,
    /// Mass (kg), instead of a density.
    #[serde(default)]
    pub mass: Option<f64>,
    /// rapier's own friction coefficient: for pairs without stickslip, and the plain
    /// Coulomb side of a pair with an attached collider (see `StickSlip::attach`).
    #[serde(default = "default_friction")]
    pub friction: f64,
    /// How this collider's friction combines with another's (rapier's
    /// `friction_combine_rule`, also for stickslip's materials): "average" (default), "min",
    /// "multiply", "max", "clamped-sum", "geometric-mean".
    #[serde(default)]
    pub combine: stickslip_core::law::CombineRule,
    /// Restitution.
    #[serde(default)]
    pub restitution: f64,
    /// Attach to stickslip with this material (a key of `[material]`).
    #[serde(default)]
    pub material: Option<String>,
    /// Attach to stickslip with the default material.
    #[serde(default)]
    pub stickslip: bool,
    /// A vibration source (a key of `[vibration]`) felt by this collider's contacts.
    #[serde(default)]
    pub vibration: Option<String>,
}

fn default_friction() -> f64 {
    0.5
}

/// A collider shape (centered on the collider's position).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "kebab-case", deny_unknown_fields)]
pub enum ShapeSpec {
    /// A box.
    Cuboid {
        /// Half extents (m).
        half_extents: [f64; 3],
    },
    /// A sphere.
    Ball {
        /// Radius (m).
        radius: f64,
    },
    /// A capsule along the collider's y axis.
    Capsule {
        /// Half the length of the segment between the cap centers (m).
        half_height: f64,
        /// Radius (m).
        radius: f64,
    },
}

/// `[[driver]]`: something acting on a body every step.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "kebab-case", deny_unknown_fields)]
pub enum DriverSpec {
    /// Drags a kinematic body at constant velocity from `start` on (at rest before).
    Velocity {
        /// Body or group name (must be kinematic).
        body: String,
        /// Linear velocity (m/s).
        velocity: [f64; 3],
        /// Angular velocity (rad/s).
        #[serde(default)]
        angular: [f64; 3],
        /// Start time (s).
        #[serde(default)]
        start: f64,
    },
    /// A linear spring (and damper) of zero rest length from a body point p to an anchor a(t)
    /// moving at constant velocity: F = k (a(t) − p) + d (ȧ − ṗ), restricted to `axis` when
    /// given. The anchor starts at the attachment point's initial position plus
    /// `anchor_offset`, so a group driver gives every copy its own anchor.
    Spring {
        /// Body or group name (must be dynamic).
        body: String,
        /// Stiffness k (N/m).
        stiffness: f64,
        /// Damping d (N·s/m).
        #[serde(default)]
        damping: f64,
        /// Anchor at t = 0 relative to the attachment point's initial position (m); zero
        /// (the default) starts the spring unstretched.
        #[serde(default)]
        anchor_offset: [f64; 3],
        /// Anchor velocity (m/s).
        #[serde(default)]
        anchor_velocity: [f64; 3],
        /// Attachment point in the body's frame (m); default its origin.
        #[serde(default)]
        point: [f64; 3],
        /// Restrict the spring to this world axis.
        #[serde(default)]
        axis: Option<[f64; 3]>,
    },
    /// A force along `direction` with magnitude F(t) through `(t, F)` knots, linear in
    /// between, constant after the last one (the first knot at t = 0).
    Force {
        /// Body or group name (must be dynamic).
        body: String,
        /// Direction (normalized when built).
        direction: [f64; 3],
        /// `[[t0, F0], [t1, F1], ...]` (s, N).
        knots: Vec<[f64; 2]>,
        /// Point of application in the body's frame (m); default its center of mass.
        #[serde(default)]
        point: Option<[f64; 3]>,
    },
}

impl DriverSpec {
    /// The body (or group) the driver acts on.
    pub fn body(&self) -> &str {
        match self {
            DriverSpec::Velocity { body, .. }
            | DriverSpec::Spring { body, .. }
            | DriverSpec::Force { body, .. } => body,
        }
    }
}
