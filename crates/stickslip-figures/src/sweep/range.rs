//! `LO:HI:N` grids.

use crate::FigureError;
use serde::Serialize;

/// The most values one range may have.
pub const MAX_RANGE_POINTS: usize = 1000;

/// `n` evenly spaced values from `lo` to `hi` (both included; `n = 1` is `lo` alone, which
/// then must equal `hi`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Range {
    /// First value.
    pub lo: f64,
    /// Last value.
    pub hi: f64,
    /// Number of values, 1..=[`MAX_RANGE_POINTS`].
    pub n: usize,
}

impl Range {
    /// Parses `LO:HI:N` (or a single value `V`, meaning `V:V:1`) for option `name`, and checks
    /// that every value lies in `[min, max]`.
    pub fn parse(name: &str, text: &str, min: f64, max: f64) -> Result<Range, FigureError> {
        let bad = |reason: String| FigureError::Range {
            name: name.to_string(),
            text: text.to_string(),
            reason,
        };
        let parts: Vec<&str> = text.split(':').collect();
        let num = |s: &str| -> Result<f64, FigureError> {
            s.trim()
                .parse::<f64>()
                .map_err(|_| bad(format!("`{s}` is not a number")))
        };
        let (lo, hi, n) = match parts.as_slice() {
            [v] => {
                let v = num(v)?;
                (v, v, 1)
            }
            [lo, hi, n] => {
                let n = n
                    .trim()
                    .parse::<usize>()
                    .map_err(|_| bad(format!("the count `{n}` is not a whole number ≥ 1")))?;
                (num(lo)?, num(hi)?, n)
            }
            _ => return Err(bad("expected LO:HI:N or a single value".into())),
        };
        if !lo.is_finite() || !hi.is_finite() {
            return Err(bad("the bounds must be finite".into()));
        }
        if n == 0 || n > MAX_RANGE_POINTS {
            return Err(bad(format!("the count must be in 1..={MAX_RANGE_POINTS}")));
        }
        if lo > hi {
            return Err(bad(format!("LO {lo} is above HI {hi}")));
        }
        if n == 1 && lo != hi {
            return Err(bad("one value needs LO = HI".into()));
        }
        if n > 1 && lo == hi {
            return Err(bad(format!("{n} values need LO < HI")));
        }
        if lo < min || hi > max {
            return Err(bad(format!("values must lie in [{min}, {max}]")));
        }
        Ok(Range { lo, hi, n })
    }

    /// The values.
    pub fn values(&self) -> Vec<f64> {
        if self.n <= 1 {
            return vec![self.lo];
        }
        (0..self.n)
            .map(|i| {
                if i + 1 == self.n {
                    self.hi
                } else {
                    self.lo + (self.hi - self.lo) * i as f64 / (self.n - 1) as f64
                }
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_and_refuses() {
        let r = Range::parse("x", "1:3:3", 0.0, 10.0).unwrap();
        assert_eq!(r.values(), vec![1.0, 2.0, 3.0]);
        assert_eq!(
            Range::parse("x", "2", 0.0, 10.0).unwrap().values(),
            vec![2.0]
        );
        for bad in [
            "", "1:2", "a:2:3", "1:2:0", "3:1:2", "1:2:1", "1:1:3", "1:2:-1", "1:2:1e9", "nan:1:2",
            "1:inf:2", "-1:2:3", "1:20:3", "1:2:3:4",
        ] {
            assert!(Range::parse("x", bad, 0.0, 10.0).is_err(), "{bad}");
        }
    }
}
