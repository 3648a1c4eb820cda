//! `stickslip figures`: every figure of the user guide as PNG and SVG, plus `figures.json`.

use crate::{CliError, output};
use clap::Args;
use std::path::PathBuf;
use stickslip_figures::Size;

/// Arguments of `stickslip figures`.
#[derive(Debug, Args)]
pub struct FiguresArgs {
    /// Directory to write into (created if missing).
    #[arg(long, default_value = "docs/figures")]
    out: PathBuf,
    /// Small sizes for CI: coarse grids, two rapier points per curve, short runs.
    #[arg(long)]
    quick: bool,
}

/// Runs `stickslip figures`.
pub fn run(args: &FiguresArgs, json: bool) -> Result<(), CliError> {
    let size = if args.quick { Size::Quick } else { Size::Full };
    let started = std::time::Instant::now();
    let summary = stickslip_figures::generate(&args.out, size, &|name| {
        eprintln!("[{:6.1} s] {name}", started.elapsed().as_secs_f64());
    })?;
    if json {
        output::json(&summary)?;
    } else {
        for f in &summary.files {
            out!("{}", f.display());
        }
        out!("{}", args.out.join("figures.json").display());
    }
    Ok(())
}
