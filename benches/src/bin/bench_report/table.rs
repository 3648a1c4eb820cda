//! Markdown tables, number formatting and the targets summary.

use std::fmt::Write as _;

/// A markdown table.
pub fn render(headers: &[&str], rows: &[Vec<String>]) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "| {} |", headers.join(" | "));
    let _ = writeln!(s, "|{}", headers.iter().map(|_| "---|").collect::<String>());
    for r in rows {
        let _ = writeln!(s, "| {} |", r.join(" | "));
    }
    s.push('\n');
    s
}

/// A number with `sig` significant digits, plain or in scientific notation.
pub fn num(x: f64, sig: usize) -> String {
    if !x.is_finite() {
        return if x.is_nan() {
            "—".into()
        } else {
            "∞".into()
        };
    }
    if x == 0.0 {
        return "0".into();
    }
    let mag = x.abs().log10().floor() as i32;
    if !(-3..6).contains(&mag) {
        return format!("{x:.prec$e}", prec = sig.saturating_sub(1));
    }
    let decimals = (sig as i32 - 1 - mag).max(0) as usize;
    format!("{x:.decimals$}")
}

/// A count.
pub fn int(x: f64) -> String {
    if x.is_finite() {
        format!("{}", x.round() as i64)
    } else {
        "—".into()
    }
}

/// A percentage with sign.
pub fn pct(x: f64) -> String {
    if !x.is_finite() {
        return "—".into();
    }
    let p = 100.0 * x;
    if p.abs() >= 100.0 {
        format!("{p:+.0} %")
    } else if p.abs() >= 1.0 {
        format!("{p:+.2} %")
    } else {
        format!("{p:+.3} %")
    }
}

/// An unsigned percentage.
pub fn upct(x: f64) -> String {
    pct(x).trim_start_matches('+').to_string()
}

/// A ratio like `1.07×`.
pub fn ratio(x: f64) -> String {
    if !x.is_finite() {
        "—".into()
    } else if x.abs() >= 0.1 {
        format!("{x:.2}×")
    } else {
        format!("{}×", num(x, 2))
    }
}

/// Met / missed marker.
pub fn verdict(met: bool) -> String {
    if met {
        "met".into()
    } else {
        "**missed**".into()
    }
}

/// The targets of the issue, with their measured figures.
#[derive(Debug, Default)]
pub struct Summary {
    rows: Vec<Vec<String>>,
}

impl Summary {
    /// Adds a target: what, the target value, the measured figure, met or not.
    pub fn add(&mut self, what: impl Into<String>, target: &str, measured: String, met: bool) {
        self.rows
            .push(vec![what.into(), target.into(), measured, verdict(met)]);
    }

    /// Adds a line with no verdict (information).
    pub fn info(&mut self, what: impl Into<String>, target: &str, measured: String) {
        self.rows
            .push(vec![what.into(), target.into(), measured, "—".into()]);
    }

    /// The summary section.
    pub fn render(&self) -> String {
        let mut s = String::from("## Targets at a glance\n\n");
        if self.rows.is_empty() {
            s.push_str("No section was run.\n\n");
            return s;
        }
        s.push_str(&render(
            &["target", "wanted", "measured", "verdict"],
            &self.rows,
        ));
        let missed: Vec<&Vec<String>> = self.rows.iter().filter(|r| r[3] != "met").collect();
        let missed: Vec<&Vec<String>> = missed.into_iter().filter(|r| r[3] != "—").collect();
        if missed.is_empty() {
            s.push_str("All targets met.\n\n");
        } else {
            s.push_str("Missed:\n\n");
            for r in missed {
                let _ = writeln!(s, "- {}: wanted {}, measured {}.", r[0], r[1], r[2]);
            }
            s.push('\n');
        }
        s
    }
}
