//! The exact JSON form of sweeps and points, for shard files: every `f64` is written as its
//! shortest round-trip decimal (`{:e}`, e.g. `"4.123456789012345e-1"`, `"NaN"`) in a string
//! and read back with `str::parse`, which is correctly rounded.
//!
//! Why strings: serde_json's default number parser (without its `float_roundtrip` feature) may
//! land one ulp off for 17-digit numbers, and a merge must reproduce the unsharded output byte
//! for byte; a string also carries NaN and infinities, which JSON numbers cannot. The
//! unsharded `NAME.json` keeps plain numbers.
//!
//! [`Exact`] (and [`ExactRef`] for writing) wraps a value in that form; [`ExactJson`] is implemented for the grids and points
//! with serde's remote derives (which fail to compile when a field is added to the original
//! type and not here).

use super::Range;
use super::feeder::{FeederPoint, FeederSweep};
use super::popov::{Drive, PopovPoint, PopovSweep};
use serde::de::Error as _;
use serde::{Deserialize, Deserializer, Serialize, Serializer};
use stickslip_core::waveform::WaveformKind;

/// A value written and read in the exact form.
#[derive(Debug, Clone, PartialEq)]
pub struct Exact<T>(pub T);

/// A borrowed value written in the exact form.
#[derive(Debug, Clone, Copy)]
pub struct ExactRef<'a, T>(pub &'a T);

/// A type with an exact JSON form.
pub trait ExactJson: Sized {
    /// Writes `value` in the exact form.
    fn serialize_exact<S: Serializer>(value: &Self, serializer: S) -> Result<S::Ok, S::Error>;
    /// Reads a value in the exact form.
    fn deserialize_exact<'de, D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error>;
}

impl<T: ExactJson> Serialize for Exact<T> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        T::serialize_exact(&self.0, serializer)
    }
}

impl<T: ExactJson> Serialize for ExactRef<'_, T> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        T::serialize_exact(self.0, serializer)
    }
}

impl<'de, T: ExactJson> Deserialize<'de> for Exact<T> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        T::deserialize_exact(deserializer).map(Exact)
    }
}

/// `f64` as an exact decimal string.
mod float {
    use super::*;

    pub fn serialize<S: Serializer>(v: &f64, s: S) -> Result<S::Ok, S::Error> {
        s.collect_str(&format_args!("{v:e}"))
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<f64, D::Error> {
        let text = String::deserialize(d)?;
        text.parse()
            .map_err(|_| D::Error::custom(format!("`{text}` is not a number")))
    }
}

/// `Option<f64>` as an exact decimal string or null.
mod opt_float {
    use super::*;

    pub fn serialize<S: Serializer>(v: &Option<f64>, s: S) -> Result<S::Ok, S::Error> {
        match v {
            Some(v) => float::serialize(v, s),
            None => s.serialize_none(),
        }
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Option<f64>, D::Error> {
        Option::<String>::deserialize(d)?
            .map(|text| {
                text.parse()
                    .map_err(|_| D::Error::custom(format!("`{text}` is not a number")))
            })
            .transpose()
    }
}

#[derive(Serialize, Deserialize)]
#[serde(remote = "Range", deny_unknown_fields)]
struct RangeDef {
    #[serde(with = "float")]
    lo: f64,
    #[serde(with = "float")]
    hi: f64,
    n: usize,
}

#[derive(Serialize, Deserialize)]
#[serde(remote = "PopovSweep", deny_unknown_fields)]
struct PopovSweepDef {
    waveforms: Vec<WaveformKind>,
    #[serde(with = "RangeDef")]
    beta: Range,
    #[serde(with = "RangeDef")]
    alpha: Range,
    rapier: bool,
    drive: Drive,
}

#[derive(Serialize, Deserialize)]
#[serde(remote = "PopovPoint", deny_unknown_fields)]
struct PopovPointDef {
    waveform: String,
    #[serde(with = "float")]
    beta: f64,
    #[serde(with = "float")]
    alpha: f64,
    #[serde(with = "float")]
    theory: f64,
    #[serde(with = "opt_float")]
    rapier: Option<f64>,
}

#[derive(Serialize, Deserialize)]
#[serde(remote = "FeederSweep", deny_unknown_fields)]
struct FeederSweepDef {
    #[serde(with = "RangeDef")]
    amplitude: Range,
    #[serde(with = "RangeDef")]
    frequency: Range,
    #[serde(with = "RangeDef")]
    angle: Range,
    #[serde(with = "float")]
    mu: f64,
    #[serde(with = "float")]
    dt: f64,
    #[serde(with = "opt_float")]
    ep: Option<f64>,
    settle: usize,
    measure: usize,
}

#[derive(Serialize, Deserialize)]
#[serde(remote = "FeederPoint", deny_unknown_fields)]
struct FeederPointDef {
    #[serde(with = "float")]
    amplitude_mm: f64,
    #[serde(with = "float")]
    frequency: f64,
    #[serde(with = "float")]
    angle_deg: f64,
    #[serde(with = "float")]
    throw_number: f64,
    #[serde(with = "float")]
    rapier: f64,
    #[serde(with = "float")]
    reference: f64,
}

macro_rules! exact_json {
    ($($ty:ty => $def:ty),* $(,)?) => {$(
        impl ExactJson for $ty {
            fn serialize_exact<S: Serializer>(value: &Self, s: S) -> Result<S::Ok, S::Error> {
                <$def>::serialize(value, s)
            }
            fn deserialize_exact<'de, D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
                <$def>::deserialize(d)
            }
        }
    )*};
}

exact_json! {
    Range => RangeDef,
    PopovSweep => PopovSweepDef,
    PopovPoint => PopovPointDef,
    FeederSweep => FeederSweepDef,
    FeederPoint => FeederPointDef,
}

#[cfg(test)]
mod tests {
    use super::*;

    fn round_trip<T: ExactJson + Clone>(v: &T) -> (String, T) {
        let text = serde_json::to_string(&Exact(v.clone())).unwrap();
        let back: Exact<T> = serde_json::from_str(&text).unwrap();
        (text, back.0)
    }

    #[test]
    fn floats_come_back_bit_for_bit() {
        // 17-digit values, where a plain JSON number may come back one ulp off, and values
        // JSON numbers cannot hold.
        let mut x = 0.1_f64;
        let mut values = vec![
            0.30000000000000004,
            1.0 / 3000.0,
            3.3333333333333335e-5,
            -0.0,
            f64::MIN_POSITIVE,
            f64::MAX,
            5e-324,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
        ];
        for _ in 0..2000 {
            x = (x * 3.7 + 0.123_456_789).fract() * 1.7;
            values.push(x);
            values.push(1.0 / (x + 1e-9));
        }
        // Why strings: plain JSON numbers come back one ulp off for some of these (unless a
        // build enables serde_json's `float_roundtrip`, e.g. through another package's
        // features, which is why this only reports).
        let plain_off = values
            .iter()
            .filter(|v| v.is_finite())
            .filter(|&&v| {
                let text = serde_json::to_string(&v).unwrap();
                serde_json::from_str::<f64>(&text).unwrap().to_bits() != v.to_bits()
            })
            .count();
        println!(
            "plain JSON numbers: {plain_off} of {} values off",
            values.len()
        );
        for v in values {
            let p = FeederPoint {
                amplitude_mm: v,
                frequency: v,
                angle_deg: v,
                throw_number: v,
                rapier: v,
                reference: -v,
            };
            let (_, back) = round_trip(&p);
            if v.is_nan() {
                // NaN's sign and payload are not kept; every output prints it alike.
                assert!(back.rapier.is_nan() && back.reference.is_nan());
                continue;
            }
            assert_eq!(back.rapier.to_bits(), v.to_bits(), "{v:e}");
            assert_eq!(back.reference.to_bits(), (-v).to_bits(), "{v:e}");
        }
    }

    #[test]
    fn sweeps_and_points_round_trip() {
        let sweep = PopovSweep {
            waveforms: vec![WaveformKind::Sine, WaveformKind::Square],
            beta: Range {
                lo: 0.5,
                hi: 12.0,
                n: 7,
            },
            alpha: Range {
                lo: 0.2,
                hi: 0.2,
                n: 1,
            },
            rapier: false,
            drive: Drive::Averaged,
        };
        let (text, back) = round_trip(&sweep);
        assert_eq!(back, sweep);
        assert!(text.contains(r#""lo":"5e-1""#), "{text}");
        let point = PopovPoint {
            waveform: "sine".into(),
            beta: 0.1,
            alpha: 0.2,
            theory: 0.30000000000000004,
            rapier: None,
        };
        assert_eq!(round_trip(&point).1, point);
        let feeder = FeederSweep {
            amplitude: Range {
                lo: 1.0,
                hi: 2.0,
                n: 2,
            },
            frequency: Range {
                lo: 25.0,
                hi: 25.0,
                n: 1,
            },
            angle: Range {
                lo: 25.0,
                hi: 25.0,
                n: 1,
            },
            mu: 0.5,
            dt: 1.0 / 3000.0,
            ep: Some(1e5),
            settle: 20,
            measure: 20,
        };
        assert_eq!(round_trip(&feeder).1, feeder);
    }

    #[test]
    fn bad_values_are_errors() {
        for bad in [
            r#"{"lo":"x","hi":"1","n":1}"#,
            r#"{"lo":1,"hi":"1","n":1}"#,
            r#"{"lo":"1","hi":"1"}"#,
            r#"{"lo":"1","hi":"1","n":1,"extra":0}"#,
        ] {
            assert!(serde_json::from_str::<Exact<Range>>(bad).is_err(), "{bad}");
        }
    }
}
