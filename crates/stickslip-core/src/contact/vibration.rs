//! Vibration sources attached to colliders, and what they do to a contact's friction.
//!
//! A source has one to three components at one frequency f (Popov Eq. 9), each
//! F_i(t) = A_i·w_i(f t + φ_i) with w_i a normalized waveform from the core: at most one
//! **normal** component, at most one **tangential** and one **transverse** (in-plane, along a
//! world axis projected onto each contact plane). [`VibrationSource::new`] makes a
//! single-component source, [`VibrationSource::superimposed`] several, e.g. elliptical
//! vibration (normal and tangential a quarter period apart), which transports a slider by
//! itself.
//!
//! ## Mapping onto the seed's compliant contact
//! Amplitudes are forces ([`Amplitude`]): a ratio r of the contact's mean normal force F̄ or a
//! force per manifold. Popov's contact spring is the law's: k_t = c·F̄ for the elasto-plastic
//! law (the law's state is the spring force), else the source's
//! [`tangential stiffness`](VibrationSource::with_tangential_stiffness). With ū_z = 1 and
//! k_z = F̄ the theory's ([`crate::popov::CompliantContact`]) displacement amplitudes
//! are A_z = A/F̄ (normal) and A_x = A/k_t (in-plane: the spring force k_t A_x of the seed's
//! base oscillation in stick, Eq. 5–9), the in-plane ones in units of the slip length
//! μ0 F̄/k_t simply A/(μ0 F̄), and the dimensionless speed is u = v k_t/(μ0 F̄ f).
//! The source moves its own collider's surface: the other collider's base oscillates by −A_x w
//! relative to it, so a slider on a vibrating plate and a vibrating slider on a fixed plate
//! are driven in opposite directions.
//!
//! ## Time-resolved mode ([`VibrationMode::TimeResolved`], dt ≪ 1/f)
//! Every component is evaluated at the step's mid-time.
//! - The normal component modulates the normal force the law sees,
//!   F_n(t) = F̄ (1 + A/F̄ · w)⁺ (Popov Eq. 3), with F̄ the solver's normal force.
//! - The in-plane components add up to a⃗(t) = Σ ± A_i w_i ê_i, the oscillating part of the
//!   contact spring's force. While the contact holds (the solver's rigid stick, the c → ∞
//!   limit) its steady friction f⃗ must satisfy |f⃗ + a⃗| ≤ μ F_n (Eq. 5, 7, 9): the solver's
//!   circle gets the radius available along the steady load's direction d̂,
//!   r = a⃗·d̂ + √((μF_n)² − |a⃗ − (a⃗·d̂)d̂|²). While it slips, an elasto-plastic law
//!   integrates the seed's spring exactly: its force S⃗ = s⃗ + a⃗ is loaded by the slip and by
//!   Δa⃗/k_t and yields on the friction circle; the bodies feel the elastic part s⃗ (whose
//!   period mean is the theory's ⟨F_x⟩), applied by the solver as a saturated friction of
//!   magnitude |s⃗| along −ŝ (through its target tangent velocity when s⃗ does not simply resist
//!   the slip, e.g. a propulsive force during the backward slips of a drive). Other laws keep
//!   the rigid circle while slipping too.
//!
//! ## Averaged mode ([`VibrationMode::Averaged`], f ≫ 1/dt, ultrasonic)
//! - Normal component alone: Popov's μ_s (Eq. 4) while holding and
//!   μ̄ = μ0 (1 − α Ψ_w(β)) (Eq. 33) while sliding, β = k_t v / (μ0 A f).
//! - With in-plane components (with or without a normal one): the compliant theory
//!   ([`crate::popov::mean_friction`], signed) tabulated once per source and μ0 (and
//!   per 1 % band of F̄ for force amplitudes) over the dimensionless speed u, in the theory's
//!   frame x̂ = −(tangential axis) (or the slip/load direction without a tangential component),
//!   with the static band ([`crate::popov::static_friction_compliant`]) at u = 0 and
//!   the free drive velocity v_d ([`crate::popov::free_drive_velocity`]). rapier's
//!   friction has a limit and a target velocity per manifold: the hook gives it the target
//!   relative velocity v_d x̂ and the limit |μ̄(u)| with u from the slip along x̂ (holding: the
//!   end of the static band the load presses on). Since μ̄(u) changes sign exactly at v_d, the
//!   solver then pushes towards v_d with the theory's force on either side: a free slider
//!   runs at v_d, a held one feels the blocking force, a dragged one μ̄(v). Slip across x̂ is
//!   resisted with μ̄ at the slip's component along x̂ (the table is one-dimensional). The
//!   first contact of a new μ0 (or load band) computes the band and v_d (a few ms), the grid
//!   points (16 per decade of u, Catmull-Rom between them) are computed when a contact first
//!   needs them, then shared: no allocation in the step.

use std::sync::{Arc, OnceLock, RwLock};

use crate::ParamError;
use crate::error::{finite, in_range, positive};
use crate::popov;
use crate::waveform::Waveform;
use serde::{Deserialize, Serialize};

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

impl VibrationDirection {
    /// The world axis of an in-plane direction, `None` for the normal.
    pub fn axis(&self) -> Option<[f32; 3]> {
        match *self {
            VibrationDirection::Normal => None,
            VibrationDirection::Tangential { axis } | VibrationDirection::Transverse { axis } => {
                Some(axis)
            }
        }
    }
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

impl Amplitude {
    /// The force (N) for mean normal force `f_mean`.
    pub fn force(&self, f_mean: f64) -> f64 {
        match *self {
            Amplitude::Ratio(r) => r * f_mean,
            Amplitude::Force(a) => a,
        }
    }
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
/// Most components a source has: one per direction of Popov's Eq. 9.
pub const MAX_COMPONENTS: usize = 3;
/// Largest |cos| between a tangential and a transverse axis of one source.
pub const MAX_AXIS_COSINE: f64 = 1e-3;

/// One component of a vibration source: A·w(f t + φ) along a direction.
#[derive(Debug, Clone)]
pub struct VibrationComponent {
    direction: VibrationDirection,
    amplitude: Amplitude,
    waveform: Waveform,
    phase: f64,
}

impl VibrationComponent {
    /// A component with `direction`, `amplitude`, `waveform` and `phase` (in periods).
    pub fn new(
        direction: VibrationDirection,
        amplitude: Amplitude,
        waveform: Waveform,
        phase: f64,
    ) -> Result<Self, ParamError> {
        // Bounds that keep every force and phase of a step finite in rapier's f32.
        match amplitude {
            Amplitude::Ratio(r) => in_range("amplitude ratio", r, 0.0, MAX_RATIO)?,
            Amplitude::Force(a) => in_range("amplitude force", a, 0.0, MAX_FORCE)?,
        };
        finite("phase", phase)?;
        if let Some(axis) = direction.axis() {
            let n = (axis[0] as f64).hypot(axis[1] as f64).hypot(axis[2] as f64);
            positive("axis length", n)?;
        }
        Ok(VibrationComponent {
            direction,
            amplitude,
            waveform,
            phase,
        })
    }

    /// Direction.
    pub fn direction(&self) -> VibrationDirection {
        self.direction
    }
    /// Amplitude.
    pub fn amplitude(&self) -> Amplitude {
        self.amplitude
    }
    /// Waveform.
    pub fn waveform(&self) -> &Waveform {
        &self.waveform
    }
    /// Phase (in periods).
    pub fn phase(&self) -> f64 {
        self.phase
    }
}

/// A vibration source attached to a collider (validated at construction).
#[derive(Debug, Clone)]
pub struct VibrationSource {
    components: Vec<VibrationComponent>,
    frequency: f64,
    mode: VibrationMode,
    tangential_stiffness: Option<f64>,
    psi_table: Option<PsiTable>,
    drive_tables: Option<Arc<DriveCache>>,
}

impl VibrationSource {
    /// A single-component source with `direction`, `amplitude`, `frequency` (Hz), `waveform`,
    /// `phase` (in periods) and `mode`.
    pub fn new(
        direction: VibrationDirection,
        amplitude: Amplitude,
        frequency: f64,
        waveform: Waveform,
        phase: f64,
        mode: VibrationMode,
    ) -> Result<Self, ParamError> {
        let c = VibrationComponent::new(direction, amplitude, waveform, phase)?;
        Self::superimposed(&[c], frequency, mode)
    }

    /// A source of several components at one `frequency` (Hz), Popov's Eq. 9: one to
    /// [`MAX_COMPONENTS`], at most one of each direction kind, a tangential and a transverse
    /// axis perpendicular (|cos| ≤ [`MAX_AXIS_COSINE`]).
    pub fn superimposed(
        components: &[VibrationComponent],
        frequency: f64,
        mode: VibrationMode,
    ) -> Result<Self, ParamError> {
        in_range("frequency", frequency, 0.0, MAX_FREQUENCY)?;
        positive("frequency", frequency)?;
        in_range(
            "number of vibration components",
            components.len() as f64,
            1.0,
            MAX_COMPONENTS as f64,
        )?;
        let count = |f: fn(&VibrationDirection) -> bool| {
            components.iter().filter(|c| f(&c.direction)).count() as f64
        };
        in_range(
            "normal vibration components",
            count(|d| matches!(d, VibrationDirection::Normal)),
            0.0,
            1.0,
        )?;
        in_range(
            "tangential vibration components",
            count(|d| matches!(d, VibrationDirection::Tangential { .. })),
            0.0,
            1.0,
        )?;
        in_range(
            "transverse vibration components",
            count(|d| matches!(d, VibrationDirection::Transverse { .. })),
            0.0,
            1.0,
        )?;
        let unit = |a: [f32; 3]| {
            let v = [a[0] as f64, a[1] as f64, a[2] as f64];
            let n = v[0].hypot(v[1]).hypot(v[2]);
            [v[0] / n, v[1] / n, v[2] / n]
        };
        let axis_of = |f: fn(&VibrationDirection) -> bool| {
            components
                .iter()
                .find(|c| f(&c.direction))
                .and_then(|c| c.direction.axis())
                .map(unit)
        };
        if let (Some(t), Some(y)) = (
            axis_of(|d| matches!(d, VibrationDirection::Tangential { .. })),
            axis_of(|d| matches!(d, VibrationDirection::Transverse { .. })),
        ) {
            let cos = t[0] * y[0] + t[1] * y[1] + t[2] * y[2];
            in_range(
                "cosine between tangential and transverse axes",
                cos,
                -MAX_AXIS_COSINE,
                MAX_AXIS_COSINE,
            )?;
        }
        let in_plane = components.iter().any(|c| c.direction.axis().is_some());
        let (psi_table, drive_tables) = match (mode, in_plane) {
            (VibrationMode::Averaged, false) => {
                (Some(PsiTable::new(&components[0].waveform)?), None)
            }
            (VibrationMode::Averaged, true) => (None, Some(Arc::new(DriveCache::default()))),
            _ => (None, None),
        };
        Ok(VibrationSource {
            components: components.to_vec(),
            frequency,
            mode,
            tangential_stiffness: None,
            psi_table,
            drive_tables,
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

    /// The components, in the order given.
    pub fn components(&self) -> &[VibrationComponent] {
        &self.components
    }
    /// The normal component, if any.
    pub fn normal(&self) -> Option<&VibrationComponent> {
        self.components
            .iter()
            .find(|c| matches!(c.direction, VibrationDirection::Normal))
    }
    /// Whether any component acts in the contact plane.
    pub fn has_in_plane(&self) -> bool {
        self.components.iter().any(|c| c.direction.axis().is_some())
    }
    /// Direction of the first component.
    pub fn direction(&self) -> VibrationDirection {
        self.components[0].direction
    }
    /// Mode.
    pub fn mode(&self) -> VibrationMode {
        self.mode
    }
    /// Amplitude of the first component.
    pub fn amplitude(&self) -> Amplitude {
        self.components[0].amplitude
    }
    /// Phase (in periods) of the first component.
    pub fn phase(&self) -> f64 {
        self.components[0].phase
    }
    /// Frequency (Hz).
    pub fn frequency(&self) -> f64 {
        self.frequency
    }
    /// Waveform of the first component.
    pub fn waveform(&self) -> &Waveform {
        &self.components[0].waveform
    }
    /// Tangential stiffness if set.
    pub fn tangential_stiffness(&self) -> Option<f64> {
        self.tangential_stiffness
    }

    /// Force amplitude (N) of the first component for mean normal force `f_mean`.
    pub fn force_amplitude(&self, f_mean: f64) -> f64 {
        self.components[0].amplitude.force(f_mean)
    }

    /// The normalized signal w(f t + φ) of the first component at time `t` (s).
    pub fn signal(&self, t: f64) -> f64 {
        self.component_signal(&self.components[0], t)
    }

    /// The normalized signal w_i(f t + φ_i) of component `c` at time `t` (s).
    pub fn component_signal(&self, c: &VibrationComponent, t: f64) -> f64 {
        c.waveform.value(self.frequency * t + c.phase)
    }

    /// Popov's Ψ_w(β) of the normal (else first) component (tabulated at construction for
    /// averaged normal sources).
    pub fn psi(&self, beta: f64) -> f64 {
        match &self.psi_table {
            Some(t) => t.eval(beta),
            None => {
                let w = self.normal().unwrap_or(&self.components[0]).waveform();
                popov::psi(w, beta).unwrap_or(0.0)
            }
        }
    }

    /// The theory's excitation for a contact with coefficient `mu0`, mean normal force `f_mean`
    /// and the unit ū_z = 1, k_z = F̄, k_t = μ0 F̄ (slip length 1): normal amplitude A/F̄,
    /// in-plane amplitudes A/(μ0 F̄) slip lengths, each with its waveform and phase.
    pub fn excitation(&self, mu0: f64, f_mean: f64) -> Result<popov::Excitation, ParamError> {
        let mut ex = popov::Excitation::default();
        for c in &self.components {
            let a = c.amplitude.force(f_mean) / f_mean;
            let (slot, amp) = match c.direction {
                VibrationDirection::Normal => (&mut ex.normal, a),
                VibrationDirection::Tangential { .. } => (&mut ex.tangential, a / mu0),
                VibrationDirection::Transverse { .. } => (&mut ex.transverse, a / mu0),
            };
            *slot = Some(popov::Oscillation::new(amp, c.waveform.clone(), c.phase)?);
        }
        Ok(ex)
    }

    /// The averaged-mode table of μ̄ over the dimensionless speed for `mu0` and mean normal
    /// force `f_mean` (computed on first use, then shared; `None` if the source is not
    /// averaged in-plane, the theory failed, or the cache is full).
    pub(crate) fn drive_table(&self, mu0: f64, f_mean: f64) -> Option<TableRef<'_>> {
        let cache = self.drive_tables.as_ref()?;
        let force_amplitudes = self
            .components
            .iter()
            .any(|c| matches!(c.amplitude, Amplitude::Force(_)));
        // Force amplitudes: the ratios depend on F̄, banded by 1 % (the table's F̄ is the band's
        // centre).
        let (band, f_key) = if force_amplitudes {
            if !(f_mean > 0.0 && f_mean.is_finite()) {
                return None;
            }
            let b = (f_mean.ln() / LOAD_BAND.ln_1p()).round();
            (b as i64, (b * LOAD_BAND.ln_1p()).exp())
        } else {
            (0, 1.0)
        };
        let key = (mu0.to_bits(), band);
        let build = || {
            self.excitation(mu0, f_key)
                .and_then(|ex| DriveTable::new(mu0, &ex))
                .ok()
        };
        // The first key (one material, ratio amplitudes: the usual case) without a lock.
        let (first_key, first) = cache.first.get_or_init(|| (key, build()));
        if *first_key == key {
            return first.as_ref().map(TableRef::Borrowed);
        }
        if let Ok(entries) = cache.entries.read()
            && let Some((_, t)) = entries.iter().find(|(k, _)| *k == key)
        {
            return t.clone().map(TableRef::Shared);
        }
        let mut entries = cache.entries.write().ok()?;
        if let Some((_, t)) = entries.iter().find(|(k, _)| *k == key) {
            return t.clone().map(TableRef::Shared);
        }
        if entries.len() >= MAX_DRIVE_TABLES {
            return None;
        }
        let table = build().map(Arc::new);
        entries.push((key, table.clone()));
        table.map(TableRef::Shared)
    }
}

/// Relative width of the load bands of force-amplitude tables.
const LOAD_BAND: f64 = 0.01;
/// Most tables one source keeps (distinct μ0 and load bands).
const MAX_DRIVE_TABLES: usize = 64;
/// Points per decade of the dimensionless speed.
const DRIVE_POINTS_PER_DECADE: usize = 16;
/// Decades below the amplitude scale where the table starts.
const DRIVE_DECADES_BELOW: f64 = 3.0;
/// Decades above the amplitude scale where it ends (μ̄ is on its plateau long before).
const DRIVE_DECADES_ABOVE: f64 = 3.0;

/// The tables of one averaged in-plane source, shared by its clones: the first key's
/// lock-free, further ones (other μ0, load bands) behind a lock.
#[derive(Debug, Default)]
struct DriveCache {
    first: OnceLock<((u64, i64), Option<DriveTable>)>,
    #[allow(clippy::type_complexity)]
    entries: RwLock<Vec<((u64, i64), Option<Arc<DriveTable>>)>>,
}

/// A table from a source's cache.
pub(crate) enum TableRef<'a> {
    Borrowed(&'a DriveTable),
    Shared(Arc<DriveTable>),
}

impl std::ops::Deref for TableRef<'_> {
    type Target = DriveTable;
    fn deref(&self) -> &DriveTable {
        match self {
            TableRef::Borrowed(t) => t,
            TableRef::Shared(t) => t,
        }
    }
}

/// μ̄(u) of the compliant theory over the signed dimensionless speed u = v k_t/(μ0 F̄ f),
/// along the theory's x (see the module docs), with the static band at u = 0 and the free
/// drive velocity. The band and the drive velocity are computed with the table; the points of
/// the log grid when first needed (a contact only ever visits the few around its speeds).
#[derive(Debug)]
pub(crate) struct DriveTable {
    contact: popov::CompliantContact,
    excitation: popov::Excitation,
    log_u0: f64,
    step: f64,
    /// μ̄ at u = +e^(log_u0 + i step).
    positive: Vec<OnceLock<f64>>,
    /// μ̄ at u = −e^(log_u0 + i step) (mirrored from `positive` without a tangential
    /// component).
    negative: Vec<OnceLock<f64>>,
    signed: bool,
    /// μ̄(0−).
    pub lower: f64,
    /// μ̄(0+).
    pub upper: f64,
    /// Free drive velocity in units of the speed scale (0: none).
    pub drive: f64,
}

impl DriveTable {
    fn new(mu0: f64, ex: &popov::Excitation) -> Result<Self, ParamError> {
        // Slip length 1 and frequency 1: u is the drag speed itself.
        let contact = popov::CompliantContact::new(mu0, 1.0, mu0, 1.0)?;
        let amp = |o: &Option<popov::Oscillation>| o.as_ref().map_or(0.0, |o| o.amplitude());
        let scale = (amp(&ex.normal) + amp(&ex.tangential) + amp(&ex.transverse)).max(1e-3);
        let log_u0 = scale.ln() - DRIVE_DECADES_BELOW * std::f64::consts::LN_10;
        let n = ((DRIVE_DECADES_BELOW + DRIVE_DECADES_ABOVE) * DRIVE_POINTS_PER_DECADE as f64)
            as usize
            + 1;
        let step = std::f64::consts::LN_10 / DRIVE_POINTS_PER_DECADE as f64;
        let signed = ex.tangential.is_some();
        // The largest speed must be one the theory takes.
        popov::mean_friction(&contact, ex, 1.0, (log_u0 + step * (n - 1) as f64).exp())?;
        let band = popov::static_friction_compliant(&contact, ex)?;
        let drive = if signed && band.drive() != 0.0 {
            popov::free_drive_velocity(&contact, ex, 1.0)?.unwrap_or(0.0)
        } else {
            0.0
        };
        let cells = |k: usize| (0..k).map(|_| OnceLock::new()).collect::<Vec<_>>();
        Ok(DriveTable {
            contact,
            excitation: ex.clone(),
            log_u0,
            step,
            positive: cells(n),
            negative: cells(if signed { n } else { 0 }),
            signed,
            lower: band.lower,
            upper: band.upper,
            drive,
        })
    }

    /// μ̄ at grid point `i` on the side `negative`: computed once; a speed the theory cannot
    /// settle (e.g. a transverse offset creeping at the slowest speeds) takes the next faster
    /// point's value.
    fn point(&self, negative: bool, i: usize) -> f64 {
        if negative && !self.signed {
            return -self.point(false, i);
        }
        let cells = if negative {
            &self.negative
        } else {
            &self.positive
        };
        let last = cells.len() - 1;
        *cells[i].get_or_init(|| {
            let sign = if negative { -1.0 } else { 1.0 };
            let u = sign * (self.log_u0 + self.step * i as f64).exp();
            match popov::mean_friction(&self.contact, &self.excitation, 1.0, u) {
                Ok(mu) => mu,
                Err(_) if i < last => self.point(negative, i + 1),
                Err(_) => sign * self.contact.mu0(),
            }
        })
    }

    /// μ̄ at the signed dimensionless speed `u` (u = 0: the upper end of the band).
    pub fn eval(&self, u: f64) -> f64 {
        if u.is_nan() {
            return self.upper;
        }
        let (negative, at_zero) = if u >= 0.0 {
            (false, self.upper)
        } else {
            (true, self.lower)
        };
        let a = u.abs();
        let u0 = self.log_u0.exp();
        if a <= u0 {
            return at_zero + (self.point(negative, 0) - at_zero) * a / u0;
        }
        let x = (a.ln() - self.log_u0) / self.step;
        let last = self.positive.len() - 1;
        if x >= last as f64 {
            return self.point(negative, last);
        }
        // Catmull-Rom on the uniform log grid (one-sided at the ends), kept inside the two
        // neighbours' range so a kink (the onset of pure sliding) is not overshot.
        let i = (x.floor() as usize).min(last - 1);
        let w = (x - i as f64).clamp(0.0, 1.0);
        let (p1, p2) = (self.point(negative, i), self.point(negative, i + 1));
        let p0 = if i > 0 {
            self.point(negative, i - 1)
        } else {
            2.0 * p1 - p2
        };
        let p3 = if i + 2 <= last {
            self.point(negative, i + 2)
        } else {
            2.0 * p2 - p1
        };
        let (m1, m2) = (0.5 * (p2 - p0), 0.5 * (p3 - p1));
        let (w2, w3) = (w * w, w * w * w);
        let v = (2.0 * w3 - 3.0 * w2 + 1.0) * p1
            + (w3 - 2.0 * w2 + w) * m1
            + (-2.0 * w3 + 3.0 * w2) * p2
            + (w3 - w2) * m2;
        v.clamp(p1.min(p2), p1.max(p2))
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
