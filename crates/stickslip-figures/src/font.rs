//! The embedded font: DejaVu Sans (Bitstream Vera license, `assets/DejaVuSans-LICENSE.txt`),
//! registered with plotters under its own name and the generic families plotters' defaults
//! use, so no system font is needed (plotters' `ttf` feature would look them up with
//! font-kit).

use crate::FigureError;
use plotters::style::{FontStyle, register_font};
use std::sync::OnceLock;

/// The family name every figure uses.
pub const FAMILY: &str = "DejaVu Sans";

static BYTES: &[u8] = include_bytes!("../assets/DejaVuSans.ttf");

/// Registers the font once per process (later calls return the first outcome).
pub fn register() -> Result<(), FigureError> {
    static DONE: OnceLock<bool> = OnceLock::new();
    let ok = *DONE.get_or_init(|| {
        [FAMILY, "sans-serif", "serif", "monospace"]
            .iter()
            .flat_map(|name| {
                [
                    FontStyle::Normal,
                    FontStyle::Bold,
                    FontStyle::Italic,
                    FontStyle::Oblique,
                ]
                .map(|style| register_font(name, style, BYTES).is_ok())
            })
            .all(|ok| ok)
    });
    if ok {
        Ok(())
    } else {
        Err(FigureError::Draw {
            figure: "font".into(),
            message: "the embedded DejaVu Sans could not be parsed".into(),
        })
    }
}
