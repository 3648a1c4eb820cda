//! Several charts on one canvas.

use super::{Plot, text};
use plotters::coord::Shift;
use plotters::prelude::*;

/// Panels laid out row by row in `cols` columns under an optional overall title.
#[derive(Debug, Clone, PartialEq)]
pub struct Grid<P> {
    /// Overall title.
    pub title: Option<String>,
    /// Columns (≥ 1).
    pub cols: usize,
    /// The panels.
    pub panels: Vec<P>,
}

impl<P: Plot> Plot for Grid<P> {
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), String> {
        let area = match &self.title {
            Some(t) => root.titled(t, text(22)).map_err(|e| e.to_string())?,
            None => root.clone(),
        };
        let cols = self.cols.max(1);
        let rows = self.panels.len().div_ceil(cols).max(1);
        for (a, p) in area.split_evenly((rows, cols)).iter().zip(&self.panels) {
            p.draw(a)?;
        }
        Ok(())
    }
}
