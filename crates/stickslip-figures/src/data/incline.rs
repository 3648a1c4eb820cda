//! Creep on an incline over time (`crates/stickslip-fixtures/tests/rapier_incline.rs`'s setup): a 125 kg box on a slope
//! at tan θ = 0.95 μ_ba in rapier at 60 Hz, with plain rapier Coulomb friction (μ_ba on the
//! colliders), EP (c = 1e4 1/m, μ_ba = 0.5, μ_max = 0.55) and Regul (ġ_t0 = 0.01 and
//! 0.001 m/s): displacement along the slope over 10 s after 1 s of settling.

use crate::FigureError;
use crate::scenes::BoxOnGround;
use serde::Serialize;
use stickslip_core::law::{Law, Regularization, Regularized};
use stickslip_core::sliding_curve::Curve;
use stickslip_rapier::{FrictionMaterial, StickSlip};

/// Break-away coefficient.
pub const MU_BA: f64 = 0.5;
/// Sliding level.
pub const MU_MAX: f64 = 0.55;
/// EP stiffness (1/m).
pub const C: f64 = 1e4;
/// Load ratio tan θ / μ_ba.
pub const RATIO: f64 = 0.95;
/// Steps per second.
pub const RATE: f64 = 60.0;

/// Displacement over time for one friction model.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Creep {
    /// Model.
    pub label: String,
    /// ġ_t0 for Regul.
    pub v_reg: Option<f64>,
    /// Times since the end of settling (s).
    pub t: Vec<f64>,
    /// Displacement along the slope (m).
    pub x: Vec<f64>,
}

impl Creep {
    /// Displacement at the end (m).
    pub fn final_x(&self) -> f64 {
        self.x.last().copied().unwrap_or(f64::NAN)
    }
    /// Largest |x| (m).
    pub fn max_abs_x(&self) -> f64 {
        self.x.iter().fold(0.0, |m, x| m.max(x.abs()))
    }
}

fn run(label: &str, law: Option<Law>, seconds: f64) -> Creep {
    let theta = (RATIO * MU_BA).atan();
    let mut scene = BoxOnGround {
        incline: theta,
        ..BoxOnGround::default()
    }
    .build();
    let v_reg = match &law {
        Some(Law::Regularized(r)) => Some(r.v_reg()),
        _ => None,
    };
    let mu = if law.is_none() { MU_BA as f32 } else { 0.0 };
    for (_, c) in scene.world.colliders.iter_mut() {
        c.set_friction(mu);
    }
    let mut modifier = law.map(|l| {
        let mut m = StickSlip::new(FrictionMaterial::new(l));
        m.attach(&mut scene.world.colliders, scene.ground, None);
        m.attach(&mut scene.world.colliders, scene.box_collider, None);
        m
    });
    let mut step = |scene: &mut crate::scenes::BoxScene| match modifier.as_mut() {
        Some(m) => m.step(&mut scene.world),
        None => scene.world.step(),
    };
    for _ in 0..RATE as usize {
        step(&mut scene);
    }
    let x0 = scene.x();
    let steps = (seconds * RATE).round() as usize;
    let (mut t, mut x) = (Vec::with_capacity(steps), Vec::with_capacity(steps));
    for k in 0..steps {
        step(&mut scene);
        t.push((k + 1) as f64 / RATE);
        x.push(scene.x() - x0);
    }
    Creep {
        label: label.into(),
        v_reg,
        t,
        x,
    }
}

/// Plain rapier, EP and Regul (0.01, 0.001 m/s) over `seconds`.
pub fn compute(seconds: f64) -> Result<Vec<Creep>, FigureError> {
    let flat = Curve::constant(MU_MAX)?;
    let regul = |v| -> Result<Law, FigureError> {
        Ok(Law::Regularized(Regularized::new(
            flat.clone(),
            v,
            Regularization::Linear,
        )?))
    };
    Ok(vec![
        run("rapier Coulomb (no hook)", None, seconds),
        run(
            "EP c = 1e4",
            Some(Law::elasto_plastic(C, MU_BA, MU_MAX, flat.clone())?),
            seconds,
        ),
        run("Regul ġ_t0 = 0.01", Some(regul(0.01)?), seconds),
        run("Regul ġ_t0 = 0.001", Some(regul(0.001)?), seconds),
    ])
}

/// Regul's steady creep speed ġ_t0 tan θ / μ_ve (m/s), `crates/stickslip-fixtures/tests/rapier_incline.rs`'s reference.
pub fn regul_creep_speed(v_reg: f64) -> f64 {
    v_reg * (RATIO * MU_BA) / MU_MAX
}
