//! Vibration sources attached to colliders, and what they do to a contact's friction.
//!
//! A source oscillates with F(t) = A·w(f t + φ), w a normalized waveform from the core.
//!
//! - **Normal** sources modulate the normal force the friction law sees,
//!   F_n(t) = F̄ (1 + A/F̄ · w)⁺ (Popov Eq. 3), with F̄ the solver's normal force.
//! - **Tangential** and **transverse** sources are an in-plane force a⃗(t) = A w ê that the
//!   contact has to carry besides the steady load: the steady friction f⃗ must satisfy
//!   |f⃗ + a⃗| ≤ μ F_n (Popov Eq. 5 and 7). rapier's friction limit is a circle, so the hook
//!   gives it the radius available along the steady load's direction d̂:
//!   r = −a⃗·d̂ + √((μF_n)² − |a⃗ − (a⃗·d̂)d̂|²). For ê ∥ d̂ that is Eq. 5, for ê ⊥ d̂ Eq. 7; the
//!   two names only say which axis the user means.
//!
//! Modes: [`VibrationMode::TimeResolved`] evaluates the above at each step's mid-time (the
//! step must resolve the period: dt ≪ 1/f). [`VibrationMode::Averaged`] is for f ≫ 1/dt
//! (ultrasonic): the contact gets Popov's effective coefficients — static μ_s (Eq. 4, 6, 8)
//! while holding and, for normal vibration, μ̄ = μ0 (1 − α Ψ_w(β)) (Eq. 33) while sliding,
//! with β = k_t v / (μ0 A f) and k_t the contact's tangential stiffness. Popov gives no closed
//! sliding law for in-plane vibration; averaged tangential/transverse sources use his static
//! value while holding and the plateau μ0 (Eq. 12) while sliding.

use serde::{Deserialize, Serialize};
use stickslip_core::ParamError;
use stickslip_core::error::{finite, in_range, positive};
use stickslip_core::popov;
use stickslip_core::waveform::Waveform;

/// Direction of the oscillation.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "kebab-case")]
pub enum VibrationDirection {
    /// Along the contact normal.
    Normal,
    /// In the contact plane along `axis` (world), meant along the sliding direction.
    Tangential {
        /// World-space axis (projected onto each contact plane).
        axis: [f32; 3],
    },
    /// In the contact plane along `axis` (world), meant across the sliding direction.
    Transverse {
        /// World-space axis (projected onto each contact plane).
        axis: [f32; 3],
    },
}

/// How big the oscillation is.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Amplitude {
    /// A multiple of the contact's mean normal force (Popov's α for normal vibration).
    Ratio(f64),
    /// A force (N) per contact manifold.
    Force(f64),
}

/// Whether the step resolves the oscillation.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum VibrationMode {
    /// Apply the oscillation at each step's phase (needs dt ≪ 1/f).
    #[default]
    TimeResolved,
    /// Use Popov's period-averaged friction (for f ≫ 1/dt).
    Averaged,
}

/// Largest amplitude ratio α a source accepts (α > 1 lifts a normally loaded contact off).
pub const MAX_RATIO: f64 = 1e3;
/// Largest force amplitude (N) a source accepts: far beyond any machine, far inside f32.
pub const MAX_FORCE: f64 = 1e15;
/// Largest frequency (Hz) a source accepts (ultrasonic sources run at 20–100 kHz).
pub const MAX_FREQUENCY: f64 = 1e9;
/// Largest tangential contact stiffness (N/m) a source accepts.
pub const MAX_TANGENTIAL_STIFFNESS: f64 = 1e15;

/// A vibration source attached to a collider (validated at construction).
#[derive(Debug, Clone)]
pub struct VibrationSource {
    direction: VibrationDirection,
    amplitude: Amplitude,
    frequency: f64,
    waveform: Waveform,
    phase: f64,
    mode: VibrationMode,
    tangential_stiffness: Option<f64>,
    psi_table: Option<PsiTable>,
}

impl VibrationSource {
    /// A source with `direction`, `amplitude`, `frequency` (Hz), `waveform`, `phase` (in
    /// periods) and `mode`.
    pub fn new(
        direction: VibrationDirection,
        amplitude: Amplitude,
        frequency: f64,
        waveform: Waveform,
        phase: f64,
        mode: VibrationMode,
    ) -> Result<Self, ParamError> {
        // Bounds that keep every force and phase of a step finite in rapier's f32.
        match amplitude {
            Amplitude::Ratio(r) => in_range("amplitude ratio", r, 0.0, MAX_RATIO)?,
            Amplitude::Force(a) => in_range("amplitude force", a, 0.0, MAX_FORCE)?,
        };
        in_range("frequency", frequency, 0.0, MAX_FREQUENCY)?;
        positive("frequency", frequency)?;
        finite("phase", phase)?;
        if let VibrationDirection::Tangential { axis } | VibrationDirection::Transverse { axis } =
            direction
        {
            let n = (axis[0] as f64).hypot(axis[1] as f64).hypot(axis[2] as f64);
            positive("axis length", n)?;
        }
        let psi_table = match (mode, direction) {
            (VibrationMode::Averaged, VibrationDirection::Normal) => {
                Some(PsiTable::new(&waveform)?)
            }
            _ => None,
        };
        Ok(VibrationSource {
            direction,
            amplitude,
            frequency,
            waveform,
            phase,
            mode,
            tangential_stiffness: None,
            psi_table,
        })
    }

    /// Tangential stiffness k_t (N/m) of the contact, used for β in averaged mode. Default:
    /// c·F̄ of an elasto-plastic material (required for other laws).
    pub fn with_tangential_stiffness(mut self, k_t: f64) -> Result<Self, ParamError> {
        positive("tangential stiffness", k_t)?;
        in_range("tangential stiffness", k_t, 0.0, MAX_TANGENTIAL_STIFFNESS)?;
        self.tangential_stiffness = Some(k_t);
        Ok(self)
    }

    /// Direction.
    pub fn direction(&self) -> VibrationDirection {
        self.direction
    }
    /// Mode.
    pub fn mode(&self) -> VibrationMode {
        self.mode
    }
    /// Amplitude.
    pub fn amplitude(&self) -> Amplitude {
        self.amplitude
    }
    /// Phase (in periods).
    pub fn phase(&self) -> f64 {
        self.phase
    }
    /// Frequency (Hz).
    pub fn frequency(&self) -> f64 {
        self.frequency
    }
    /// Waveform.
    pub fn waveform(&self) -> &Waveform {
        &self.waveform
    }
    /// Tangential stiffness if set.
    pub fn tangential_stiffness(&self) -> Option<f64> {
        self.tangential_stiffness
    }

    /// Force amplitude (N) for mean normal force `f_mean`.
    pub fn force_amplitude(&self, f_mean: f64) -> f64 {
        match self.amplitude {
            Amplitude::Ratio(r) => r * f_mean,
            Amplitude::Force(a) => a,
        }
    }

    /// The normalized signal w(f t + φ) at time `t` (s).
    pub fn signal(&self, t: f64) -> f64 {
        self.waveform.value(self.frequency * t + self.phase)
    }

    /// Popov's Ψ_w(β) (tabulated at construction for averaged normal sources).
    pub fn psi(&self, beta: f64) -> f64 {
        match &self.psi_table {
            Some(t) => t.eval(beta),
            None => popov::psi(&self.waveform, beta).unwrap_or(0.0),
        }
    }
}

/// Ψ_w(β) on a log grid, so the per-step cost in averaged mode is a table lookup.
#[derive(Debug, Clone)]
struct PsiTable {
    log_beta0: f64,
    step: f64,
    values: Vec<f64>,
    beta_c: f64,
}

const PSI_POINTS: usize = 192;
const PSI_BETA_MIN: f64 = 1e-4;
const PSI_BETA_MAX_UNBOUNDED: f64 = 1e4;

impl PsiTable {
    fn new(w: &Waveform) -> Result<Self, ParamError> {
        let beta_c = w.beta_c();
        let top = if beta_c.is_finite() {
            beta_c
        } else {
            PSI_BETA_MAX_UNBOUNDED
        };
        let (l0, l1) = (PSI_BETA_MIN.ln(), top.ln());
        let step = (l1 - l0) / (PSI_POINTS - 1) as f64;
        let values = (0..PSI_POINTS)
            .map(|i| popov::psi(w, (l0 + step * i as f64).exp()))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(PsiTable {
            log_beta0: l0,
            step,
            values,
            beta_c,
        })
    }

    fn eval(&self, beta: f64) -> f64 {
        if !(beta > PSI_BETA_MIN) {
            return 1.0; // Ψ(0) = 1; the table starts where Ψ is 1 to within 1e-4
        }
        if beta >= self.beta_c {
            return 0.0;
        }
        let x = (beta.ln() - self.log_beta0) / self.step;
        let i = (x.floor() as usize).min(self.values.len() - 2);
        let w = (x - i as f64).clamp(0.0, 1.0);
        self.values[i] + w * (self.values[i + 1] - self.values[i])
    }
}
