//! Ψ_w(β), the dimensionless friction reduction under normal oscillation (seed Eq. 25, 30,
//! 31), computed numerically for any waveform, and the seed's closed forms (Eq. 34–38).
//!
//! The numeric Ψ walks the phase axis as the quasi-static spring does: in slip the spring
//! force follows w; a stick event starts where w rises faster than the stick line (w′ crosses
//! β upwards, a kink or a drop is followed by w′ > β, or w jumps up), and ends at the first
//! φ2 with β(φ2 − φ1) = w(φ2) − w(φ1) (Eq. 25) or at a downward jump that undercuts the line.
//! Each event contributes Eq. 31, integrated by Gauss–Legendre between breakpoints.

use super::numeric::bracketed_root;
use crate::error::{ParamError, in_range, positive};
use crate::waveform::{Breakpoint, Waveform};

/// Sign-scan resolution per period; features of w′ narrower than this may be missed, which
/// costs O(width³) in Ψ (only near β_c of smooth waveforms).
const SCAN_PER_PERIOD: f64 = 512.0;
/// Longest quadrature panel (phase units); 16 nodes on 1/16 period integrate sin to 1e-16.
const QUAD_PANEL: f64 = 1.0 / 16.0;
/// Probe distance (fraction of a piece) for the left derivative at a piece's end.
const LEFT_PROBE: f64 = 1e-9;

/// One stick phase of the periodic steady state.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StickEvent {
    /// Stick onset φ1 in [0, 1).
    pub onset: f64,
    /// Stick end φ2 > φ1 (may exceed 1: the event wraps into the next period).
    pub release: f64,
    /// Contribution of this event to Ψ_w(β) (Eq. 31).
    pub psi: f64,
}

/// Ψ_w(β) of Eq. 31, summed over all stick events of a period.
///
/// Ψ(0) = 1 (by normalization), Ψ(β) = 0 for β ≥ β_c. Accurate to ~1e-12 except within
/// ~1e-4 of β_c for smooth waveforms (stick shorter than the scan grid, Ψ below ~1e-8 there).
pub fn psi(waveform: &Waveform, beta: f64) -> Result<f64, ParamError> {
    in_range("beta", beta, 0.0, MAX_BETA)?;
    if beta == 0.0 {
        // The stick line is flat: f ≡ −1, so Ψ = ∫(w + 1) = 1 exactly.
        return Ok(1.0);
    }
    let sum: f64 = events(waveform, beta).iter().map(|e| e.psi).sum();
    // Ψ ≥ 0: a sum of rounding-level negatives (β at or past β_c) is zero, not −0.
    Ok(if sum > 0.0 { sum } else { 0.0 })
}

/// The dimensionless speed β at which Ψ_w(β) has fallen to `target` (0 < target ≤ 1), searched
/// upwards from β = 0 (the first crossing). It is where the mean sliding friction under normal
/// vibration, μ0 (1 − α Ψ_w(β)) (Eq. 33), equals a given level: a part on a slope tan θ
/// between μ0 (1 − α) and μ0 flows down it at v = β μ0 α f / c (f the frequency, c the
/// contact's stiffness per unit normal force) with Ψ_w(β) = (1 − tan θ/μ0)/α. A target Ψ never
/// falls to within [`MAX_BETA`] (a left sawtooth's 2/(2 + β) far below 1e-9) is
/// [`ParamError::NoConvergence`].
pub fn beta_at_psi(waveform: &Waveform, target: f64) -> Result<f64, ParamError> {
    positive("target", target)?;
    in_range("target", target, 0.0, 1.0)?;
    let f = |beta: f64| psi(waveform, beta).unwrap_or(0.0) - target;
    // Doubling brackets: the first where Ψ has fallen to the target.
    let (mut lo, mut hi) = (0.0, 1.0);
    let mut doublings = 0;
    while f(hi) > 0.0 {
        if hi >= MAX_BETA {
            return Err(ParamError::NoConvergence {
                name: "beta_at_psi doublings",
                limit: doublings,
            });
        }
        (lo, hi) = (hi, (2.0 * hi).min(MAX_BETA));
        doublings += 1;
    }
    Ok(bracketed_root(f, lo, hi))
}

/// The largest dimensionless velocity β [`psi`] accepts (far past every waveform's β_c, where
/// Ψ = 0).
pub const MAX_BETA: f64 = 1e9;

/// The stick events of one period of the steady state, ordered by onset (β > 0).
pub fn stick_events(waveform: &Waveform, beta: f64) -> Result<Vec<StickEvent>, ParamError> {
    positive("beta", beta)?;
    in_range("beta", beta, 0.0, MAX_BETA)?;
    Ok(events(waveform, beta))
}

/// Closed forms of Ψ_w(β): Eq. 34 (right sawtooth), 35 (left sawtooth), 36 (square) and,
/// derived the same way (not in the seed), the rectangular impulse train of width δ:
/// Ψ = 1 − βδ²/2 for β ≤ 1/δ², 1/(2βδ²) above; δ = ½ is Eq. 36, δ → 0 is Eq. 39.
///
/// `None` for waveforms without a closed form and for negative or NaN β.
pub fn psi_closed_form(waveform: &Waveform, beta: f64) -> Option<f64> {
    if beta.is_nan() || beta < 0.0 {
        return None;
    }
    match waveform {
        Waveform::SawtoothRight => Some((1.0 - beta / 2.0).max(0.0)),
        Waveform::SawtoothLeft => Some(2.0 / (2.0 + beta)),
        Waveform::Square => Some(if beta < 4.0 {
            1.0 - beta / 8.0
        } else {
            2.0 / beta
        }),
        Waveform::Impulse(p) => {
            let d2 = p.width() * p.width();
            Some(if beta * d2 <= 1.0 {
                1.0 - beta * d2 / 2.0
            } else {
                1.0 / (2.0 * beta * d2)
            })
        }
        _ => None,
    }
}

/// The seed's first empirical fit for the sine (Eq. 37):
/// ¾(1 − β/β_c)² + ¼(1 − β/β_c)⁴ with β_c = 2π; 0 for β ≥ β_c.
pub fn psi_sine_eq37(beta: f64) -> f64 {
    let r = (1.0 - beta / std::f64::consts::TAU).max(0.0);
    0.75 * r.powi(2) + 0.25 * r.powi(4)
}

/// The seed's second empirical fit for the sine (Eq. 38): (1 − β/β_c)^2.4 with β_c = 2π.
pub fn psi_sine_eq38(beta: f64) -> f64 {
    (1.0 - beta / std::f64::consts::TAU).max(0.0).powf(2.4)
}

fn events(waveform: &Waveform, beta: f64) -> Vec<StickEvent> {
    if beta >= waveform.beta_c() {
        return Vec::new();
    }
    Walker::new(waveform, beta).run()
}

/// Points in (from, to], about 1/SCAN_PER_PERIOD apart, ending exactly at `to`.
fn grid(from: f64, to: f64) -> impl Iterator<Item = f64> {
    super::numeric::scan_grid(from, to, SCAN_PER_PERIOD)
}

/// A smooth stretch of w between consecutive breakpoints, in period `k` (global index j =
/// k·m + i). Phases inside are local, in [0, 1], so breakpoints are hit exactly.
struct Piece {
    k: usize,
    a: f64,
    b: f64,
    /// w(a+).
    w_a: f64,
    /// w(b−).
    w_b: f64,
    /// w(b+) − w(b−).
    jump_b: f64,
}

/// A stick event in walk coordinates: onset (piece j1, local x1) and the stick line's level.
#[derive(Clone, Copy)]
struct Onset {
    j1: usize,
    x1: f64,
    level: f64,
}

struct Walker<'a> {
    w: &'a Waveform,
    beta: f64,
    /// Breakpoints with one at phase 0 (added if smooth there), so pieces tile each period.
    bps: Vec<Breakpoint>,
}

impl<'a> Walker<'a> {
    fn new(w: &'a Waveform, beta: f64) -> Self {
        let mut bps = w.breakpoints();
        if bps.first().is_none_or(|b| b.phase > 0.0) {
            let v = w.value(0.0);
            bps.insert(
                0,
                Breakpoint {
                    phase: 0.0,
                    before: v,
                    after: v,
                },
            );
        }
        Self { w, beta, bps }
    }

    fn piece(&self, j: usize) -> Piece {
        let m = self.bps.len();
        let i = j % m;
        let next = &self.bps[(i + 1) % m];
        Piece {
            k: j / m,
            a: self.bps[i].phase,
            b: if i + 1 < m { next.phase } else { 1.0 },
            w_a: self.bps[i].after,
            w_b: next.before,
            jump_b: next.jump(),
        }
    }

    /// w on the closed piece, with the one-sided limits at its ends.
    fn w_on(&self, p: &Piece, x: f64) -> f64 {
        if x <= p.a {
            p.w_a
        } else if x >= p.b {
            p.w_b
        } else {
            self.w.value(x)
        }
    }

    /// w′ − β: positive where w outruns the stick line.
    fn rise(&self, x: f64) -> f64 {
        self.w.slope(x) - self.beta
    }

    /// w minus the stick line of `on`, at local `x` in piece `p`.
    fn gap(&self, p: &Piece, x: f64, on: &Onset, m: usize) -> f64 {
        let periods = p.k as f64 - (on.j1 / m) as f64;
        self.w_on(p, x) - on.level - self.beta * (periods + (x - on.x1))
    }

    /// Walks two periods from an assumed slip state at φ = 0 and keeps the events starting in
    /// the second: the spring force is pinned to w at the global minimum of w (it can neither
    /// exceed w nor drop below −1), so the walk is exact after the first period.
    fn run(&self) -> Vec<StickEvent> {
        let m = self.bps.len();
        let mut out = Vec::new();
        let (mut j, mut x) = (0, 0.0);
        while j < 2 * m {
            let p = self.piece(j);
            if let Some((x1, rising_at)) = self.slip_until_onset(&p, x) {
                let on = Onset {
                    j1: j,
                    x1,
                    level: self.w_on(&p, x1),
                };
                let (peak, past_peak) = self.end_of_rise(&p, rising_at);
                if self.gap(&p, peak, &on, m) > 0.0 {
                    (j, x) = self.release(&on, j, peak);
                    self.record(&mut out, &on, j, x);
                } else {
                    // Stick too short to resolve: skip past it by a whole scan step.
                    x = past_peak;
                }
            } else if p.jump_b > 0.0 {
                let q = self.piece(j + 1);
                let on = Onset {
                    j1: j + 1,
                    x1: q.a,
                    level: p.w_b,
                };
                (j, x) = self.release(&on, j + 1, q.a);
                self.record(&mut out, &on, j, x);
            } else {
                j += 1;
                x = self.piece(j).a;
            }
        }
        out
    }

    /// In slip from `x`: the first onset inside the piece, as (φ1, a point just after it where
    /// w′ > β), or `None` if the slip lasts to the piece's end.
    fn slip_until_onset(&self, p: &Piece, x: f64) -> Option<(f64, f64)> {
        if x >= p.b {
            return None;
        }
        if self.rise(x) > 0.0 {
            // Kink, drop, or tangency: the stick starts right here.
            return Some((x, x));
        }
        let end = p.b - LEFT_PROBE * (p.b - p.a);
        let mut prev = x;
        for t in grid(x, end) {
            if self.rise(t) > 0.0 {
                return Some((bracketed_root(|s| self.rise(s), prev, t), t));
            }
            prev = t;
        }
        None
    }

    /// From a point where w′ > β: where w′ falls back to β (the gap w − line peaks there) and
    /// the next scan point past it; (b, b) if w′ > β to the piece's end.
    fn end_of_rise(&self, p: &Piece, from: f64) -> (f64, f64) {
        let end = p.b - LEFT_PROBE * (p.b - p.a);
        let mut prev = from;
        for t in grid(from, end) {
            if self.rise(t) <= 0.0 {
                let r = bracketed_root(|s| self.rise(s), prev, t);
                return (if r > from { r } else { t }, t);
            }
            prev = t;
        }
        (p.b, p.b)
    }

    /// From (j, x) inside the stick of `on`, with a positive gap there: the stick's end as
    /// (piece, local phase) — the first zero of the gap (Eq. 25) or a downward jump below it.
    fn release(&self, on: &Onset, mut j: usize, mut x: f64) -> (usize, f64) {
        let m = self.bps.len();
        loop {
            let p = self.piece(j);
            let gap = |s: f64| self.gap(&p, s, on, m);
            let mut prev = x;
            for t in grid(x, p.b) {
                if gap(t) <= 0.0 {
                    return (j, bracketed_root(gap, prev, t));
                }
                // The gap can dip below zero between scan points when the line grazes w (small
                // β); its dips are where w′ rises through β, so look there too.
                let probe = t.min(p.b - LEFT_PROBE * (p.b - p.a));
                if probe > prev && self.rise(prev) < 0.0 && self.rise(probe) > 0.0 {
                    let dip = bracketed_root(|s| self.rise(s), prev, probe);
                    if gap(dip) <= 0.0 {
                        return (j, bracketed_root(gap, prev, dip));
                    }
                }
                prev = t;
            }
            if self.gap(&p, p.b, on, m) + p.jump_b <= 0.0 {
                return (j, p.b);
            }
            j += 1;
            x = self.piece(j).a;
            // A stick lasts less than a period for β > 0 (w is periodic, the line rises):
            // this only bounds the loop against pathological round-off.
            if j > on.j1 + 2 * m {
                return (j, x);
            }
        }
    }

    /// Keeps events starting in the second period, integrating Eq. 31 piece by piece.
    fn record(&self, out: &mut Vec<StickEvent>, on: &Onset, j2: usize, x2: f64) {
        let m = self.bps.len();
        if !(m..2 * m).contains(&on.j1) {
            return;
        }
        let mut psi = 0.0;
        for j in on.j1..=j2 {
            let p = self.piece(j);
            let lo = if j == on.j1 { on.x1 } else { p.a };
            let hi = if j == j2 { x2 } else { p.b };
            if hi <= lo {
                continue;
            }
            let panels = ((hi - lo) / QUAD_PANEL).ceil().max(1.0) as usize;
            let width = (hi - lo) / panels as f64;
            for i in 0..panels {
                let a = lo + width * i as f64;
                let b = if i + 1 == panels { hi } else { a + width };
                psi += super::numeric::quadrature().integrate(a, b, |s| self.gap(&p, s, on, m));
            }
        }
        let duration = (j2 / m - on.j1 / m) as f64 + (x2 - on.x1);
        out.push(StickEvent {
            onset: on.x1,
            release: on.x1 + duration,
            psi,
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::TAU;

    #[test]
    fn validates_beta() {
        assert!(psi(&Waveform::Sine, -1.0).is_err());
        assert!(psi(&Waveform::Sine, f64::NAN).is_err());
        assert!(stick_events(&Waveform::Sine, 0.0).is_err());
        assert_eq!(psi(&Waveform::Sine, 0.0), Ok(1.0));
        assert_eq!(psi(&Waveform::Sine, TAU), Ok(0.0));
        assert_eq!(psi_closed_form(&Waveform::Sine, 1.0), None);
        assert_eq!(psi_closed_form(&Waveform::Square, -1.0), None);
    }

    #[test]
    fn square_closed_form_example() {
        // One stick per period, from the upward jump at φ = 0.
        let ev = stick_events(&Waveform::Square, 2.0).unwrap();
        assert_eq!(ev.len(), 1);
        assert!(ev[0].onset.abs() < 1e-15 && (ev[0].release - 0.5).abs() < 1e-15);
        assert!((ev[0].psi - 0.75).abs() < 1e-14);
        let ev = stick_events(&Waveform::Square, 8.0).unwrap();
        assert!((ev[0].release - 0.25).abs() < 1e-14);
    }

    #[test]
    fn sine_onset_solves_eq_19_and_release_eq_25() {
        let beta = 3.0;
        let ev = stick_events(&Waveform::Sine, beta).unwrap();
        assert_eq!(ev.len(), 1);
        let (p1, p2) = (ev[0].onset, ev[0].release);
        assert!((Waveform::Sine.slope(p1) - beta).abs() < 1e-9);
        assert!(
            Waveform::Sine.slope(p1 + 1e-3) > beta,
            "w′ rises through β at onset"
        );
        let eq25 = beta * (p2 - p1) - (Waveform::Sine.value(p2) - Waveform::Sine.value(p1));
        assert!(eq25.abs() < 1e-12);
    }

    #[test]
    fn closed_forms_are_continuous_at_their_kinks() {
        let sq = |b| psi_closed_form(&Waveform::Square, b).unwrap();
        assert!((sq(4.0 - 1e-12) - sq(4.0)).abs() < 1e-9);
        let imp = Waveform::impulse(0.1).unwrap();
        let i = |b| psi_closed_form(&imp, b).unwrap();
        assert!((i(100.0 - 1e-9) - i(100.0 + 1e-9)).abs() < 1e-9);
        assert!((psi_sine_eq37(0.0) - 1.0).abs() < 1e-15 && psi_sine_eq38(TAU) == 0.0);
    }

    #[test]
    fn beta_at_psi_inverts_psi() {
        // Closed forms: right sawtooth Ψ = 1 − β/2, left sawtooth Ψ = 2/(2 + β).
        for t in [0.05, 0.2, 0.5, 0.9, 1.0] {
            let right = beta_at_psi(&Waveform::SawtoothRight, t).unwrap();
            assert!((right - 2.0 * (1.0 - t)).abs() < 1e-9, "{t}: {right}");
            let left = beta_at_psi(&Waveform::SawtoothLeft, t).unwrap();
            assert!(
                (left - (2.0 / t - 2.0)).abs() < 1e-9 * (1.0 + left),
                "{t}: {left}"
            );
            for w in [Waveform::Sine, Waveform::Square] {
                let beta = beta_at_psi(&w, t).unwrap();
                assert!(
                    (psi(&w, beta).unwrap() - t).abs() < 1e-9,
                    "{w:?} {t}: {beta}"
                );
            }
        }
        for bad in [0.0, -0.1, 1.5, f64::NAN] {
            assert!(beta_at_psi(&Waveform::Sine, bad).is_err(), "{bad}");
        }
        assert!(matches!(
            beta_at_psi(&Waveform::SawtoothLeft, 1e-12),
            Err(ParamError::NoConvergence { .. })
        ));
    }
}
