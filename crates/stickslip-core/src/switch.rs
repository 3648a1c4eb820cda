//! The switching function α(μ) of the seed's elasto-plastic law (Eq. 5–7).
//!
//! α compares the magnitude of the friction state with the thresholds μ_ba and μ_max:
//! 0 below μ_ba (sticking, Eq. 6), 1 above μ_max (sliding, Eq. 5; the paper's Eq. 5 prints
//! "|μ| > μ_ba", which overlaps Eq. 7, the sine blend makes clear the bound is μ_max), and a
//! half sine wave in between (stick-slip, Eq. 7), so α and its slope are continuous at both
//! ends. Eq. 7 is written for μ ≥ 0; the law is odd in μ, so we evaluate it at |μ|.

use std::f64::consts::PI;

/// The friction regime the switch reports for a state magnitude.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Regime {
    /// α = 0: the contact behaves as an elastic spring (Eq. 2 / Eq. 6).
    Sticking,
    /// 0 < α < 1: the spring yields, stick-slip transition (Eq. 3 / Eq. 7).
    StickSlip,
    /// α = 1: (oscillatory) sliding on the sliding curve (Eq. 1 / Eq. 5).
    Sliding,
}

impl Regime {
    /// Kebab-case name used in tables and JSON.
    pub fn name(self) -> &'static str {
        match self {
            Regime::Sticking => "sticking",
            Regime::StickSlip => "stick-slip",
            Regime::Sliding => "sliding",
        }
    }

    /// The most slippery of `regimes` (sliding over stick-slip over sticking), or `None` if
    /// there are none: a body's regime from its contacts'.
    pub fn most_slippery(regimes: impl IntoIterator<Item = Regime>) -> Option<Regime> {
        regimes.into_iter().max_by_key(|r| r.code())
    }

    /// The regime's colour in every viewer (bevy gizmos and materials, rerun), as sRGB bytes:
    /// green sticking, orange stick-slip, red sliding, bright on a dark background.
    pub fn srgb(self) -> [u8; 3] {
        match self {
            Regime::Sticking => [51, 217, 77],
            Regime::StickSlip => [255, 153, 26],
            Regime::Sliding => [242, 51, 51],
        }
    }
}

/// α(|μ|) for thresholds `mu_ba <= mu_max` (Eq. 5–7). With `mu_ba == mu_max` it is a step.
#[inline]
pub fn alpha(mu_abs: f64, mu_ba: f64, mu_max: f64) -> f64 {
    if mu_abs < mu_ba {
        0.0
    } else if mu_abs >= mu_max {
        1.0
    } else {
        let x = (mu_abs - 0.5 * (mu_max + mu_ba)) / (mu_max - mu_ba);
        0.5 * (PI * x).sin() + 0.5
    }
}

/// The regime for a state magnitude.
#[inline]
pub fn regime(mu_abs: f64, mu_ba: f64, mu_max: f64) -> Regime {
    if mu_abs < mu_ba {
        Regime::Sticking
    } else if mu_abs >= mu_max {
        Regime::Sliding
    } else {
        Regime::StickSlip
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_most_slippery_regime_ranks_sliding_over_stick_slip_over_sticking() {
        use Regime::*;
        assert_eq!(Regime::most_slippery([]), None);
        assert_eq!(Regime::most_slippery([Sticking, Sticking]), Some(Sticking));
        assert_eq!(
            Regime::most_slippery([Sticking, StickSlip, Sticking]),
            Some(StickSlip)
        );
        assert_eq!(
            Regime::most_slippery([StickSlip, Sliding, Sticking]),
            Some(Sliding)
        );
    }

    #[test]
    fn alpha_matches_eq_5_to_7() {
        let (ba, max) = (0.3, 0.4);
        assert_eq!(alpha(0.0, ba, max), 0.0);
        assert_eq!(alpha(0.299, ba, max), 0.0);
        assert!((alpha(0.3, ba, max) - 0.0).abs() < 1e-12);
        assert!((alpha(0.35, ba, max) - 0.5).abs() < 1e-12);
        assert!((alpha(0.4, ba, max) - 1.0).abs() < 1e-12);
        assert_eq!(alpha(1.0, ba, max), 1.0);
        // Quarter point from Eq. 7 directly: 0.5 sin(-π/4) + 0.5.
        let q = 0.5 * (-PI / 4.0).sin() + 0.5;
        assert!((alpha(0.325, ba, max) - q).abs() < 1e-12);
        // Monotone.
        let mut last = 0.0;
        for i in 0..=100 {
            let a = alpha(0.25 + 0.2 * i as f64 / 100.0, ba, max);
            assert!(a >= last);
            last = a;
        }
    }

    #[test]
    fn sharp_limit_is_a_step() {
        assert_eq!(alpha(0.4999, 0.5, 0.5), 0.0);
        assert_eq!(alpha(0.5, 0.5, 0.5), 1.0);
    }
}
