//! Normalized oscillation waveforms w(φ) of Popov (2020), Eq. 11: period 1, zero mean,
//! minimum −1; the maximum is free.
//!
//! Conventions used by every consumer ([`crate::popov`]):
//! - [`Waveform::value`] is right-continuous at jumps and [`Waveform::slope`] returns the right
//!   derivative at kinks, so both describe the piece that *starts* at a breakpoint.
//! - [`Waveform::breakpoints`] lists every phase where w or w′ is not smooth, with both one-sided
//!   limits of w; stick events start at the upward jumps ([`Waveform::upward_jumps`]).

use std::{f64::consts::TAU, fmt, str::FromStr, sync::Arc};

use serde::{Deserialize, Deserializer, Serialize, Serializer, de, ser};
use thiserror::Error;

use crate::error::{ParamError, in_range};
use crate::popov::numeric::periodic_min;

/// Pulse width used when an [`WaveformKind::Impulse`] is turned into a [`Waveform`].
pub const DEFAULT_IMPULSE_WIDTH: f64 = 0.05;

/// Samples used to normalize a closure waveform and to find its maximum slope.
const CLOSURE_SAMPLES: usize = 4096;
/// Step of the central difference that gives a closure waveform's slope.
const CLOSURE_DIFF_STEP: f64 = 1e-4;

/// A normalized periodic waveform (period 1, zero mean, minimum −1).
///
/// Parameterized variants carry validated types; build them with [`Waveform::impulse`],
/// [`Waveform::from_table`] and [`Waveform::from_fn`].
#[derive(Clone, Debug)]
pub enum Waveform {
    /// Harmonic oscillation w = sin(2πφ); β_c = 2π.
    Sine,
    /// Right-leaning sawtooth: rises with slope 2 from −1 to +1, then drops back (Eq. 34);
    /// β_c = 2.
    SawtoothRight,
    /// Left-leaning sawtooth: jumps from −1 to +1, then falls with slope −2 (Eq. 35); β_c = ∞.
    SawtoothLeft,
    /// Square wave: +1 on [0, ½), −1 on [½, 1) (Eq. 36); β_c = ∞.
    Square,
    /// Rectangular approximation of the impulse wave δ(φ) − 1 (Eq. 39); β_c = ∞.
    Impulse(ImpulseTrain),
    /// Piecewise-linear interpolation of a sampled period.
    Table(TableWaveform),
    /// A user closure, normalized numerically at construction.
    Custom(CustomWaveform),
}

/// A rectangular pulse of area 1 on top of −1: w = 1/width − 1 on [0, width), −1 elsewhere.
///
/// Width ½ is the square wave; width → 0 approaches δ(φ) − 1.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ImpulseTrain {
    width: f64,
}

impl ImpulseTrain {
    /// Pulse width as a fraction of the period, in (0, 1).
    pub fn width(&self) -> f64 {
        self.width
    }

    /// Value of w on the pulse, 1/width − 1.
    pub fn peak(&self) -> f64 {
        1.0 / self.width - 1.0
    }
}

/// A waveform linear between `n` equidistant samples at phases k/n, wrapping from the last
/// sample back to the first. The samples are stored normalized.
#[derive(Clone, Debug, PartialEq)]
pub struct TableWaveform {
    samples: Arc<[f64]>,
}

impl TableWaveform {
    /// The normalized samples (zero mean, minimum −1).
    pub fn samples(&self) -> &[f64] {
        &self.samples
    }

    fn segment(&self, phase: f64) -> (usize, f64) {
        let n = self.samples.len();
        let pos = phase * n as f64;
        let mut i = (pos.floor() as usize).min(n - 1);
        // Align with the breakpoint phases k/n exactly so a breakpoint selects the piece after it.
        if i + 1 < n && ((i + 1) as f64 / n as f64) <= phase {
            i += 1;
        } else if i > 0 && (i as f64 / n as f64) > phase {
            i -= 1;
        }
        (i, (pos - i as f64).clamp(0.0, 1.0))
    }

    fn value(&self, phase: f64) -> f64 {
        let (i, t) = self.segment(phase);
        let n = self.samples.len();
        self.samples[i] * (1.0 - t) + self.samples[(i + 1) % n] * t
    }

    fn slope(&self, phase: f64) -> f64 {
        let (i, _) = self.segment(phase);
        let n = self.samples.len();
        (self.samples[(i + 1) % n] - self.samples[i]) * n as f64
    }
}

/// Shared, thread-safe user waveform closure (called with phases in [0, 1)).
pub type WaveformFn = Arc<dyn Fn(f64) -> f64 + Send + Sync>;

/// A user closure `f`, used as w(φ) = (f(φ) − offset)·scale with offset and scale chosen at
/// construction so that w has zero mean and minimum −1.
#[derive(Clone)]
pub struct CustomWaveform {
    f: WaveformFn,
    offset: f64,
    scale: f64,
    beta_c: f64,
    max: f64,
}

impl fmt::Debug for CustomWaveform {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("CustomWaveform")
            .field("offset", &self.offset)
            .field("scale", &self.scale)
            .field("beta_c", &self.beta_c)
            .field("max", &self.max)
            .finish_non_exhaustive()
    }
}

impl CustomWaveform {
    fn value(&self, phase: f64) -> f64 {
        ((self.f)(phase) - self.offset) * self.scale
    }

    /// Fourth-order central difference; the closure is assumed smooth.
    fn slope(&self, phase: f64) -> f64 {
        let h = CLOSURE_DIFF_STEP;
        let at = |dx: f64| self.value((phase + dx).rem_euclid(1.0));
        (8.0 * (at(h) - at(-h)) - (at(2.0 * h) - at(-2.0 * h))) / (12.0 * h)
    }
}

/// A phase where w or w′ is not smooth, with the one-sided limits of w there.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Breakpoint {
    /// Phase in [0, 1).
    pub phase: f64,
    /// Left limit w(φ−).
    pub before: f64,
    /// Right limit w(φ+), equal to [`Waveform::value`] at `phase`.
    pub after: f64,
}

impl Breakpoint {
    /// Jump height w(φ+) − w(φ−); zero at a kink.
    pub fn jump(&self) -> f64 {
        self.after - self.before
    }
}

impl Waveform {
    /// Rectangular impulse train of the given pulse width (fraction of the period, in (0, 1)).
    pub fn impulse(width: f64) -> Result<Self, ParamError> {
        in_range("impulse width", width, 0.0, 1.0)?;
        if width == 0.0 || width == 1.0 {
            return Err(ParamError::OutOfRange {
                name: "impulse width",
                value: width,
                min: 0.0,
                max: 1.0,
            });
        }
        Ok(Self::Impulse(ImpulseTrain { width }))
    }

    /// Piecewise-linear waveform through `samples` at phases k/n (do not repeat the first sample
    /// at the end: the period wraps by itself).
    ///
    /// The table is *renormalized*, not rejected: w = (s − mean)/(mean − min), so any affine
    /// image of the intended shape works. Rejected: fewer than 2 samples, non-finite samples,
    /// a constant table.
    pub fn from_table(samples: &[f64]) -> Result<Self, ParamError> {
        let bad = |reason: &str| ParamError::BadTable {
            name: "waveform",
            reason: reason.to_owned(),
        };
        if samples.len() < 2 {
            return Err(bad("needs at least 2 samples"));
        }
        if samples.iter().any(|s| !s.is_finite()) {
            return Err(bad("samples must be finite"));
        }
        // The mean of the periodic linear interpolant is the plain sample mean.
        let mean = samples.iter().sum::<f64>() / samples.len() as f64;
        let min = samples.iter().copied().fold(f64::INFINITY, f64::min);
        let range = mean - min;
        if range <= 1e-12 * mean.abs().max(1.0) {
            return Err(bad("samples are constant"));
        }
        let samples = samples.iter().map(|s| (s - mean) / range).collect();
        Ok(Self::Table(TableWaveform { samples }))
    }

    /// A table waveform from samples that are already normalized (as
    /// [`TableWaveform::samples`] returns them), kept bit for bit: re-normalizing them with
    /// [`Waveform::from_table`] could move them by an ulp, so a saved and restored waveform
    /// would not reproduce the original exactly. The samples are checked like
    /// [`Waveform::from_table`]'s, and must have zero mean and minimum −1 to within 1e-9.
    pub fn from_normalized_table(samples: &[f64]) -> Result<Self, ParamError> {
        let bad = |reason: &str| ParamError::BadTable {
            name: "normalized waveform table",
            reason: reason.to_owned(),
        };
        // Validates length, finiteness and non-constancy.
        Self::from_table(samples)?;
        let mean = samples.iter().sum::<f64>() / samples.len() as f64;
        let min = samples.iter().copied().fold(f64::INFINITY, f64::min);
        if !(mean.abs() <= 1e-9 && (min + 1.0).abs() <= 1e-9) {
            return Err(bad("samples are not normalized (zero mean, minimum -1)"));
        }
        Ok(Self::Table(TableWaveform {
            samples: samples.into(),
        }))
    }

    /// Waveform from a closure `f(φ)` on [0, 1), normalized numerically (mean by the
    /// periodic rectangle rule on 4096 points, minimum by golden-section refinement).
    ///
    /// `f` must be continuous and periodic (f(1) = f(0), checked to 1e-6 of its range) and
    /// should be smooth: the slope is a finite difference and no jumps or kinks are looked
    /// for; use [`Waveform::from_table`] for piecewise shapes.
    pub fn from_fn<F>(f: F) -> Result<Self, ParamError>
    where
        F: Fn(f64) -> f64 + Send + Sync + 'static,
    {
        let bad = |reason: &str| ParamError::BadTable {
            name: "waveform closure",
            reason: reason.to_owned(),
        };
        let n = CLOSURE_SAMPLES;
        let samples: Vec<f64> = (0..n).map(|i| f(i as f64 / n as f64)).collect();
        if samples.iter().any(|s| !s.is_finite()) {
            return Err(bad("returned a non-finite value"));
        }
        let mean = samples.iter().sum::<f64>() / n as f64;
        let (_, min) = periodic_min(&f, n, 4);
        let (_, neg_max) = periodic_min(|x| -f(x), n, 4);
        let (min, max) = (min, -neg_max);
        if !(min.is_finite() && max.is_finite()) {
            return Err(bad("returned a non-finite value"));
        }
        let range = mean - min;
        if range <= 1e-12 * mean.abs().max(1.0) {
            return Err(bad("is constant"));
        }
        let end = f(1.0);
        if !end.is_finite() || (end - samples[0]).abs() > 1e-6 * (max - min) {
            return Err(bad("is not periodic: f(1) != f(0)"));
        }
        let mut custom = CustomWaveform {
            f: Arc::new(f),
            offset: mean,
            scale: 1.0 / range,
            beta_c: 0.0,
            max: (max - mean) / range,
        };
        let (_, neg_slope) = periodic_min(|x| -custom.slope(x), n, 4);
        custom.beta_c = -neg_slope;
        Ok(Self::Custom(custom))
    }

    /// w(φ), with φ taken modulo 1; right-continuous at jumps.
    pub fn value(&self, phase: f64) -> f64 {
        let x = phase.rem_euclid(1.0);
        match self {
            Self::Sine => (TAU * x).sin(),
            Self::SawtoothRight => 2.0 * x - 1.0,
            Self::SawtoothLeft => 1.0 - 2.0 * x,
            Self::Square => {
                if x < 0.5 {
                    1.0
                } else {
                    -1.0
                }
            }
            Self::Impulse(p) => {
                if x < p.width {
                    p.peak()
                } else {
                    -1.0
                }
            }
            Self::Table(t) => t.value(x),
            Self::Custom(c) => c.value(x),
        }
    }

    /// w′(φ), with φ taken modulo 1: the right derivative at kinks, the slope of the piece after
    /// a jump at jumps (jumps themselves are in [`Waveform::breakpoints`]).
    pub fn slope(&self, phase: f64) -> f64 {
        let x = phase.rem_euclid(1.0);
        match self {
            Self::Sine => TAU * (TAU * x).cos(),
            Self::SawtoothRight => 2.0,
            Self::SawtoothLeft => -2.0,
            Self::Square | Self::Impulse(_) => 0.0,
            Self::Table(t) => t.slope(x),
            Self::Custom(c) => c.slope(x),
        }
    }

    /// β_c = max w′ (Eq. 20), `f64::INFINITY` if w jumps up. Stick-slip needs β < β_c.
    pub fn beta_c(&self) -> f64 {
        match self {
            Self::Sine => TAU,
            Self::SawtoothRight => 2.0,
            Self::SawtoothLeft | Self::Square | Self::Impulse(_) => f64::INFINITY,
            Self::Table(t) => {
                let n = t.samples.len();
                (0..n)
                    .map(|i| (t.samples[(i + 1) % n] - t.samples[i]) * n as f64)
                    .fold(f64::NEG_INFINITY, f64::max)
            }
            Self::Custom(c) => c.beta_c,
        }
    }

    /// Maximum of w (the minimum is −1 by normalization).
    pub fn max_value(&self) -> f64 {
        match self {
            Self::Sine | Self::SawtoothRight | Self::SawtoothLeft | Self::Square => 1.0,
            Self::Impulse(p) => p.peak(),
            Self::Table(t) => t.samples.iter().copied().fold(f64::NEG_INFINITY, f64::max),
            Self::Custom(c) => c.max,
        }
    }

    /// Phases in [0, 1), ascending, where w jumps or w′ is discontinuous.
    pub fn breakpoints(&self) -> Vec<Breakpoint> {
        let jump = |phase, before, after| Breakpoint {
            phase,
            before,
            after,
        };
        match self {
            Self::Sine | Self::Custom(_) => Vec::new(),
            Self::SawtoothRight => vec![jump(0.0, 1.0, -1.0)],
            Self::SawtoothLeft => vec![jump(0.0, -1.0, 1.0)],
            Self::Square => vec![jump(0.0, -1.0, 1.0), jump(0.5, 1.0, -1.0)],
            Self::Impulse(p) => vec![jump(0.0, -1.0, p.peak()), jump(p.width, p.peak(), -1.0)],
            Self::Table(t) => {
                let n = t.samples.len();
                (0..n)
                    .map(|i| jump(i as f64 / n as f64, t.samples[i], t.samples[i]))
                    .collect()
            }
        }
    }

    /// Phases in [0, 1) where w jumps up; a stick event starts at each of them.
    pub fn upward_jumps(&self) -> Vec<f64> {
        self.breakpoints()
            .into_iter()
            .filter(|b| b.jump() > 0.0)
            .map(|b| b.phase)
            .collect()
    }

    /// The named shape, if this is one (impulse trains of any width map to
    /// [`WaveformKind::Impulse`]).
    pub fn kind(&self) -> Option<WaveformKind> {
        match self {
            Self::Sine => Some(WaveformKind::Sine),
            Self::SawtoothRight => Some(WaveformKind::SawtoothRight),
            Self::SawtoothLeft => Some(WaveformKind::SawtoothLeft),
            Self::Square => Some(WaveformKind::Square),
            Self::Impulse(_) => Some(WaveformKind::Impulse),
            Self::Table(_) | Self::Custom(_) => None,
        }
    }
}

/// The named waveforms, e.g. for a command line: `sine`, `sawtooth-right`, `sawtooth-left`,
/// `square`, `impulse`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum WaveformKind {
    /// [`Waveform::Sine`].
    Sine,
    /// [`Waveform::SawtoothRight`].
    SawtoothRight,
    /// [`Waveform::SawtoothLeft`].
    SawtoothLeft,
    /// [`Waveform::Square`].
    Square,
    /// [`Waveform::Impulse`] with [`DEFAULT_IMPULSE_WIDTH`].
    Impulse,
}

impl WaveformKind {
    /// Every kind, in declaration order.
    pub const ALL: [Self; 5] = [
        Self::Sine,
        Self::SawtoothRight,
        Self::SawtoothLeft,
        Self::Square,
        Self::Impulse,
    ];

    /// The kebab-case name.
    pub fn name(self) -> &'static str {
        match self {
            Self::Sine => "sine",
            Self::SawtoothRight => "sawtooth-right",
            Self::SawtoothLeft => "sawtooth-left",
            Self::Square => "square",
            Self::Impulse => "impulse",
        }
    }
}

impl From<WaveformKind> for Waveform {
    fn from(kind: WaveformKind) -> Self {
        match kind {
            WaveformKind::Sine => Self::Sine,
            WaveformKind::SawtoothRight => Self::SawtoothRight,
            WaveformKind::SawtoothLeft => Self::SawtoothLeft,
            WaveformKind::Square => Self::Square,
            WaveformKind::Impulse => Self::Impulse(ImpulseTrain {
                width: DEFAULT_IMPULSE_WIDTH,
            }),
        }
    }
}

impl fmt::Display for WaveformKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A string that names no [`WaveformKind`].
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[error(
    "unknown waveform `{0}`; expected one of sine, sawtooth-right, sawtooth-left, square, impulse"
)]
pub struct ParseWaveformKindError(pub String);

impl FromStr for WaveformKind {
    type Err = ParseWaveformKindError;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Self::ALL
            .into_iter()
            .find(|k| k.name() == s)
            .ok_or_else(|| ParseWaveformKindError(s.to_owned()))
    }
}

/// Serialized form of the serializable variants; deserialization re-validates.
#[derive(Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "kebab-case")]
enum WaveformRepr {
    Sine,
    SawtoothRight,
    SawtoothLeft,
    Square,
    Impulse { width: f64 },
    Table { samples: Vec<f64> },
}

/// Closure waveforms cannot be serialized and report an error.
impl Serialize for Waveform {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let repr = match self {
            Self::Sine => WaveformRepr::Sine,
            Self::SawtoothRight => WaveformRepr::SawtoothRight,
            Self::SawtoothLeft => WaveformRepr::SawtoothLeft,
            Self::Square => WaveformRepr::Square,
            Self::Impulse(p) => WaveformRepr::Impulse { width: p.width },
            Self::Table(t) => WaveformRepr::Table {
                samples: t.samples.to_vec(),
            },
            Self::Custom(_) => {
                return Err(ser::Error::custom("closure waveforms are not serializable"));
            }
        };
        repr.serialize(serializer)
    }
}

impl<'de> Deserialize<'de> for Waveform {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        match WaveformRepr::deserialize(deserializer)? {
            WaveformRepr::Sine => Ok(Self::Sine),
            WaveformRepr::SawtoothRight => Ok(Self::SawtoothRight),
            WaveformRepr::SawtoothLeft => Ok(Self::SawtoothLeft),
            WaveformRepr::Square => Ok(Self::Square),
            WaveformRepr::Impulse { width } => Self::impulse(width).map_err(de::Error::custom),
            WaveformRepr::Table { samples } => {
                Self::from_table(&samples).map_err(de::Error::custom)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn all() -> Vec<Waveform> {
        vec![
            Waveform::Sine,
            Waveform::SawtoothRight,
            Waveform::SawtoothLeft,
            Waveform::Square,
            Waveform::impulse(0.1).unwrap(),
            Waveform::from_table(&[0.0, 3.0, 1.0, 2.0]).unwrap(),
            Waveform::from_fn(|x| 5.0 + (TAU * x).cos() + 0.3 * (2.0 * TAU * x).sin()).unwrap(),
        ]
    }

    #[test]
    fn every_waveform_is_normalized() {
        for w in all() {
            let n = 20_000;
            let vals: Vec<f64> = (0..n).map(|i| w.value(i as f64 / n as f64)).collect();
            // Midpoints: exact for the piecewise-linear shapes.
            let mean = (0..n)
                .map(|i| w.value((i as f64 + 0.5) / n as f64))
                .sum::<f64>()
                / n as f64;
            let min = vals.iter().copied().fold(f64::INFINITY, f64::min);
            let max = vals.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            assert!(mean.abs() < 1e-9, "{w:?}: mean {mean}");
            assert!(
                (-1.0 - 1e-9..-1.0 + 2e-4).contains(&min),
                "{w:?}: min {min}"
            );
            // A sawtooth's extremum is a one-sided limit, reached only within one sample.
            assert!(max <= w.max_value() + 1e-9, "{w:?}: max {max}");
            assert!(max > w.max_value() - 2e-4, "{w:?}: max {max}");
        }
    }

    #[test]
    fn slope_matches_finite_difference_away_from_breakpoints() {
        for w in all() {
            for i in 1..50 {
                let x = i as f64 / 50.0 + 0.003;
                if w.breakpoints().iter().any(|b| (b.phase - x).abs() < 0.01) {
                    continue;
                }
                let h = 1e-6;
                let fd = (w.value(x + h) - w.value(x - h)) / (2.0 * h);
                assert!((fd - w.slope(x)).abs() < 1e-5, "{w:?} at {x}");
            }
        }
    }

    #[test]
    fn beta_c_and_jumps() {
        assert_eq!(Waveform::Sine.beta_c(), TAU);
        assert_eq!(Waveform::SawtoothRight.beta_c(), 2.0);
        assert!(Waveform::Square.beta_c().is_infinite());
        assert_eq!(Waveform::Square.upward_jumps(), vec![0.0]);
        assert!(Waveform::SawtoothRight.upward_jumps().is_empty());
        let custom = Waveform::from_fn(|x| (TAU * x).sin()).unwrap();
        assert!((custom.beta_c() - TAU).abs() < 1e-9);
        // The table [0, 3, 1, 2] normalizes to [-1.5, 1.5, -0.5, 0.5]/1.5: steepest rise 3/1.5 * 4.
        let table = Waveform::from_table(&[0.0, 3.0, 1.0, 2.0]).unwrap();
        assert!((table.beta_c() - 8.0).abs() < 1e-12);
        assert!((table.slope(0.25) + 16.0 / 3.0).abs() < 1e-12);
    }

    #[test]
    fn phase_is_taken_modulo_one() {
        for w in all() {
            assert!((w.value(0.3) - w.value(2.3)).abs() < 1e-12);
            assert!((w.value(0.3) - w.value(-0.7)).abs() < 1e-12);
        }
    }

    #[test]
    fn invalid_parameters_are_rejected() {
        assert!(Waveform::impulse(0.0).is_err());
        assert!(Waveform::impulse(1.0).is_err());
        assert!(Waveform::impulse(f64::NAN).is_err());
        assert!(Waveform::from_table(&[1.0]).is_err());
        assert!(Waveform::from_table(&[1.0, 1.0, 1.0]).is_err());
        assert!(Waveform::from_table(&[1.0, f64::INFINITY]).is_err());
        assert!(Waveform::from_fn(|_| 2.0).is_err());
        assert!(Waveform::from_fn(|x| x).is_err(), "a ramp is not periodic");
        assert!(Waveform::from_fn(|x| if x > 0.5 { f64::NAN } else { 0.0 }).is_err());
    }

    #[test]
    fn normalized_table_round_trips_bit_for_bit() {
        let w = Waveform::from_table(&[0.1, 3.7, 1.3, 2.9, 0.7]).unwrap();
        let Waveform::Table(t) = &w else { panic!() };
        let again = Waveform::from_normalized_table(t.samples()).unwrap();
        let Waveform::Table(t2) = &again else {
            panic!()
        };
        let bits = |s: &[f64]| s.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(t.samples()), bits(t2.samples()));
        assert!(Waveform::from_normalized_table(&[0.0, 3.0, 1.0, 2.0]).is_err());
        assert!(Waveform::from_normalized_table(&[-1.0, f64::NAN]).is_err());
    }

    #[test]
    fn half_width_impulse_is_the_square_wave() {
        let imp = Waveform::impulse(0.5).unwrap();
        for i in 0..100 {
            let x = i as f64 / 100.0;
            assert_eq!(imp.value(x), Waveform::Square.value(x));
        }
    }

    #[test]
    fn kind_names_round_trip() {
        for k in WaveformKind::ALL {
            assert_eq!(k.to_string().parse::<WaveformKind>(), Ok(k));
            assert_eq!(Waveform::from(k).kind(), Some(k));
        }
        assert!("triangle".parse::<WaveformKind>().is_err());
    }

    #[test]
    fn deserializes_named_shapes_and_rejects_closures_on_serialize() {
        use serde::de::{IntoDeserializer, value::Error, value::MapDeserializer};
        let from = |kind: &str| {
            let map = MapDeserializer::<_, Error>::new([("kind", kind)].into_iter());
            Waveform::deserialize(map).map(|w| w.kind())
        };
        assert_eq!(
            from("sawtooth-left").unwrap(),
            Some(WaveformKind::SawtoothLeft)
        );
        assert!(from("triangle").is_err());
        let kind: Result<WaveformKind, Error> =
            WaveformKind::deserialize("sawtooth-right".into_deserializer());
        assert_eq!(kind, Ok(WaveformKind::SawtoothRight));
    }

    #[test]
    fn waveforms_are_send_sync() {
        fn check<T: Send + Sync + Clone + fmt::Debug>() {}
        check::<Waveform>();
    }
}
