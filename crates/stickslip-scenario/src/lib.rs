//! # stickslip-scenario
//!
//! Scenario files for stickslip: a TOML description of a rapier scene — gravity, time step and
//! solver settings, bodies and colliders, friction materials (any core
//! [`Law`](stickslip_core::law::Law)), vibration sources, drivers (kinematic drags, springs to
//! moving anchors, time-dependent forces), run length and logging — and a headless
//! [`Runner`] that steps it and summarizes what happened.
//!
//! The format is documented on the types of [`spec`]; the shipped examples live in the
//! workspace's `scenarios/` folder, and [`Scenario::builtin`] is the one a bare
//! `stickslip run` uses.
//!
//! ```
//! use stickslip_scenario::{Runner, Scenario};
//!
//! let scenario = Scenario::builtin();
//! let mut runner = Runner::new(scenario.build().expect("the built-in scenario is valid"));
//! runner.run(30);
//! let summary = runner.summary();
//! assert_eq!(summary.steps, 30);
//! assert!(summary.finite);
//!
//! // Errors name the field and the line.
//! let err = Scenario::from_toml_str("name = \"x\"\n[world]\ndt = \"fast\"\n").unwrap_err();
//! assert_eq!(err.field(), Some("world.dt"));
//! assert_eq!(err.line(), Some(3));
//! ```
#![warn(missing_docs)]

mod build;
mod drive;
mod error;
pub mod limits;
pub mod prelude;
mod runner;
pub mod spec;

pub use build::{Driver, DriverAction, Scene, SceneBody, SceneCollider};
pub use drive::apply_drivers;
pub use error::{BuildError, ParseError, ScenarioError};
pub use runner::{BodySummary, RegimeCounts, Runner, Summary};
pub use spec::Scenario;

use std::path::Path;

/// The built-in scenario's TOML (`scenarios/showcase.toml`: three inclined troughs — EP holding,
/// EP conveying under ultrasonic vibration, plain rapier friction).
pub const BUILTIN_TOML: &str = include_str!("showcase.toml");

impl Scenario {
    /// Parses and validates a scenario. `origin` names the source in errors.
    pub fn from_toml_str_named(text: &str, origin: &str) -> Result<Scenario, ScenarioError> {
        let de =
            toml::Deserializer::parse(text).map_err(|e| error::syntax_error(origin, text, e))?;
        let scenario: Scenario = serde_path_to_error::deserialize(de)
            .map_err(|e| error::parse_error(origin, text, e))?;
        scenario
            .validate()
            .map_err(|source| ScenarioError::Invalid {
                origin: origin.to_string(),
                line: error::locate(text, source.field()).map(|(l, _)| l),
                source: Box::new(source),
            })?;
        Ok(scenario)
    }

    /// Parses and validates a scenario from TOML text.
    pub fn from_toml_str(text: &str) -> Result<Scenario, ScenarioError> {
        Scenario::from_toml_str_named(text, "<string>")
    }

    /// Reads, parses and validates a scenario file.
    pub fn from_path(path: impl AsRef<Path>) -> Result<Scenario, ScenarioError> {
        let path = path.as_ref();
        let text = std::fs::read_to_string(path).map_err(|source| ScenarioError::Io {
            path: path.display().to_string(),
            source,
        })?;
        Scenario::from_toml_str_named(&text, &path.display().to_string())
    }

    /// The built-in default scenario ([`BUILTIN_TOML`]).
    pub fn builtin() -> Scenario {
        Scenario::from_toml_str_named(BUILTIN_TOML, "<built-in>")
            .expect("the built-in scenario is valid (checked by tests)")
    }

    /// The scenario as TOML.
    pub fn to_toml_string(&self) -> Result<String, toml::ser::Error> {
        toml::to_string(self)
    }
}
