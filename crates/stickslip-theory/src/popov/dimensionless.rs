//! The dimensionless groups of the theory: amplitude α (Eq. 16), velocity β (Eq. 17), and the
//! effective coefficient μ̄ = μ0 (1 − α Ψ) they combine into (Eq. 33).

use stickslip_core::error::{ParamError, in_range, non_negative, positive};

/// α = A_z/ū_z (Eq. 16): normal amplitude over mean indentation (equivalently the force ratio
/// A_F/F̄_n of a linear contact).
pub fn alpha(amplitude: f64, mean_indentation: f64) -> Result<f64, ParamError> {
    non_negative("amplitude", amplitude)?;
    positive("mean indentation", mean_indentation)?;
    Ok(amplitude / mean_indentation)
}

/// β = k_x v0 / (μ0 k_z A_z f) (Eq. 17) of the seed's spring contact.
pub fn beta_from_springs(
    k_x: f64,
    k_z: f64,
    v0: f64,
    mu0: f64,
    amplitude: f64,
    frequency: f64,
) -> Result<f64, ParamError> {
    positive("k_z", k_z)?;
    positive("amplitude", amplitude)?;
    beta_from_force(k_x, v0, mu0, k_z * amplitude, frequency)
}

/// β = k_t v0 / (μ0 A_F f) for a compliant contact with tangential stiffness `k_t` whose
/// normal force oscillates with amplitude `force_amplitude` = A_F. Eq. 17 is the case
/// A_F = k_z A_z; for the elasto-plastic law (k_t = c F̄_n, A_F = α F̄_n) it is
/// β = c v0 / (μ0 α f).
pub fn beta_from_force(
    k_t: f64,
    v0: f64,
    mu0: f64,
    force_amplitude: f64,
    frequency: f64,
) -> Result<f64, ParamError> {
    positive("k_t", k_t)?;
    non_negative("v0", v0)?;
    positive("mu0", mu0)?;
    positive("force amplitude", force_amplitude)?;
    positive("frequency", frequency)?;
    Ok(k_t * v0 / (mu0 * force_amplitude * frequency))
}

/// μ̄ = μ0 (1 − α Ψ) (Eq. 33). Valid while contact is never lost, hence α ∈ [0, 1].
pub fn mu_eff(mu0: f64, alpha: f64, psi: f64) -> Result<f64, ParamError> {
    in_range("mu0", mu0, 0.0, stickslip_core::error::MAX_COEFFICIENT)?;
    in_range("alpha", alpha, 0.0, 1.0)?;
    in_range("psi", psi, 0.0, 1.0)?;
    Ok(mu0 * (1.0 - alpha * psi))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn beta_of_springs_equals_beta_of_force() {
        let (k_x, k_z, v0, mu0, a_z, f) = (2.0, 3.0, 0.5, 0.4, 1e-3, 100.0);
        let b = beta_from_springs(k_x, k_z, v0, mu0, a_z, f).unwrap();
        assert!((b - k_x * v0 / (mu0 * k_z * a_z * f)).abs() < 1e-12 * b);
        assert_eq!(b, beta_from_force(k_x, v0, mu0, k_z * a_z, f).unwrap());
    }

    #[test]
    fn rejects_bad_inputs() {
        assert!(beta_from_springs(1.0, 1.0, -1.0, 0.3, 1.0, 1.0).is_err());
        assert!(beta_from_force(1.0, 1.0, 0.3, 0.0, 1.0).is_err());
        assert!(mu_eff(0.3, 1.5, 0.5).is_err());
        assert!(alpha(1.0, 0.0).is_err());
        assert_eq!(mu_eff(0.5, 1.0, 1.0), Ok(0.0));
    }
}
