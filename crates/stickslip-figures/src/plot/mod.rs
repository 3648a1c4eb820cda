//! Drawing figures with plotters, to PNG and SVG from the same code.
//!
//! Every chart type implements [`Plot`] for any plotters backend; [`save`] draws one to
//! `NAME.png` and `NAME.svg`.

mod bars;
mod grid;
mod heatmap;
mod line;

pub use bars::{Bar, BarChart};
pub use grid::Grid;
pub use heatmap::HeatMap;
pub use line::{LineChart, Mark, Series};

use crate::FigureError;
use crate::font;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::{Path, PathBuf};

/// A chart that can draw itself on any plotters drawing area.
pub trait Plot {
    /// Draws onto `root` (already filled white); the error is the backend's message.
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), String>;
}

/// Draws `plot` to `dir/NAME.png` and `dir/NAME.svg` at `size` pixels; returns both paths.
pub fn save<P: Plot>(
    plot: &P,
    dir: &Path,
    name: &str,
    size: (u32, u32),
) -> Result<[PathBuf; 2], FigureError> {
    let png = save_png(plot, dir, name, size)?;
    let draw_err = |message: String| FigureError::Draw {
        figure: name.to_string(),
        message,
    };
    let svg = dir.join(format!("{name}.svg"));
    {
        let root = SVGBackend::new(&svg, size).into_drawing_area();
        root.fill(&WHITE).map_err(|e| draw_err(e.to_string()))?;
        plot.draw(&root).map_err(draw_err)?;
        root.present().map_err(|e| draw_err(e.to_string()))?;
    }
    Ok([png, svg])
}

/// Draws `plot` to `dir/NAME.png` only; returns its path.
pub fn save_png<P: Plot>(
    plot: &P,
    dir: &Path,
    name: &str,
    size: (u32, u32),
) -> Result<PathBuf, FigureError> {
    font::register()?;
    let draw_err = |message: String| FigureError::Draw {
        figure: name.to_string(),
        message,
    };
    let png = dir.join(format!("{name}.png"));
    {
        let root = BitMapBackend::new(&png, size).into_drawing_area();
        root.fill(&WHITE).map_err(|e| draw_err(e.to_string()))?;
        plot.draw(&root).map_err(draw_err)?;
        root.present().map_err(|e| draw_err(e.to_string()))?;
    }
    Ok(png)
}

/// The colour of series `i` (the tab10 palette, repeating).
pub fn color(i: usize) -> RGBColor {
    const TAB10: [(u8, u8, u8); 10] = [
        (31, 119, 180),
        (255, 127, 14),
        (44, 160, 44),
        (214, 39, 40),
        (148, 103, 189),
        (140, 86, 75),
        (227, 119, 194),
        (127, 127, 127),
        (188, 189, 34),
        (23, 190, 207),
    ];
    let (r, g, b) = TAB10[i % TAB10.len()];
    RGBColor(r, g, b)
}

/// Text style of titles, labels and legends at `size` px.
pub(crate) fn text(size: u32) -> TextStyle<'static> {
    (font::FAMILY, size).into_font().into()
}

/// A tick label: plain on a linear axis, 10^v on a log axis (data are plotted as log10).
pub(crate) fn tick(v: f64, log: bool) -> String {
    if log {
        let p = 10f64.powf(v);
        if (v - v.round()).abs() < 1e-9 {
            format!("1e{}", v.round() as i64)
        } else {
            format!("{p:.1e}")
        }
    } else if v != 0.0 && (v.abs() >= 1e4 || v.abs() < 1e-3) {
        format!("{v:.1e}")
    } else {
        let s = format!("{v:.4}");
        let s = s.trim_end_matches('0').trim_end_matches('.');
        if s == "-0" { "0".into() } else { s.into() }
    }
}

/// `[lo, hi]` covering `values` with 5 % padding (a unit span around a single value).
pub(crate) fn bounds(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
    if !lo.is_finite() {
        return (0.0, 1.0);
    }
    if hi - lo <= 1e-12 * lo.abs().max(1e-300) {
        let d = if lo == 0.0 { 1.0 } else { 0.1 * lo.abs() };
        return (lo - d, hi + d);
    }
    let pad = 0.05 * (hi - lo);
    (lo - pad, hi + pad)
}
