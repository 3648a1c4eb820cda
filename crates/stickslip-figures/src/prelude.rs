//! What most users of the figures name: `use stickslip_figures::prelude::*;`.
pub use crate::{FigureError, Size, generate};
