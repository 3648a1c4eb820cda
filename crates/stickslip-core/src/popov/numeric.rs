//! Bracketed 1-D root and extremum search shared by the waveform normalization, Ψ_w(β) and the
//! static-friction solver; the Gauss–Legendre rule and the event-scan grid shared by Ψ_w(β) and
//! the compliant contact's periodic orbit.

use gauss_quad::GaussLegendre;
use roots::{Convergency, find_root_brent};
use std::num::NonZeroUsize;
use std::sync::OnceLock;

/// Order of the Gauss–Legendre rule of the period averages (exact for polynomials to degree 31
/// on each panel).
const QUAD_ORDER: NonZeroUsize = NonZeroUsize::new(16).unwrap();

/// The shared 16-point Gauss–Legendre rule.
pub(crate) fn quadrature() -> &'static GaussLegendre {
    static RULE: OnceLock<GaussLegendre> = OnceLock::new();
    RULE.get_or_init(|| GaussLegendre::new(QUAD_ORDER))
}

/// Points in (from, to], about 1/`per_unit` apart, ending exactly at `to` (the scan for sign
/// changes between events).
pub(crate) fn scan_grid(from: f64, to: f64, per_unit: f64) -> impl Iterator<Item = f64> {
    let n = if to > from {
        ((to - from) * per_unit).ceil().max(1.0) as usize
    } else {
        0
    };
    (1..=n).map(move |i| {
        if i == n {
            to
        } else {
            from + (to - from) * i as f64 / n as f64
        }
    })
}

/// Brent stopping rule: converge on x only (the y scale differs per caller), never give up
/// early; the bisection fallback below covers the rare non-convergence.
struct XTolerance;

impl Convergency<f64> for XTolerance {
    fn is_root_found(&mut self, y: f64) -> bool {
        y == 0.0
    }
    fn is_converged(&mut self, x1: f64, x2: f64) -> bool {
        (x1 - x2).abs() <= 4.0 * f64::EPSILON * x1.abs().max(x2.abs()).max(1e-3)
    }
    fn is_iteration_limit_reached(&mut self, iter: usize) -> bool {
        iter >= 200
    }
}

/// A root of `f` in `[lo, hi]`, where `f(lo)` and `f(hi)` must not have the same strict sign.
/// Always returns a point inside the bracket.
pub(crate) fn bracketed_root(mut f: impl FnMut(f64) -> f64, lo: f64, hi: f64) -> f64 {
    let (lo, hi) = if lo <= hi { (lo, hi) } else { (hi, lo) };
    match find_root_brent(lo, hi, &mut f, &mut XTolerance) {
        Ok(x) if x.is_finite() => x.clamp(lo, hi),
        _ => bisect(f, lo, hi),
    }
}

fn bisect(mut f: impl FnMut(f64) -> f64, mut lo: f64, mut hi: f64) -> f64 {
    let positive_at_lo = f(lo) > 0.0;
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if (f(mid) > 0.0) == positive_at_lo {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// Golden-section search for the minimum of `f` on `[lo, hi]`; returns `(x, f(x))`, never worse
/// than the better endpoint (the function need not be unimodal, the result is then local).
pub fn golden_min(mut f: impl FnMut(f64) -> f64, lo: f64, hi: f64) -> (f64, f64) {
    const INV_PHI: f64 = 0.618_033_988_749_894_8;
    let (mut a, mut b) = (lo, hi);
    let mut c = b - INV_PHI * (b - a);
    let mut d = a + INV_PHI * (b - a);
    let (mut fc, mut fd) = (f(c), f(d));
    // 80 shrinks by 0.618 take any bracket below f64 resolution.
    for _ in 0..80 {
        if fc < fd {
            b = d;
            d = c;
            fd = fc;
            c = b - INV_PHI * (b - a);
            fc = f(c);
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + INV_PHI * (b - a);
            fd = f(d);
        }
    }
    let mut best = if fc < fd { (c, fc) } else { (d, fd) };
    for x in [lo, hi] {
        let fx = f(x);
        if fx < best.1 {
            best = (x, fx);
        }
    }
    best
}

/// Global minimum of a 1-periodic function sampled on `n` equidistant phases, refined by golden
/// section around the `refine` lowest local minima of the samples. Returns `(phase, value)`.
pub fn periodic_min(mut f: impl FnMut(f64) -> f64, n: usize, refine: usize) -> (f64, f64) {
    let h = 1.0 / n as f64;
    let samples: Vec<f64> = (0..n).map(|i| f(i as f64 * h)).collect();
    let mut minima: Vec<usize> = (0..n)
        .filter(|&i| {
            let (l, r) = (samples[(i + n - 1) % n], samples[(i + 1) % n]);
            samples[i] <= l && samples[i] <= r
        })
        .collect();
    minima.sort_by(|&i, &j| samples[i].total_cmp(&samples[j]));
    minima.truncate(refine.max(1));
    let mut best = (0.0, f64::INFINITY);
    for (i, &v) in samples.iter().enumerate() {
        if v < best.1 {
            best = (i as f64 * h, v);
        }
    }
    for i in minima {
        let centre = i as f64 * h;
        let (x, v) = golden_min(|x| f(x.rem_euclid(1.0)), centre - h, centre + h);
        if v < best.1 {
            best = (x.rem_euclid(1.0), v);
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn root_of_cosine() {
        let x = bracketed_root(f64::cos, 1.0, 2.0);
        assert!((x - std::f64::consts::FRAC_PI_2).abs() < 1e-14);
    }

    #[test]
    fn root_at_step_converges_to_the_step() {
        let x = bracketed_root(|x| if x < 0.3 { 1.0 } else { -1.0 }, 0.0, 1.0);
        assert!((x - 0.3).abs() < 1e-12);
    }

    #[test]
    fn periodic_min_of_shifted_sine() {
        let (x, v) = periodic_min(|x| (2.0 * std::f64::consts::PI * (x - 0.123)).sin(), 64, 2);
        assert!((v + 1.0).abs() < 1e-14);
        assert!((x - (0.75 + 0.123)).abs() < 1e-6);
    }
}
