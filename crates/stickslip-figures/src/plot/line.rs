//! Line and point charts, optionally on log axes.

use super::{Plot, bounds, color, text, tick};
use plotters::coord::Shift;
use plotters::prelude::*;

/// How a series is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mark {
    /// A solid line.
    Line,
    /// A dashed line.
    Dashed,
    /// Filled circles (measured points).
    Points,
    /// Crosses (measured points of a second kind).
    Crosses,
}

/// One labelled series.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// Legend label (empty: not in the legend).
    pub label: String,
    /// x values.
    pub x: Vec<f64>,
    /// y values.
    pub y: Vec<f64>,
    /// How it is drawn.
    pub mark: Mark,
    /// Palette index ([`super::color`]).
    pub color: usize,
}

impl Series {
    /// A series from `(x, y)` pairs.
    pub fn new(label: impl Into<String>, points: &[(f64, f64)], mark: Mark, color: usize) -> Self {
        Series {
            label: label.into(),
            x: points.iter().map(|p| p.0).collect(),
            y: points.iter().map(|p| p.1).collect(),
            mark,
            color,
        }
    }
}

/// An x–y chart.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct LineChart {
    /// Caption.
    pub title: String,
    /// x-axis label.
    pub x_label: String,
    /// y-axis label.
    pub y_label: String,
    /// The series.
    pub series: Vec<Series>,
    /// Logarithmic x axis (non-positive values are dropped).
    pub log_x: bool,
    /// Logarithmic y axis (non-positive values are dropped).
    pub log_y: bool,
    /// Vertical guide lines at these x values (e.g. phase boundaries).
    pub vlines: Vec<f64>,
    /// Labels written along the top at these x values.
    pub annotations: Vec<(f64, String)>,
    /// Legend at the lower right instead of the upper right.
    pub legend_lower: bool,
    /// Fixed y range (in data units) instead of the data's.
    pub y_range: Option<(f64, f64)>,
}

fn axis(v: f64, log: bool) -> Option<f64> {
    let a = if log {
        if v > 0.0 { v.log10() } else { return None }
    } else {
        v
    };
    a.is_finite().then_some(a)
}

impl LineChart {
    fn points(&self, s: &Series) -> Vec<(f64, f64)> {
        s.x.iter()
            .zip(&s.y)
            .filter_map(|(&x, &y)| Some((axis(x, self.log_x)?, axis(y, self.log_y)?)))
            .collect()
    }
}

impl Plot for LineChart {
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), String> {
        let pts: Vec<Vec<(f64, f64)>> = self.series.iter().map(|s| self.points(s)).collect();
        let x = bounds(pts.iter().flatten().map(|p| p.0));
        let y = match self.y_range {
            Some((lo, hi)) => (
                axis(lo, self.log_y).unwrap_or(0.0),
                axis(hi, self.log_y).unwrap_or(1.0),
            ),
            None => bounds(
                pts.iter()
                    .flatten()
                    .map(|p| p.1)
                    .chain(self.annotations.iter().map(|_| f64::NAN)),
            ),
        };
        // Room above the data for the annotations.
        let y = if self.annotations.is_empty() {
            y
        } else {
            (y.0, y.1 + 0.08 * (y.1 - y.0))
        };
        let mut chart = ChartBuilder::on(root)
            .caption(&self.title, text(18))
            .margin(12)
            .x_label_area_size(42)
            .y_label_area_size(72)
            .build_cartesian_2d(x.0..x.1, y.0..y.1)
            .map_err(|e| e.to_string())?;
        let (log_x, log_y) = (self.log_x, self.log_y);
        let fx = move |v: &f64| tick(*v, log_x);
        let fy = move |v: &f64| tick(*v, log_y);
        chart
            .configure_mesh()
            .x_desc(&self.x_label)
            .y_desc(&self.y_label)
            .label_style(text(13))
            .axis_desc_style(text(15))
            .x_label_formatter(&fx)
            .y_label_formatter(&fy)
            .light_line_style(RGBColor(240, 240, 240))
            .bold_line_style(RGBColor(215, 215, 215))
            .draw()
            .map_err(|e| e.to_string())?;
        let grey = RGBColor(110, 110, 110);
        for &v in &self.vlines {
            if let Some(v) = axis(v, self.log_x) {
                chart
                    .draw_series(DashedLineSeries::new(
                        [(v, y.0), (v, y.1)],
                        6,
                        4,
                        grey.stroke_width(1),
                    ))
                    .map_err(|e| e.to_string())?;
            }
        }
        for (v, label) in &self.annotations {
            if let Some(v) = axis(*v, self.log_x) {
                chart
                    .draw_series(std::iter::once(Text::new(
                        label.clone(),
                        (v, y.1 - 0.01 * (y.1 - y.0)),
                        text(17).color(&grey),
                    )))
                    .map_err(|e| e.to_string())?;
            }
        }
        let mut legend = false;
        for (s, p) in self.series.iter().zip(pts) {
            let c = color(s.color);
            // plotters joins wide polylines with miters, which shoot far out of the chart at
            // sharp reversals: series that reverse often (oscillations) are drawn 1 px wide.
            let reversals = p
                .windows(3)
                .filter(|w| (w[1].1 - w[0].1) * (w[2].1 - w[1].1) < 0.0)
                .count();
            let width = if reversals > 10 { 1 } else { 2 };
            let anno = match s.mark {
                Mark::Line => chart.draw_series(LineSeries::new(p, c.stroke_width(width))),
                Mark::Dashed => {
                    chart.draw_series(DashedLineSeries::new(p, 8, 5, c.stroke_width(width)))
                }
                Mark::Points => {
                    chart.draw_series(p.into_iter().map(move |q| Circle::new(q, 5, c.filled())))
                }
                Mark::Crosses => chart.draw_series(
                    p.into_iter()
                        .map(move |q| Cross::new(q, 6, c.stroke_width(2))),
                ),
            }
            .map_err(|e| e.to_string())?;
            if !s.label.is_empty() {
                legend = true;
                let mark = s.mark;
                anno.label(s.label.clone())
                    .legend(move |(x, y)| match mark {
                        Mark::Points => Circle::new((x + 10, y), 5, c.filled()).into_dyn(),
                        Mark::Crosses => Cross::new((x + 10, y), 6, c.stroke_width(2)).into_dyn(),
                        _ => PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(2))
                            .into_dyn(),
                    });
            }
        }
        if legend {
            chart
                .configure_series_labels()
                .label_font(text(13))
                .background_style(WHITE.mix(0.85))
                .border_style(RGBColor(180, 180, 180))
                .position(if self.legend_lower {
                    SeriesLabelPosition::LowerRight
                } else {
                    SeriesLabelPosition::UpperRight
                })
                .draw()
                .map_err(|e| e.to_string())?;
        }
        Ok(())
    }
}
