//! What most users of the rerun sinks name: `use stickslip_rerun::prelude::*;`.
pub use crate::{LogError, LogOptions, RerunLogger, Sink};
