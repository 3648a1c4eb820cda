//! The in-plane slip arcs of the periodic orbit: a small ODE (the force's angle θ and two
//! running integrals) integrated by the Dormand–Prince 5(4) pair with step-size control, up
//! to the first downward crossing of an event function.
//!
//! It is here, not in an ODE crate, because the averaged in-plane vibration tables solve
//! these arcs while an engine runs: a three-state system with one event does not justify an
//! ODE crate in every engine user's build. The tests check it against
//! `differential-equations`' Dormand–Prince (a dev-dependency), which the reference
//! simulators of stickslip-theory use.

use super::numeric::bracketed_root;

/// The Dormand–Prince 5(4) tableau (Dormand & Prince 1980): nodes, stages, the fifth-order
/// weights (first same as last) and the difference to the embedded fourth-order ones.
const C: [f64; 6] = [0.2, 0.3, 0.8, 8.0 / 9.0, 1.0, 1.0];
const A: [[f64; 6]; 6] = [
    [0.2, 0.0, 0.0, 0.0, 0.0, 0.0],
    [3.0 / 40.0, 9.0 / 40.0, 0.0, 0.0, 0.0, 0.0],
    [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0, 0.0, 0.0, 0.0],
    [
        19372.0 / 6561.0,
        -25360.0 / 2187.0,
        64448.0 / 6561.0,
        -212.0 / 729.0,
        0.0,
        0.0,
    ],
    [
        9017.0 / 3168.0,
        -355.0 / 33.0,
        46732.0 / 5247.0,
        49.0 / 176.0,
        -5103.0 / 18656.0,
        0.0,
    ],
    [
        35.0 / 384.0,
        0.0,
        500.0 / 1113.0,
        125.0 / 192.0,
        -2187.0 / 6784.0,
        11.0 / 84.0,
    ],
];
const E: [f64; 7] = [
    71.0 / 57600.0,
    0.0,
    -71.0 / 16695.0,
    71.0 / 1920.0,
    -17253.0 / 339200.0,
    22.0 / 525.0,
    -1.0 / 40.0,
];

/// Accuracy and budget of an arc.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ArcTolerances {
    /// Relative error per step.
    pub rtol: f64,
    /// Absolute error per step.
    pub atol: f64,
    /// Longest step.
    pub h_max: f64,
    /// Steps (accepted or rejected) before giving up.
    pub max_steps: usize,
}

/// Where an arc ended: at the event or at the end of the span.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct ArcEnd {
    /// Independent variable at the end.
    pub x: f64,
    /// State at the end.
    pub y: [f64; 3],
}

type State = [f64; 3];

/// y + h Σ a_j k_j.
fn combine(y: &State, h: f64, a: &[f64], k: &[State]) -> State {
    let mut out = *y;
    for (a, k) in a.iter().zip(k) {
        for (o, k) in out.iter_mut().zip(k) {
            *o += h * a * k;
        }
    }
    out
}

/// One Dormand–Prince step of size `h` from (x, y) with k1 = f(x, y): the fifth-order state,
/// the derivative there (the next k1) and the embedded error estimate.
fn step(f: &impl Fn(f64, &State) -> State, x: f64, y: &State, k1: &State, h: f64) -> [State; 3] {
    let mut k = [*k1; 7];
    for s in 1..6 {
        let ys = combine(y, h, &A[s - 1][..s], &k[..s]);
        k[s] = f(x + C[s - 1] * h, &ys);
    }
    let y1 = combine(y, h, &A[5], &k[..6]);
    k[6] = f(x + h, &y1);
    let err = combine(&[0.0; 3], h, &E, &k);
    [y1, k[6], err]
}

/// The error of a step relative to the tolerances (RMS; ≤ 1 accepts it).
fn error_norm(err: &State, y0: &State, y1: &State, tol: &ArcTolerances) -> f64 {
    let sum: f64 = (0..3)
        .map(|i| {
            let scale = tol.atol + tol.rtol * y0[i].abs().max(y1[i].abs());
            (err[i] / scale).powi(2)
        })
        .sum();
    (sum / 3.0).sqrt()
}

/// Integrates y′ = f(x, y) from (x0, y0) towards x1 ≥ x0, stopping at the first point where
/// `event` crosses from ≥ 0 to < 0 (located to the root inside the step). `None` when the
/// step budget runs out or the step size underflows.
pub(crate) fn integrate_arc(
    f: impl Fn(f64, &State) -> State,
    event: impl Fn(f64, &State) -> f64,
    x0: f64,
    x1: f64,
    y0: State,
    tol: &ArcTolerances,
) -> Option<ArcEnd> {
    let (mut x, mut y) = (x0, y0);
    let mut k1 = f(x, &y);
    let mut g = event(x, &y);
    let mut h = ((x1 - x0) * 1e-3).min(tol.h_max);
    for _ in 0..tol.max_steps {
        if x >= x1 {
            return Some(ArcEnd { x: x1, y });
        }
        let last = x + h >= x1;
        let h_try = if last { x1 - x } else { h };
        let [y_next, k_next, err] = step(&f, x, &y, &k1, h_try);
        let e = error_norm(&err, &y, &y_next, tol);
        if !e.is_finite() {
            h = h_try * 0.2;
            if !(h > f64::EPSILON * x.abs().max(1.0)) {
                return None;
            }
            continue;
        }
        if e <= 1.0 {
            let x_next = if last { x1 } else { x + h_try };
            let g_next = event(x_next, &y_next);
            if g >= 0.0 && g_next < 0.0 {
                // The event inside the step: a fresh step of each trial length is as
                // accurate as the accepted one.
                let at = |s: f64| step(&f, x, &y, &k1, s)[0];
                let s = bracketed_root(
                    |s| if s <= 0.0 { g } else { event(x + s, &at(s)) },
                    0.0,
                    h_try,
                );
                return Some(ArcEnd {
                    x: x + s,
                    y: if s <= 0.0 { y } else { at(s) },
                });
            }
            (x, y, k1, g) = (x_next, y_next, k_next, g_next);
        }
        let factor = (0.9 * e.max(1e-10).powf(-0.2)).clamp(0.2, 10.0);
        h = (h_try * factor).min(tol.h_max);
        if !(h > f64::EPSILON * x.abs().max(1.0)) {
            return None;
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    use differential_equations::prelude::*;

    const TOL: ArcTolerances = ArcTolerances {
        rtol: 1e-10,
        atol: 1e-12,
        h_max: 1.0 / 512.0,
        max_steps: 200_000,
    };

    /// A slip arc of the kind the orbit solves: the base turning on an ellipse, the disc
    /// breathing, θ turning towards the base's motion; the event is the push falling to zero.
    struct Turning {
        a: f64,
    }
    impl Turning {
        fn rate(&self, x: f64) -> [f64; 2] {
            let p = std::f64::consts::TAU * x;
            [1.0 + self.a * p.cos(), 0.7 * self.a * p.sin()]
        }
        fn radius(&self, x: f64) -> f64 {
            1.0 + 0.6 * (std::f64::consts::TAU * x).sin()
        }
        fn rhs(&self, x: f64, y: &[f64; 3]) -> [f64; 3] {
            let (s, c) = y[0].sin_cos();
            let w = self.rate(x);
            let r = self.radius(x);
            [(w[1] * c - w[0] * s) / r, r * c, r * s]
        }
        fn push(&self, x: f64, y: &[f64; 3]) -> f64 {
            let (s, c) = y[0].sin_cos();
            let w = self.rate(x);
            let dr = 0.6 * std::f64::consts::TAU * (std::f64::consts::TAU * x).cos();
            w[0] * c + w[1] * s - dr
        }
    }
    impl ODE<f64, [f64; 3]> for Turning {
        fn diff(&self, x: f64, y: &[f64; 3], dydx: &mut [f64; 3]) {
            *dydx = self.rhs(x, y);
        }
    }
    impl Event<f64, [f64; 3]> for Turning {
        fn config(&self) -> EventConfig {
            EventConfig::new(CrossingDirection::Negative, Some(1))
        }
        fn event(&self, x: f64, y: &[f64; 3]) -> f64 {
            self.push(x, y)
        }
    }

    fn reference(t: &Turning, x0: f64, x1: f64, y0: [f64; 3]) -> (f64, [f64; 3]) {
        let sol = IVP::ode(t, x0, x1, y0)
            .event(t)
            .method(
                ExplicitRungeKutta::dopri5()
                    .rtol(1e-12)
                    .atol(1e-14)
                    .h_max(1.0 / 512.0)
                    .max_steps(1_000_000),
            )
            .solve()
            .unwrap();
        (*sol.t.last().unwrap(), *sol.y.last().unwrap())
    }

    #[test]
    fn arcs_match_differential_equations_dormand_prince() {
        for (a, theta0) in [(0.3, 0.2), (1.5, -0.4), (2.5, 1.0), (4.0, 0.0)] {
            let t = Turning { a };
            let ours = integrate_arc(
                |x, y| t.rhs(x, y),
                |x, y| t.push(x, y),
                0.0,
                1.0,
                [theta0, 0.0, 0.0],
                &TOL,
            )
            .unwrap();
            let (x_ref, y_ref) = reference(&t, 0.0, 1.0, [theta0, 0.0, 0.0]);
            assert!(
                (ours.x - x_ref).abs() < 1e-8,
                "a {a}: end {} vs {x_ref}",
                ours.x
            );
            for (i, (y, y_ref)) in ours.y.iter().zip(y_ref).enumerate() {
                assert!((y - y_ref).abs() < 1e-8, "a {a}: y[{i}] {y} vs {y_ref}");
            }
        }
    }

    #[test]
    fn an_arc_without_event_matches_the_closed_form() {
        // θ′ = 1 (a base turning at unit rate around a unit disc): θ = θ0 + x, and the
        // integrals of cos θ and sin θ are sines and cosines.
        let f = |_x: f64, y: &[f64; 3]| [1.0, y[0].cos(), y[0].sin()];
        let end = integrate_arc(f, |_, _| 1.0, 0.0, 3.0, [0.5, 0.0, 0.0], &TOL).unwrap();
        assert_eq!(end.x, 3.0);
        assert!((end.y[0] - 3.5).abs() < 1e-11);
        assert!((end.y[1] - (3.5f64.sin() - 0.5f64.sin())).abs() < 1e-10);
        assert!((end.y[2] - (0.5f64.cos() - 3.5f64.cos())).abs() < 1e-10);
    }

    #[test]
    fn a_nan_field_gives_up_instead_of_looping() {
        let f = |_x: f64, _y: &[f64; 3]| [f64::NAN; 3];
        assert!(integrate_arc(f, |_, _| 1.0, 0.0, 1.0, [0.0; 3], &TOL).is_none());
    }
}
