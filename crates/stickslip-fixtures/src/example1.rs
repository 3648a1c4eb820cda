//! The seed's Example 1 in rapier, sampled at given times.

use crate::example1_trace;

/// The seed's Example 1 in rapier: a 1 kg box (rotations locked) on the ground under the
/// tangential force `profile`, with the friction `law`, at step `dt`. Returns the box's
/// displacement at each of `times` (s) and its velocity at the end.
pub fn example1(
    law: stickslip_core::law::Law,
    profile: &stickslip_core::profile::ForceProfile,
    dt: f64,
    times: &[f64],
) -> (Vec<f64>, f64) {
    let end = times.iter().cloned().fold(0.0, f64::max);
    let trace = example1_trace(law, profile, dt, end);
    let mut out = Vec::with_capacity(times.len());
    for s in &trace {
        for &ti in times {
            if (s.t - ti).abs() < 0.5 * dt {
                out.push(s.x);
            }
        }
    }
    (out, trace.last().map_or(0.0, |s| s.v))
}
