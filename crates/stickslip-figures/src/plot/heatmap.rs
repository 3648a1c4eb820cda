//! Heat maps of a value over a 2-D parameter grid, with a colour bar.

use super::{Plot, bounds, text, tick};
use plotters::coord::Shift;
use plotters::prelude::*;

/// Values on the grid `xs × ys` (row-major: `values[j * xs.len() + i]` at `(xs[i], ys[j])`);
/// non-finite values are drawn grey.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct HeatMap {
    /// Caption.
    pub title: String,
    /// x-axis label.
    pub x_label: String,
    /// y-axis label.
    pub y_label: String,
    /// Colour-bar label.
    pub value_label: String,
    /// Grid x values, increasing.
    pub xs: Vec<f64>,
    /// Grid y values, increasing.
    pub ys: Vec<f64>,
    /// The values.
    pub values: Vec<f64>,
}

/// A viridis-like map of `t ∈ [0, 1]`.
pub fn viridis(t: f64) -> RGBColor {
    const STOPS: [(f64, f64, f64); 5] = [
        (68.0, 1.0, 84.0),
        (59.0, 82.0, 139.0),
        (33.0, 145.0, 140.0),
        (94.0, 201.0, 98.0),
        (253.0, 231.0, 37.0),
    ];
    let t = if t.is_finite() {
        t.clamp(0.0, 1.0)
    } else {
        0.0
    };
    let s = t * (STOPS.len() - 1) as f64;
    let i = (s.floor() as usize).min(STOPS.len() - 2);
    let w = s - i as f64;
    let (a, b) = (STOPS[i], STOPS[i + 1]);
    let mix = |p: f64, q: f64| (p + w * (q - p)).round() as u8;
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

/// Cell edges around grid values (midpoints; a lone value gets a unit-ish cell).
fn edges(v: &[f64]) -> Vec<f64> {
    match v.len() {
        0 => vec![0.0, 1.0],
        1 => {
            let d = if v[0] == 0.0 { 0.5 } else { 0.1 * v[0].abs() };
            vec![v[0] - d, v[0] + d]
        }
        n => {
            let mut e = Vec::with_capacity(n + 1);
            e.push(v[0] - 0.5 * (v[1] - v[0]));
            for w in v.windows(2) {
                e.push(0.5 * (w[0] + w[1]));
            }
            e.push(v[n - 1] + 0.5 * (v[n - 1] - v[n - 2]));
            e
        }
    }
}

impl Plot for HeatMap {
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), String> {
        let (w, _) = root.dim_in_pixel();
        let (main, bar) = root.split_horizontally(w as i32 - 130);
        let (ex, ey) = (edges(&self.xs), edges(&self.ys));
        let (vlo, vhi) = {
            let (a, b) = bounds(self.values.iter().cloned());
            // bounds() pads by 5 %: undo for the colour scale.
            let pad = (b - a) / 1.1 * 0.05;
            (a + pad, b - pad)
        };
        let span = if vhi > vlo { vhi - vlo } else { 1.0 };
        let mut chart = ChartBuilder::on(&main)
            .caption(&self.title, text(18))
            .margin(12)
            .x_label_area_size(42)
            .y_label_area_size(72)
            .build_cartesian_2d(ex[0]..ex[ex.len() - 1], ey[0]..ey[ey.len() - 1])
            .map_err(|e| e.to_string())?;
        let f = |v: &f64| tick(*v, false);
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc(&self.x_label)
            .y_desc(&self.y_label)
            .label_style(text(13))
            .axis_desc_style(text(15))
            .x_label_formatter(&f)
            .y_label_formatter(&f)
            .draw()
            .map_err(|e| e.to_string())?;
        let nx = self.xs.len();
        let cells = (0..self.ys.len()).flat_map(|j| {
            let ex = &ex;
            let ey = &ey;
            (0..nx).map(move |i| (i, j, ex, ey))
        });
        chart
            .draw_series(cells.map(|(i, j, ex, ey)| {
                let v = self.values.get(j * nx + i).copied().unwrap_or(f64::NAN);
                let c = if v.is_finite() {
                    viridis((v - vlo) / span)
                } else {
                    RGBColor(160, 160, 160)
                };
                Rectangle::new([(ex[i], ey[j]), (ex[i + 1], ey[j + 1])], c.filled())
            }))
            .map_err(|e| e.to_string())?;
        // The colour bar.
        let mut cb = ChartBuilder::on(&bar)
            .margin_top(40)
            .margin_bottom(54)
            .margin_right(10)
            .y_label_area_size(70)
            .build_cartesian_2d(0.0..1.0, vlo..(vlo + span))
            .map_err(|e| e.to_string())?;
        cb.configure_mesh()
            .disable_mesh()
            .disable_x_axis()
            .y_desc(&self.value_label)
            .label_style(text(12))
            .axis_desc_style(text(13))
            .y_label_formatter(&f)
            .draw()
            .map_err(|e| e.to_string())?;
        let steps = 100;
        cb.draw_series((0..steps).map(|k| {
            let a = vlo + span * k as f64 / steps as f64;
            let b = vlo + span * (k + 1) as f64 / steps as f64;
            Rectangle::new(
                [(0.0, a), (1.0, b)],
                viridis((k as f64 + 0.5) / steps as f64).filled(),
            )
        }))
        .map_err(|e| e.to_string())?;
        Ok(())
    }
}
