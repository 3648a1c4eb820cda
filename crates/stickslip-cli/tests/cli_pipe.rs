//! A closed output pipe (`stickslip … | head`) ends every subcommand quietly with success:
//! no panic message, exit code 0.

use std::process::{Command, Stdio};

fn closed_pipe(args: &[&str]) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_stickslip"))
        .args(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // Close the reading end before the program writes anything.
    drop(child.stdout.take());
    let out = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        out.status.success(),
        "{args:?}: {:?}, stderr {stderr}",
        out.status
    );
    assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
}

#[test]
fn closed_stdout_is_a_quiet_success() {
    closed_pipe(&["theory", "psi", "--waveform", "sine", "--beta", "2"]);
    closed_pipe(&[
        "theory",
        "psi",
        "--waveform",
        "sine",
        "--beta",
        "2",
        "--json",
    ]);
    closed_pipe(&["block", "--law", "ep"]);
    closed_pipe(&["run", "--steps", "20"]);
}
