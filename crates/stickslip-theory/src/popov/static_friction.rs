//! Static friction under oscillation (seed Section 2): the closed forms for a single
//! direction (Eq. 4, 6, 8) and a numeric solver for superimposed oscillations (Eq. 9).
//!
//! Amplitudes are force ratios A/F_z. The closed forms assume the waveform spans [−1, 1]
//! (sine, square, sawteeth); the numeric solver works for any waveform.

use stickslip_core::error::{MAX_COEFFICIENT, ParamError, in_range, positive};
use stickslip_core::popov::numeric::periodic_min;
use stickslip_core::popov::{Excitation, Oscillation};

/// The largest amplitude ratio A/F_z the closed forms accept (far past lift-off at 1).
pub const MAX_AMPLITUDE_RATIO: f64 = 1e3;

/// Samples per period for the Eq. 9 solver; each sampled minimum is then refined.
const SAMPLES: usize = 8192;
/// Local minima refined by golden section.
const REFINED_MINIMA: usize = 8;
/// Offset (phase) at which a jump's left limit is read.
const LEFT_LIMIT: f64 = 1e-12;

/// μ_s,z = μ0 (1 − A_z/F_z)⁺ under normal oscillation (Eq. 4).
pub fn mu_s_normal(mu0: f64, amplitude_ratio: f64) -> Result<f64, ParamError> {
    in_range("mu0", mu0, 0.0, MAX_COEFFICIENT)?;
    in_range("amplitude ratio", amplitude_ratio, 0.0, MAX_AMPLITUDE_RATIO)?;
    Ok(mu0 * (1.0 - amplitude_ratio).max(0.0))
}

/// μ_s,x = (μ0 − A_x/F_z)⁺ under tangential oscillation (Eq. 6).
pub fn mu_s_tangential(mu0: f64, amplitude_ratio: f64) -> Result<f64, ParamError> {
    in_range("mu0", mu0, 0.0, MAX_COEFFICIENT)?;
    in_range("amplitude ratio", amplitude_ratio, 0.0, MAX_AMPLITUDE_RATIO)?;
    Ok((mu0 - amplitude_ratio).max(0.0))
}

/// μ_s,y = √((μ0² − A_y²/F_z²)⁺) under transverse oscillation (Eq. 8).
pub fn mu_s_transverse(mu0: f64, amplitude_ratio: f64) -> Result<f64, ParamError> {
    in_range("mu0", mu0, 0.0, MAX_COEFFICIENT)?;
    in_range("amplitude ratio", amplitude_ratio, 0.0, MAX_AMPLITUDE_RATIO)?;
    Ok((mu0 * mu0 - amplitude_ratio * amplitude_ratio)
        .max(0.0)
        .sqrt())
}

/// Which constant tangential forces keep the contact stuck at all times (Eq. 9).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum StaticFriction {
    /// Every F_x/F_z strictly inside (lower, upper) sticks.
    Stick {
        /// Most negative admissible F_x/F_z.
        lower: f64,
        /// Largest admissible F_x/F_z. It can be negative ("negative static friction", seed
        /// Section 2.1): the oscillation alone drives the contact forward and a backward force
        /// is needed to hold it, the principle of frictional drives.
        upper: f64,
    },
    /// No constant force holds the contact: it slides in place at some instant (Eq. 9 cannot
    /// hold strictly, e.g. when contact is lost or A_x ≥ μ0 F_z).
    Slides,
}

impl StaticFriction {
    /// μ_s = F_x,max/F_z: `upper` (negative in the drive case) or 0 when the contact always
    /// slides, the seed's (·)⁺ convention of Eq. 4, 6 and 8.
    pub fn mu_s(&self) -> f64 {
        match *self {
            Self::Stick { upper, .. } => upper,
            Self::Slides => 0.0,
        }
    }
}

/// Solves Eq. 9 with the normal force clipped at zero as in Eq. 3:
/// (F_x + A_x g_x)² + (A_y g_y)² < μ0² ((F_z + A_z g_z)⁺)² at all phases, amplitudes in the
/// [`Excitation`] taken as ratios A/F_z.
///
/// At each phase the admissible F_x/F_z form the interval −a_x g_x ± R with
/// R = √(μ0² n⁺² − a_y² g_y²), n = 1 + a_z g_z; the answer is their intersection, whose ends
/// are extrema over the period found by dense sampling, golden-section refinement and the
/// one-sided limits at every jump.
pub fn static_friction_superimposed(
    mu0: f64,
    excitation: &Excitation,
) -> Result<StaticFriction, ParamError> {
    positive("mu0", mu0)?;
    let [normal, tangential, transverse] = excitation.components();
    let g = |osc: Option<&Oscillation>, x: f64| osc.map_or(0.0, |o| o.at(x));
    let radius2 = |x: f64| {
        let n = (1.0 + g(normal, x)).max(0.0);
        let y = g(transverse, x);
        mu0 * mu0 * n * n - y * y
    };
    let radius = |x: f64| radius2(x).max(0.0).sqrt();

    let probes = jump_probes(excitation);
    let inf = |f: &dyn Fn(f64) -> f64| {
        let (_, sampled) = periodic_min(f, SAMPLES, REFINED_MINIMA);
        probes.iter().map(|&x| f(x)).fold(sampled, f64::min)
    };
    if inf(&radius2) <= 0.0 {
        return Ok(StaticFriction::Slides);
    }
    let upper = inf(&|x| radius(x) - g(tangential, x));
    let lower = -inf(&|x| radius(x) + g(tangential, x));
    Ok(if lower < upper {
        StaticFriction::Stick { lower, upper }
    } else {
        StaticFriction::Slides
    })
}

/// Phases just left of and at every jump of every component, where extrema can hide.
fn jump_probes(excitation: &Excitation) -> Vec<f64> {
    excitation
        .components()
        .into_iter()
        .flatten()
        .flat_map(|o| {
            o.waveform()
                .breakpoints()
                .into_iter()
                .filter(|b| b.jump() != 0.0)
                .flat_map(move |b| {
                    let x = (b.phase - o.phase()).rem_euclid(1.0);
                    [(x - LEFT_LIMIT).rem_euclid(1.0), x]
                })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use stickslip_core::waveform::Waveform;

    fn osc(a: f64, w: Waveform, phase: f64) -> Option<Oscillation> {
        Some(Oscillation::new(a, w, phase).unwrap())
    }

    #[test]
    fn no_oscillation_gives_mu0() {
        let s = static_friction_superimposed(0.4, &Excitation::default()).unwrap();
        assert!((s.mu_s() - 0.4).abs() < 1e-12);
    }

    #[test]
    fn impulse_tangential_oscillation_gives_negative_static_friction() {
        // Peak 9, trough −1: admissible F_x/F_z in (−μ0 + a, μ0 − 9a), negative for a > μ0/9.
        let (mu0, a) = (0.5, 0.08);
        let ex = Excitation {
            tangential: osc(a, Waveform::impulse(0.1).unwrap(), 0.3),
            ..Excitation::default()
        };
        let s = static_friction_superimposed(mu0, &ex).unwrap();
        assert!((s.mu_s() - (mu0 - 9.0 * a)).abs() < 1e-9, "{s:?}");
        assert!(s.mu_s() < 0.0);
        let ex = Excitation::tangential(
            Oscillation::new(0.11, Waveform::impulse(0.1).unwrap(), 0.0).unwrap(),
        );
        assert_eq!(
            static_friction_superimposed(mu0, &ex).unwrap(),
            StaticFriction::Slides
        );
    }

    #[test]
    fn in_phase_tangential_oscillation_can_cancel_normal_one() {
        // F_x + a_x g < μ0 (1 + a_z g) with a_x = μ0 a_z holds for every F_x < μ0.
        let (mu0, az) = (0.5, 0.6);
        let ex = Excitation {
            normal: osc(az, Waveform::Sine, 0.2),
            tangential: osc(mu0 * az, Waveform::Sine, 0.2),
            ..Excitation::default()
        };
        let s = static_friction_superimposed(mu0, &ex).unwrap();
        assert!((s.mu_s() - mu0).abs() < 1e-9, "{s:?}");
    }

    #[test]
    fn contact_loss_means_sliding() {
        let ex = Excitation::normal(Oscillation::new(1.2, Waveform::Square, 0.0).unwrap());
        assert_eq!(
            static_friction_superimposed(0.3, &ex).unwrap(),
            StaticFriction::Slides
        );
        assert_eq!(mu_s_normal(0.3, 1.2), Ok(0.0));
    }
}
