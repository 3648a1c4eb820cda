//! Printing results as aligned tables or JSON.

use crate::CliError;
use serde::Serialize;
use std::io::Write;

/// `println!` for results: when stdout is closed (`stickslip … | head`) the process ends
/// quietly with success, as `head` users expect, instead of panicking.
macro_rules! out {
    ($($arg:tt)*) => {
        $crate::output::line(format_args!($($arg)*))
    };
}

/// Writes one line to stdout (see [`out!`]).
pub fn line(args: std::fmt::Arguments) {
    let mut stdout = std::io::stdout().lock();
    if let Err(e) = writeln!(stdout, "{args}").and_then(|()| stdout.flush()) {
        if e.kind() == std::io::ErrorKind::BrokenPipe {
            std::process::exit(0);
        }
        eprintln!("error: cannot write the output: {e}");
        std::process::exit(1);
    }
}

/// Prints `value` as pretty JSON.
pub fn json<T: Serialize>(value: &T) -> Result<(), CliError> {
    out!("{}", serde_json::to_string_pretty(value)?);
    Ok(())
}

/// Prints `rows` of `(label, value)` pairs aligned in two columns.
pub fn pairs(rows: &[(&str, String)]) {
    let width = rows
        .iter()
        .map(|(k, _)| k.chars().count())
        .max()
        .unwrap_or(0);
    for (k, v) in rows {
        out!("{k:<width$}  {v}");
    }
}
