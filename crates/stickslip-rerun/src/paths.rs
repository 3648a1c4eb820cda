//! Every entity path and timeline the logger writes, in one place.
//!
//! | path | archetype | when |
//! |---|---|---|
//! | `world` | `ViewCoordinates` (right-handed, y up) | static |
//! | `world/bodies/{body}` | `Transform3D` (body pose) | every logged step |
//! | `world/bodies/{body}/{collider}` | `Transform3D` (pose relative to the body) + `Boxes3D` / `Ellipsoids3D` / `Capsules3D` / `Mesh3D` | static, once per collider |
//! | `world/contacts` | `AnnotationContext` (regime legend) | static |
//! | `world/contacts/points` | `Points3D`, colored and classed by regime (sticking / stick-slip / sliding) | every logged step (empty when there are no contacts) |
//! | `world/contacts/friction` | `Arrows3D`: friction force on the second body, from the contact point, scaled by the logger's `force_scale` (m/N) | every logged step |
//! | `world/contacts/rolling` | `Arrows3D`: rolling- plus spinning-resistance torque on the second body of each resisting pair, from the contact point, 0.3 m for the largest torque cap (μ · arm · F_n) first seen; colored and classed by the rolling regime (else the spinning one) | logged steps from the first with a resisting pair |
//! | `series/world/{sticking,stick_slip,sliding}` | `Scalars`: number of contacts per regime | every logged step |
//! | `series/world/{normal_force,friction_force,dissipated_power,dissipated_energy}` | `Scalars` (N, N, W, J) | every logged step |
//! | `series/bodies/{body}/{speed,displacement,normal_force,friction_force,effective_mu,dissipated_power}` | `Scalars` per non-fixed body, summed over the body's contacts | every logged step (first `max_body_series` bodies) |
//! | `series/contacts/{pair}/{mu,slip_speed,normal_force,effective_mu,dissipated_power}` | `Scalars` per contact manifold | logged steps where the contact exists (first `max_contact_series` contacts) |
//! | `series/contacts/{pair}/{rolling_torque,spinning_torque,rolling_mu,spinning_mu}` | `Scalars` per pair resisting rolling or spinning: torque magnitudes (N·m) and the coefficients used, \|torque\| / (arm · F_n) | logged steps where the pair resists |
//! | `series/vibration/{collider}/signal` | `Scalars`: normalized waveform w(f t + φ) of the collider's vibration source | every logged step |
//!
//! Every `series/...` entity gets its `SeriesLines` style (name, color) logged once, statically.
//!
//! Names: `{body}` is the name given with `RerunLogger::set_body_name` (else `body_{index}`),
//! `{collider}` is `collider_{j}` (j-th collider of the body, in rapier's order),
//! `{pair}` is `{collider A}--{collider B}` with colliders named `{body}` (or
//! `{body}.{j}` when the body has several colliders), plus `_{k}` for the k-th manifold of a
//! pair beyond the first.
//!
//! Timelines: [`STEP`] (sequence: steps taken, 0 = initial state) and [`SIM_TIME`] (duration:
//! simulated seconds). The SDK's automatic `log_time` timeline is turned off, so a recording
//! is a pure function of the simulation.

/// Sequence timeline: number of steps taken.
pub const STEP: &str = "step";
/// Duration timeline: simulated time (s).
pub const SIM_TIME: &str = "sim_time";

/// Root of the 3D scene.
pub const WORLD: &str = "world";
/// Parent of the regime legend and the contact entities.
pub const CONTACTS: &str = "world/contacts";
/// Contact points colored by regime.
pub const CONTACT_POINTS: &str = "world/contacts/points";
/// Friction force arrows.
pub const FRICTION_ARROWS: &str = "world/contacts/friction";
/// Rolling- and spinning-resistance torque arrows.
pub const ROLLING_ARROWS: &str = "world/contacts/rolling";

/// Per-world series names under [`WORLD_SERIES`].
pub const WORLD_SERIES: &str = "series/world";
/// Series of the number of sticking, stick-slip and sliding contacts.
pub const REGIME_SERIES: [&str; 3] = ["sticking", "stick_slip", "sliding"];
/// Series of world totals.
pub const TOTAL_SERIES: [&str; 4] = [
    "normal_force",
    "friction_force",
    "dissipated_power",
    "dissipated_energy",
];
/// Series per body.
pub const BODY_SERIES: [&str; 6] = [
    "speed",
    "displacement",
    "normal_force",
    "friction_force",
    "effective_mu",
    "dissipated_power",
];
/// Series per pair resisting rolling or spinning (beside its contact's series).
pub const ROLLING_SERIES: [&str; 4] = [
    "rolling_torque",
    "spinning_torque",
    "rolling_mu",
    "spinning_mu",
];
/// Series per contact.
pub const CONTACT_SERIES: [&str; 5] = [
    "mu",
    "slip_speed",
    "normal_force",
    "effective_mu",
    "dissipated_power",
];

/// `world/bodies/{body}`.
pub fn body(name: &str) -> String {
    format!("world/bodies/{name}")
}

/// `world/bodies/{body}/collider_{j}`.
pub fn collider(body_name: &str, j: usize) -> String {
    format!("world/bodies/{body_name}/collider_{j}")
}

/// `series/world/{series}`.
pub fn world_series(series: &str) -> String {
    format!("{WORLD_SERIES}/{series}")
}

/// `series/bodies/{body}/{series}`.
pub fn body_series(body_name: &str, series: &str) -> String {
    format!("series/bodies/{body_name}/{series}")
}

/// `series/contacts/{pair}/{series}`.
pub fn contact_series(pair: &str, series: &str) -> String {
    format!("series/contacts/{pair}/{series}")
}

/// `series/vibration/{collider}/signal`.
pub fn vibration_series(collider_name: &str) -> String {
    format!("series/vibration/{collider_name}/signal")
}
