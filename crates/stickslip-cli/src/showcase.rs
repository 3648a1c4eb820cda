//! What the bare `stickslip run` shows: the built-in scenario's three troughs compared — how
//! fast each one's boxes move down the chute, against what the theory says they should.

use serde::Serialize;
use stickslip_core::popov;
use stickslip_core::waveform::Waveform;
use stickslip_scenario::{Scenario, Summary};

/// The built-in scenario's slope, material and vibration (`scenarios/showcase.toml`).
const SLOPE_DEG: f64 = 16.699;
const MU0: f64 = 0.5;
const C: f64 = 1e5;
const ALPHA: f64 = 0.6;
const FREQUENCY: f64 = 20_000.0;

/// One trough of the comparison.
#[derive(Debug, Serialize)]
pub struct Row {
    /// Body-name prefix of the trough's boxes.
    pub trough: &'static str,
    /// What is in it.
    pub what: &'static str,
    /// Mean speed of its boxes down the chute at the end of the run (m/s).
    pub speed: f64,
    /// What the theory says (m/s).
    pub theory: f64,
    /// Why.
    pub why: &'static str,
}

/// Whether `scenario` is the built-in showcase (then [`compare`] applies).
pub fn applies(scenario: &Scenario) -> bool {
    scenario.name == Scenario::builtin().name
}

/// Popov's conveying speed on the vibrated trough: the mean sliding friction
/// μ0 (1 − α Ψ_sine(β)) equals tan θ at β*, and v* = β* μ0 α f / c (the EP contact's
/// tangential stiffness is c F̄, so β = c v / (μ0 α f)).
pub fn conveying_speed() -> Option<f64> {
    let target = (1.0 - SLOPE_DEG.to_radians().tan() / MU0) / ALPHA;
    let g = |beta: f64| popov::psi(&Waveform::Sine, beta).map_or(f64::NAN, |p| p - target);
    let mut conv = roots::SimpleConvergency {
        eps: 1e-12,
        max_iter: 200,
    };
    let beta = roots::find_root_brent(1e-6, 100.0, g, &mut conv).ok()?;
    Some(beta * MU0 * ALPHA * FREQUENCY / C)
}

/// The three troughs after a run of the built-in scenario.
pub fn compare(summary: &Summary) -> Vec<Row> {
    let (s, c) = SLOPE_DEG.to_radians().sin_cos();
    // Mean velocity along the chute (downhill +x rotated by −θ about z).
    let speed = |prefix: &str| {
        let v: Vec<f64> = summary
            .bodies
            .iter()
            .filter(|b| b.name.starts_with(prefix) && b.name.contains("_box"))
            .map(|b| b.velocity[0] * c - b.velocity[1] * s)
            .collect();
        if v.is_empty() {
            f64::NAN
        } else {
            v.iter().sum::<f64>() / v.len() as f64
        }
    };
    vec![
        Row {
            trough: "ep_still",
            what: "EP friction, no vibration",
            speed: speed("ep_still"),
            theory: 0.0,
            why: "sticks: tan θ = 0.3 < μ_ba = 0.5",
        },
        Row {
            trough: "ep_vibrated",
            what: "EP friction, 20 kHz normal vibration α = 0.6",
            speed: speed("ep_vibrated"),
            theory: conveying_speed().unwrap_or(f64::NAN),
            why: "Popov Eq. 33: μ0 (1 − α Ψ(β)) = tan θ",
        },
        Row {
            trough: "plain",
            what: "plain rapier Coulomb friction μ = 0.5",
            speed: speed("plain"),
            theory: 0.0,
            why: "sticks, and cannot feel a 20 kHz vibration at 120 Hz steps",
        },
    ]
}

/// Prints the comparison and how to look at the run.
pub fn print(rows: &[Row], rrd: Option<&str>) {
    out!("\nwhat the three troughs did (boxes on a 16.7° chute, speed down the chute):");
    out!(
        "  {:<46} {:>12} {:>12}  why",
        "trough",
        "measured",
        "theory"
    );
    for r in rows {
        out!(
            "  {:<46} {:>9.2} mm/s {:>7.2} mm/s  {}",
            r.what,
            r.speed * 1e3,
            r.theory * 1e3,
            r.why
        );
    }
    match rrd {
        Some(path) => out!("\nrecording: {path}\nopen it with: rerun {path}"),
        None => out!(
            "\nrecord the run with `stickslip run --rrd showcase.rrd`, then open it with \
             `rerun showcase.rrd`"
        ),
    }
}
