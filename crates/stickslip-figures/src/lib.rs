//! stickslip's figures and parameter sweeps.
//!
//! - [`data`]: the numbers behind each figure, as plain series structs, from the core's
//!   theory and reference simulators and from real rapier worlds (its private `scenes` module).
//! - [`plot`]: drawing those series with plotters to PNG and SVG (an embedded font,
//!   [`font`], so the output is the same on every machine).
//! - [`figures`]: every figure of the user guide in one call, [`figures::generate`].
//! - [`sweep`]: Popov maps (μ̄ over β × α per waveform) and vibratory-feeder maps (transport
//!   speed over amplitude × frequency × throw angle), each point an independent world, run in
//!   parallel on an explicit rayon pool, written as CSV, JSON and heat maps.
//!
//! Nothing here panics on bad input: every entry point returns a [`FigureError`].

#![warn(missing_docs)]

pub mod data;
pub mod error;
pub mod figures;
pub mod font;
pub mod plot;
pub mod prelude;
// The rapier worlds the figures are drawn from; stickslip-fixtures (unpublished) compiles this
// file too, for the tests. Not everything here is read by the figures.
#[allow(dead_code)]
mod scenes;
pub mod sweep;

pub use error::FigureError;
pub use figures::{Size, generate};
