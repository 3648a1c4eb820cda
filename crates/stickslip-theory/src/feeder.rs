//! A rigid-body reference for vibratory feeders: a point mass on a horizontal trough that
//! vibrates along a throw angle, with Coulomb friction, exact ballistic flight and a plastic
//! landing with Coulomb impact friction.
//!
//! The trough moves as u(t) = A sin(ωt) (cos β, sin β) (ω = 2πf, throw angle β). In contact the
//! part carries the normal force m (g + a_y(t)); it sticks while the friction needed to follow
//! the trough, m |a_x(t)|, stays within μ m (g + a_y), and slides otherwise with
//! v̇ = −sgn(ġ) μ (g + a_y(t)) (closed form: ∫a_y dt = V_y). When g + a_y < 0 (throw number
//! Γ = A ω² sin β / g > 1) it lifts off and flies ballistically until it meets the trough
//! again; the landing is plastic (the normal relative velocity Δv_n is lost) and the
//! tangential impulse is at most μ m Δv_n (Coulomb impact friction). Every switching time is
//! the root of a closed-form function, found by scanning a fine grid and Brent's method
//! (`roots`), so the result does not depend on a time step.

use std::f64::consts::PI;
use stickslip_core::error::{ParamError, in_range, positive};

/// Grid points per period used to bracket switching times.
const SCAN_PER_PERIOD: usize = 4000;

/// A vibratory feeder: trough motion and Coulomb friction (validated).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VibratoryFeeder {
    amplitude: f64,
    omega: f64,
    throw_angle: f64,
    mu: f64,
    gravity: f64,
}

#[derive(Debug, Clone, Copy, PartialEq)]
enum Mode {
    Stick,
    /// Sliding with slip sign (part velocity minus trough velocity).
    Slide(f64),
    /// In flight since `t0` from height `y0` with vertical velocity `vy0` (relative to the
    /// ground frame).
    Flight {
        t0: f64,
        y0: f64,
        vy0: f64,
    },
}

impl VibratoryFeeder {
    /// Amplitude A (m) > 0, frequency f (Hz) > 0, throw angle β (rad) in [0, π/2], friction
    /// coefficient μ > 0, gravity g > 0.
    pub fn new(
        amplitude: f64,
        frequency: f64,
        throw_angle: f64,
        mu: f64,
        gravity: f64,
    ) -> Result<Self, ParamError> {
        Ok(VibratoryFeeder {
            amplitude: positive("amplitude", amplitude)?,
            omega: 2.0 * PI * positive("frequency", frequency)?,
            throw_angle: in_range("throw_angle", throw_angle, 0.0, 0.5 * PI)?,
            mu: positive("mu", mu)?,
            gravity: positive("gravity", gravity)?,
        })
    }

    /// Throw number Γ = A ω² sin β / g: the part leaves the trough once a period when Γ > 1.
    pub fn throw_number(&self) -> f64 {
        self.amplitude * self.omega * self.omega * self.throw_angle.sin() / self.gravity
    }

    /// Trough displacement (x, y) at time t (m).
    pub fn trough_position(&self, t: f64) -> (f64, f64) {
        let s = self.amplitude * (self.omega * t).sin();
        (s * self.throw_angle.cos(), s * self.throw_angle.sin())
    }

    /// Trough velocity (x, y) at time t (m/s).
    pub fn trough_velocity(&self, t: f64) -> (f64, f64) {
        let v = self.amplitude * self.omega * (self.omega * t).cos();
        (v * self.throw_angle.cos(), v * self.throw_angle.sin())
    }

    fn trough_accel(&self, t: f64) -> (f64, f64) {
        let a = -self.amplitude * self.omega * self.omega * (self.omega * t).sin();
        (a * self.throw_angle.cos(), a * self.throw_angle.sin())
    }

    /// Normal acceleration available for friction, g + a_y (negative: the part lifts off).
    fn press(&self, t: f64) -> f64 {
        self.gravity + self.trough_accel(t).1
    }

    /// Mean horizontal transport speed (m/s) of a part that starts riding the trough at t = 0,
    /// over `measure` periods after `settle` periods.
    pub fn transport_speed(&self, settle: usize, measure: usize) -> f64 {
        let period = 2.0 * PI / self.omega;
        let h = period / SCAN_PER_PERIOD as f64;
        let (t_start, t_end) = (settle as f64 * period, (settle + measure) as f64 * period);
        let mut t = 0.0;
        let mut vx = self.trough_velocity(0.0).0;
        let mut mode = Mode::Stick;
        // Reference point of the current piece for the closed-form velocity.
        let (mut t_ref, mut v_ref) = (0.0, vx);
        let mut distance = 0.0;
        while t < t_end {
            let t1 = (t + h).min(t_end);
            // The earliest switching time in (t, t1], if any.
            let event = self.next_event(mode, t, t1, t_ref, v_ref);
            let t_hit = event.unwrap_or(t1);
            if t_hit > t_start {
                let a = t.max(t_start);
                distance += self.distance(mode, a, t_hit, t_ref, v_ref);
            }
            vx = self.velocity(mode, t_hit, t_ref, v_ref);
            t = t_hit;
            if event.is_some() {
                mode = self.switch(mode, t, &mut vx);
                t_ref = t;
                v_ref = vx;
            }
        }
        distance / (t_end - t_start)
    }

    /// Horizontal part velocity at t in `mode` (piece started at `t_ref` with `v_ref`).
    fn velocity(&self, mode: Mode, t: f64, t_ref: f64, v_ref: f64) -> f64 {
        match mode {
            Mode::Stick => self.trough_velocity(t).0,
            Mode::Slide(sign) => {
                let vy = |s: f64| self.trough_velocity(s).1;
                v_ref - sign * self.mu * (self.gravity * (t - t_ref) + vy(t) - vy(t_ref))
            }
            Mode::Flight { .. } => v_ref,
        }
    }

    /// Distance travelled over [a, b] in `mode` (Simpson's rule on the smooth closed form;
    /// pieces are at most one grid step long).
    fn distance(&self, mode: Mode, a: f64, b: f64, t_ref: f64, v_ref: f64) -> f64 {
        if b <= a {
            return 0.0;
        }
        let v = |t: f64| self.velocity(mode, t, t_ref, v_ref);
        (b - a) / 6.0 * (v(a) + 4.0 * v(0.5 * (a + b)) + v(b))
    }

    /// The function whose sign change ends the current mode, and the first root in (t0, t1].
    fn next_event(&self, mode: Mode, t0: f64, t1: f64, t_ref: f64, v_ref: f64) -> Option<f64> {
        let root = |f: &dyn Fn(f64) -> f64| -> Option<f64> {
            let (f0, f1) = (f(t0), f(t1));
            if f0 > 0.0 && f1 <= 0.0 {
                let mut conv = roots::SimpleConvergency {
                    eps: 1e-15,
                    max_iter: 200,
                };
                roots::find_root_brent(t0, t1, f, &mut conv).ok()
            } else {
                None
            }
        };
        let earliest = |a: Option<f64>, b: Option<f64>| match (a, b) {
            (Some(x), Some(y)) => Some(x.min(y)),
            (x, None) => x,
            (None, y) => y,
        };
        match mode {
            Mode::Stick => {
                let lift = root(&|t| self.press(t));
                let slip = root(&|t| self.mu * self.press(t) - self.trough_accel(t).0.abs());
                earliest(lift, slip)
            }
            Mode::Slide(sign) => {
                let lift = root(&|t| self.press(t));
                let stop = root(&|t| {
                    sign * (self.velocity(mode, t, t_ref, v_ref) - self.trough_velocity(t).0)
                });
                earliest(lift, stop)
            }
            Mode::Flight { t0: tf, y0, vy0 } => {
                // Height above the trough; it starts at zero, so skip the lift-off instant.
                let gap = |t: f64| {
                    let d = t - tf;
                    y0 + vy0 * d - 0.5 * self.gravity * d * d - self.trough_position(t).1
                };
                if t1 - tf < 1e-9 / self.omega {
                    return None;
                }
                root(&|t| {
                    if t - tf < 1e-9 / self.omega {
                        1.0
                    } else {
                        gap(t)
                    }
                })
            }
        }
    }

    /// The mode after the event at t; sets the horizontal velocity `vx` where it jumps.
    fn switch(&self, mode: Mode, t: f64, vx: &mut f64) -> Mode {
        let (ax, _) = self.trough_accel(t);
        let (vtx, vty) = self.trough_velocity(t);
        let press = self.press(t);
        let flight = Mode::Flight {
            t0: t,
            y0: self.trough_position(t).1,
            vy0: vty,
        };
        // At rest on the trough: stick if friction can follow its acceleration, else slide
        // against it (the part lags behind).
        let at_rest = || {
            if ax.abs() <= self.mu * press {
                Mode::Stick
            } else {
                Mode::Slide(-ax.signum())
            }
        };
        let lifting = press <= 1e-9 * self.gravity;
        match mode {
            Mode::Stick if lifting => flight,
            Mode::Stick => Mode::Slide(-ax.signum()),
            Mode::Slide(_) if lifting => flight,
            Mode::Slide(_) => {
                *vx = vtx;
                at_rest()
            }
            Mode::Flight { t0, vy0, .. } => {
                // Plastic landing with Coulomb impact friction.
                let dv_n = (vty - (vy0 - self.gravity * (t - t0))).max(0.0);
                let s = *vx - vtx;
                if s.abs() <= self.mu * dv_n {
                    *vx = vtx;
                } else {
                    *vx -= s.signum() * self.mu * dv_n;
                }
                if press <= 0.0 {
                    // Still thrown: the trough leaves the part behind at once.
                    return flight;
                }
                if *vx == vtx {
                    at_rest()
                } else {
                    Mode::Slide((*vx - vtx).signum())
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn no_vibration_sideways_means_no_transport() {
        // Vertical vibration below the throw limit: the part rides along, x stays put.
        let f = VibratoryFeeder::new(1e-3, 10.0, 0.5 * PI, 0.5, 9.81).unwrap();
        assert!(f.throw_number() < 1.0);
        assert!(f.transport_speed(2, 10).abs() < 1e-12);
    }

    #[test]
    fn a_sticking_part_rides_the_trough_with_zero_mean_speed() {
        // Small acceleration: μ (g + a_y) > |a_x| always, the part sticks, mean speed 0.
        let f = VibratoryFeeder::new(1e-4, 10.0, 0.3, 0.8, 9.81).unwrap();
        assert!(f.transport_speed(1, 20).abs() < 1e-9);
    }
}
