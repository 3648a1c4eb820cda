//! How a contact's vibration source changes what the solver gets: the normal modulation of a
//! time-resolved source, the static band of Popov's Eq. 4, 6 and 8, the rigid friction circle
//! under in-plane vibration (Eq. 9), and the averaged limits and drive velocity of the
//! compliant theory (Eq. 33 and the drive tables of [`super::vibration`]). Pure functions of
//! the source, the law and the contact's measured quantities.

use super::tangent::TangentBasis;
use super::vibration::{VibrationDirection, VibrationMode, VibrationSource};
use crate::law::{FrictionLaw, Law};
use crate::vec2::{self, Vec2};

/// Time-resolved normal vibration: F_n(t) = F̄ (1 + A/F̄ w)⁺.
pub fn normal_factor(s: &VibrationSource, f_mean: f64, t: f64) -> f64 {
    match (s.normal(), s.mode()) {
        (Some(c), VibrationMode::TimeResolved) => {
            (1.0 + c.amplitude().force(f_mean) / f_mean * s.component_signal(c, t)).max(0.0)
        }
        _ => 1.0,
    }
}

/// The in-plane part a⃗(t) = Σ ± A_i w_i ê_i of the contact spring's force (N), in the slip
/// convention (`rel` = −1 when the source is on collider 1).
pub fn in_plane_force(
    s: &VibrationSource,
    f_mean: f64,
    basis: &TangentBasis,
    rel: f64,
    t: f64,
) -> Vec2 {
    let mut a = [0.0; 2];
    for c in s.components() {
        let Some(axis) = c.direction().axis() else {
            continue;
        };
        let Some(e) = vec2::normalize(basis.project(axis)) else {
            continue;
        };
        let w = rel * c.amplitude().force(f_mean) * s.component_signal(c, t);
        a = vec2::add(a, vec2::scale(e, w));
    }
    a
}

/// Static (holding) factor of a source before any load is known, or in averaged mode
/// without a table: Eq. 4 on the normal component, then Eq. 8 and Eq. 6 on what is left (each
/// exact alone).
pub fn static_factor(s: &VibrationSource, mu0: f64, f_mean: Option<f64>) -> f64 {
    let Some(f) = f_mean.filter(|f| *f > 0.0) else {
        return 1.0;
    };
    if mu0 <= 0.0 {
        return 1.0;
    }
    let (mut z, mut x, mut y) = (0.0f64, 0.0f64, 0.0f64);
    for c in s.components() {
        let ratio = c.amplitude().force(f) / f;
        match c.direction() {
            VibrationDirection::Normal => z = ratio,
            VibrationDirection::Tangential { .. } => x = ratio,
            VibrationDirection::Transverse { .. } => y = ratio,
        }
    }
    let cap = mu0 * (1.0 - z).max(0.0);
    let cap = if y > 0.0 {
        (cap * cap - y * y).max(0.0).sqrt()
    } else {
        cap
    };
    ((cap - x) / mu0).max(0.0)
}

/// The limit after in-plane vibration (time-resolved, rigid) or Popov averaging (averaged
/// mode), and the target slip velocity of an averaged in-plane source.
#[allow(clippy::too_many_arguments)]
pub fn in_plane_limit(
    s: &VibrationSource,
    limit: f64,
    f_n: f64,
    f_mean: f64,
    rel: f64,
    basis: &TangentBasis,
    mu_state: Vec2,
    slip: Vec2,
    t: f64,
    holding: bool,
    law: &Law,
) -> (f64, Option<Vec2>) {
    match s.mode() {
        VibrationMode::Averaged if s.has_in_plane() => {
            averaged_in_plane(s, limit, f_mean, rel, basis, mu_state, slip, holding, law)
        }
        VibrationMode::Averaged => {
            if holding {
                return (limit * static_factor(s, limit, Some(f_n)), None);
            }
            let a_f = s.force_amplitude(f_n);
            let alpha = a_f / f_n;
            // Popov's averaged sliding friction μ̄ = μ_k (1 − α Ψ_w(β)) with the law's
            // sliding coefficient at this speed: continuous with the static
            // μ_k (1 − α) as the slip speed goes to 0 (Ψ_w(0) = 1).
            let speed = vec2::norm(slip);
            let mu0 = law.sliding_coefficient(speed).max(1e-12);
            let k_t = s
                .tangential_stiffness()
                .or(law.stiffness().map(|c| c * f_n));
            let psi = match k_t {
                Some(k) if a_f > 0.0 => s.psi(k * speed / (mu0 * a_f * s.frequency())),
                _ => 0.0,
            };
            (mu0 * (1.0 - alpha * psi).max(0.0), None)
        }
        VibrationMode::TimeResolved => {
            if !s.has_in_plane() {
                return (limit, None);
            }
            let a = in_plane_force(s, f_n, basis, rel, t);
            let cap = limit * f_n;
            // Direction of the steady friction on body 2: against the state, else the slip.
            // It carries f⃗ = r d̂ with the spring force s⃗ = −f⃗: |−r d̂ + a⃗| ≤ cap.
            let d = vec2::normalize(vec2::scale(mu_state, -1.0))
                .or_else(|| vec2::normalize(vec2::scale(slip, -1.0)));
            let r = match d {
                Some(d) => {
                    let along = vec2::dot(a, d);
                    let across = vec2::norm(vec2::sub(a, vec2::scale(d, along)));
                    (cap * cap - across * across).max(0.0).sqrt() + along
                }
                None => (cap * cap - vec2::dot(a, a)).max(0.0).sqrt(),
            };
            ((r / f_n).max(0.0), None)
        }
    }
}

/// Averaged in-plane (and superimposed) vibration from the compliant theory's table: the
/// limit |μ̄(u)| and the target slip velocity v_d x̂ (see `vibration`).
#[allow(clippy::too_many_arguments)]
fn averaged_in_plane(
    s: &VibrationSource,
    limit: f64,
    f_mean: f64,
    rel: f64,
    basis: &TangentBasis,
    mu_state: Vec2,
    slip: Vec2,
    holding: bool,
    law: &Law,
) -> (f64, Option<Vec2>) {
    let mu0 = law.static_coefficient();
    let Some(table) = s.drive_table(mu0, f_mean) else {
        return (limit * static_factor(s, limit, Some(f_mean)), None);
    };
    // The theory's x̂ in the slip convention: the other body's base moves by +A w along it.
    let tangential = s.components().iter().find_map(|c| match c.direction() {
        VibrationDirection::Tangential { axis } => Some(axis),
        _ => None,
    });
    let x = match tangential {
        Some(axis) => vec2::normalize(basis.project(axis)).map(|e| vec2::scale(e, rel)),
        None => vec2::normalize(slip).or_else(|| vec2::normalize(mu_state)),
    };
    let Some(x) = x else {
        return (table.upper.abs(), None);
    };
    // u = v k_t / (μ0 F̄ f); without a stiffness the rigid limit (u = ±∞ once moving).
    let k_t = s
        .tangential_stiffness()
        .or(law.stiffness().map(|c| c * f_mean));
    let unit = k_t.map(|k| mu0 * f_mean * s.frequency() / k);
    let mu = if holding {
        let load = vec2::dot(mu_state, x);
        if load > 0.0 {
            table.upper
        } else if load < 0.0 {
            table.lower
        } else if table.upper < 0.0 {
            table.upper
        } else if table.lower > 0.0 {
            table.lower
        } else {
            table.upper
        }
    } else {
        let v = vec2::dot(slip, x);
        match unit {
            Some(unit) => table.eval(v / unit),
            None if v == 0.0 => table.upper,
            None => table.eval(v.signum() * f64::INFINITY),
        }
    };
    let target = match unit {
        Some(unit) if table.drive != 0.0 => Some(vec2::scale(x, table.drive * unit)),
        _ => None,
    };
    (mu.abs(), target)
}
