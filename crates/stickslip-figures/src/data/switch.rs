//! The switching function α(μ) of the seed (Fig. 1 A, Eq. 5–7) and the sliding curves the
//! tests and examples use (Eq. 1), beside Regul's regularized coefficient.

use serde::Serialize;
use stickslip_core::ParamError;
use stickslip_core::law::{Regularization, Regularized};
use stickslip_core::sliding_curve::{Curve, SlidingCurve, StribeckDecay};

/// A named curve y(x).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Curve1 {
    /// Name for the legend.
    pub label: String,
    /// Abscissae.
    pub x: Vec<f64>,
    /// Values.
    pub y: Vec<f64>,
}

/// α(|μ|) for the seed's thresholds μ_ba = 0.3, μ_max = 0.32 (Example 1) and for a wider band
/// (0.3, 0.4) that shows the sine blend, over |μ| ∈ [0.25, 0.45] with `n` points.
pub fn switch_function(n: usize) -> Vec<Curve1> {
    let n = n.max(2);
    let xs: Vec<f64> = (0..n)
        .map(|i| 0.25 + 0.2 * i as f64 / (n - 1) as f64)
        .collect();
    [(0.3, 0.32), (0.3, 0.4)]
        .into_iter()
        .map(|(ba, max)| Curve1 {
            label: format!("μ_ba = {ba}, μ_max = {max}"),
            x: xs.clone(),
            y: xs
                .iter()
                .map(|&m| stickslip_core::switch::alpha(m, ba, max))
                .collect(),
        })
        .collect()
}

/// The sliding curves μ_ve(v) in use (Example 1's constant 0.32, the incline's 0.55, a
/// Gaussian and an exponential Stribeck curve with a viscous term) and Regul's μ(ġ) for
/// ġ_t0 = 0.01 m/s (linear and tanh ramps) on the constant 0.32, over v ∈ [0, 0.05] m/s.
pub fn sliding_curves(n: usize) -> Result<Vec<Curve1>, ParamError> {
    let n = n.max(2);
    let vs: Vec<f64> = (0..n).map(|i| 0.05 * i as f64 / (n - 1) as f64).collect();
    type Named = (String, Box<dyn Fn(f64) -> f64>);
    let curves: Vec<Named> = vec![
        ("constant 0.32 (Example 1)".into(), {
            let c = Curve::constant(0.32)?;
            Box::new(move |v| c.mu(v))
        }),
        ("constant 0.55 (incline)".into(), {
            let c = Curve::constant(0.55)?;
            Box::new(move |v| c.mu(v))
        }),
        ("Stribeck Gauss 0.6→0.4, v_s 0.01".into(), {
            let c = Curve::stribeck(0.6, 0.4, 0.01, StribeckDecay::Gaussian, 0.0)?;
            Box::new(move |v| c.mu(v))
        }),
        ("Stribeck exp 0.5→0.3, v_s 0.005, +2v".into(), {
            let c = Curve::stribeck(0.5, 0.3, 0.005, StribeckDecay::Exponential, 2.0)?;
            Box::new(move |v| c.mu(v))
        }),
        ("Regul linear, ġ_t0 0.01".into(), {
            let r = Regularized::new(Curve::constant(0.32)?, 0.01, Regularization::Linear)?;
            Box::new(move |v| r.coefficient(v))
        }),
        ("Regul tanh, ġ_t0 0.01".into(), {
            let r = Regularized::new(Curve::constant(0.32)?, 0.01, Regularization::Tanh)?;
            Box::new(move |v| r.coefficient(v))
        }),
    ];
    Ok(curves
        .into_iter()
        .map(|(label, f)| Curve1 {
            label,
            x: vs.clone(),
            y: vs.iter().map(|&v| f(v)).collect(),
        })
        .collect())
}
