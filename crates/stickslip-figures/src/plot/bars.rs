//! Bar charts (integration cost per law and method).

use super::{Plot, color, text, tick};
use plotters::coord::Shift;
use plotters::prelude::*;

/// One bar; `value: None` marks a run that failed (written as "failed" instead of a bar).
#[derive(Debug, Clone, PartialEq)]
pub struct Bar {
    /// Label under the bar.
    pub label: String,
    /// Height, if the run succeeded.
    pub value: Option<f64>,
    /// Palette index.
    pub color: usize,
}

/// A bar chart, optionally on a log axis.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct BarChart {
    /// Caption.
    pub title: String,
    /// y-axis label.
    pub y_label: String,
    /// The bars, left to right.
    pub bars: Vec<Bar>,
    /// Logarithmic y axis.
    pub log_y: bool,
    /// Bars per group: the x axis then names groups (`groups`) instead of bars.
    pub group_size: usize,
    /// Group names, left to right (used when `group_size > 0`).
    pub groups: Vec<String>,
    /// Legend entries (label, palette index).
    pub legend: Vec<(String, usize)>,
}

impl Plot for BarChart {
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), String> {
        let log = self.log_y;
        let tr = |v: f64| if log { v.max(1e-300).log10() } else { v };
        let vals: Vec<f64> = self
            .bars
            .iter()
            .filter_map(|b| b.value)
            .filter(|v| v.is_finite() && (!log || *v > 0.0))
            .map(tr)
            .collect();
        let hi = vals.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
        let lo = vals.iter().cloned().fold(f64::INFINITY, f64::min);
        let (y0, y1) = match (lo.is_finite(), log) {
            (false, _) => (0.0, 1.0),
            (true, true) => (lo.floor() - 0.5, hi.ceil() + 0.2),
            (true, false) => (0.0, 1.1 * hi.max(1e-300)),
        };
        let n = self.bars.len().max(1);
        let mut chart = ChartBuilder::on(root)
            .caption(&self.title, text(18))
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(72)
            .build_cartesian_2d((0..n - 1).into_segmented(), y0..y1)
            .map_err(|e| e.to_string())?;
        let labels: Vec<String> = self.bars.iter().map(|b| b.label.clone()).collect();
        let (gs, groups) = (self.group_size, self.groups.clone());
        let fx = move |v: &SegmentValue<usize>| match v {
            SegmentValue::CenterOf(i) if gs > 0 => {
                if i % gs == gs / 2 {
                    groups.get(i / gs).cloned().unwrap_or_default()
                } else {
                    String::new()
                }
            }
            SegmentValue::CenterOf(i) => labels.get(*i).cloned().unwrap_or_default(),
            _ => String::new(),
        };
        let fy = move |v: &f64| tick(*v, log);
        chart
            .configure_mesh()
            .disable_x_mesh()
            .x_labels(n + 1)
            .y_desc(&self.y_label)
            .label_style(text(12))
            .axis_desc_style(text(15))
            .x_label_formatter(&fx)
            .y_label_formatter(&fy)
            .light_line_style(RGBColor(240, 240, 240))
            .bold_line_style(RGBColor(215, 215, 215))
            .draw()
            .map_err(|e| e.to_string())?;
        for (i, b) in self.bars.iter().enumerate() {
            match b.value.filter(|v| v.is_finite() && (!log || *v > 0.0)) {
                Some(v) => {
                    let mut r = Rectangle::new(
                        [
                            (SegmentValue::Exact(i), y0),
                            (SegmentValue::Exact(i + 1), tr(v)),
                        ],
                        color(b.color).filled(),
                    );
                    r.set_margin(0, 0, 8, 8);
                    chart
                        .draw_series(std::iter::once(r))
                        .map_err(|e| e.to_string())?;
                }
                None => {
                    chart
                        .draw_series(std::iter::once(Text::new(
                            "failed",
                            (SegmentValue::CenterOf(i), y0 + 0.05 * (y1 - y0)),
                            text(12).color(&RED),
                        )))
                        .map_err(|e| e.to_string())?;
                }
            }
        }
        for (label, c) in &self.legend {
            let c = color(*c);
            chart
                .draw_series(std::iter::empty::<Rectangle<(SegmentValue<usize>, f64)>>())
                .map_err(|e| e.to_string())?
                .label(label.clone())
                .legend(move |(x, y)| Rectangle::new([(x, y - 5), (x + 14, y + 5)], c.filled()));
        }
        if !self.legend.is_empty() {
            chart
                .configure_series_labels()
                .label_font(text(12))
                .background_style(WHITE.mix(0.85))
                .border_style(RGBColor(180, 180, 180))
                .position(SeriesLabelPosition::UpperRight)
                .draw()
                .map_err(|e| e.to_string())?;
        }
        Ok(())
    }
}
