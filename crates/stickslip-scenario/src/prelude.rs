//! What most users of the scenarios name: `use stickslip_scenario::prelude::*;`.
pub use crate::{Runner, Scenario, ScenarioError, Scene, Summary};
