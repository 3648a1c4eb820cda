//! `stickslip`: the command-line front end.
//!
//! `main` parses the arguments; each subcommand lives in its own module with a `run` function
//! that returns a typed error, so bad input ends in a clear message and a non-zero exit code,
//! never a panic.

#[macro_use]
mod output;
mod block_cmd;
mod figures_cmd;
mod run_cmd;
mod showcase;
mod sweep_cmd;
mod theory_cmd;

use clap::{Parser, Subcommand};
use std::process::ExitCode;

/// Elasto-plastic friction with vibration effects: theory, reference simulations and runs.
#[derive(Debug, Parser)]
#[command(name = "stickslip", version, about)]
struct Cli {
    /// Print machine-readable JSON instead of tables.
    #[arg(long, global = true)]
    json: bool,
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Popov's vibration theory: Ψ_w(β), effective and static friction coefficients.
    Theory(theory_cmd::TheoryArgs),
    /// The seed's Example 1: a block under a time-dependent force, any law.
    Block(block_cmd::BlockArgs),
    /// Run a scenario file headless; stream it to rerun (live viewer and/or .rrd file).
    Run(run_cmd::RunArgs),
    /// Draw the user guide's figures (PNG and SVG) and write their checked data (figures.json).
    Figures(figures_cmd::FiguresArgs),
    /// Parameter sweeps over independent rapier worlds in parallel (CSV, JSON, heat maps).
    Sweep(sweep_cmd::SweepArgs),
}

/// Errors a subcommand reports to the user.
#[derive(Debug, thiserror::Error)]
pub enum CliError {
    /// Invalid parameters.
    #[error("invalid parameter: {0}")]
    Param(#[from] stickslip_core::ParamError),
    /// Invalid argument syntax the parser could not catch.
    #[error("invalid argument: {0}")]
    Argument(String),
    /// The simulation failed.
    #[error("simulation failed: {0}")]
    Sim(#[from] stickslip_theory::block::SimError),
    /// Writing output failed.
    #[error("output failed: {0}")]
    Output(#[from] serde_json::Error),
    /// A scenario file could not be read, parsed or validated.
    #[error("{0}")]
    Scenario(#[from] stickslip_scenario::ScenarioError),
    /// A scenario could not be built into a world.
    #[error("invalid scenario: {0}")]
    Build(#[from] stickslip_scenario::BuildError),
    /// Logging to rerun failed.
    #[error("rerun: {0}")]
    Rerun(#[from] stickslip_rerun::LogError),
    /// A figure or a sweep could not be produced.
    #[error("{0}")]
    Figures(#[from] stickslip_figures::FigureError),
    /// A file operation failed.
    #[error("{0}")]
    Io(String),
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match &cli.command {
        Command::Theory(args) => theory_cmd::run(args, cli.json),
        Command::Block(args) => block_cmd::run(args, cli.json),
        Command::Run(args) => run_cmd::run(args, cli.json),
        Command::Figures(args) => figures_cmd::run(args, cli.json),
        Command::Sweep(args) => sweep_cmd::run(args, cli.json),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}
