//! The error type of figures and sweeps.

use std::path::PathBuf;
use thiserror::Error;

/// Why a figure or a sweep could not be produced.
#[derive(Debug, Error)]
pub enum FigureError {
    /// A physical parameter is out of range.
    #[error("invalid parameter: {0}")]
    Param(#[from] stickslip_core::ParamError),
    /// A reference simulation failed.
    #[error("simulation failed: {0}")]
    Sim(#[from] stickslip_theory::block::SimError),
    /// A range `LO:HI:N` is malformed or out of its domain.
    #[error("invalid range `{text}` for {name}: {reason}")]
    Range {
        /// The option it was given for.
        name: String,
        /// The text as given.
        text: String,
        /// What is wrong with it.
        reason: String,
    },
    /// A sweep has more points than it may.
    #[error("the sweep has {count} points, more than the limit of {limit}")]
    TooManyPoints {
        /// Points requested (saturating).
        count: u64,
        /// The limit.
        limit: u64,
    },
    /// An option value is invalid (e.g. an empty waveform list, zero threads).
    #[error("invalid option {name}: {reason}")]
    Option {
        /// The option.
        name: String,
        /// What is wrong with it.
        reason: String,
    },
    /// Drawing a figure failed.
    #[error("drawing {figure} failed: {message}")]
    Draw {
        /// The figure's file name.
        figure: String,
        /// The backend's message.
        message: String,
    },
    /// A file or directory could not be written.
    #[error("cannot write {}: {message}", path.display())]
    Io {
        /// The path.
        path: PathBuf,
        /// The system's message.
        message: String,
    },
    /// Serializing results failed.
    #[error("JSON: {0}")]
    Json(#[from] serde_json::Error),
    /// The worker thread pool could not be built.
    #[error("thread pool: {0}")]
    Threads(String),
}

impl FigureError {
    /// An [`FigureError::Io`] for `path`.
    pub fn io(path: impl Into<PathBuf>, e: std::io::Error) -> Self {
        FigureError::Io {
            path: path.into(),
            message: e.to_string(),
        }
    }
}
