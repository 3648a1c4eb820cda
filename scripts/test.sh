#!/usr/bin/env bash
# The test suite (README's test command): `bash scripts/test.sh` from the repository root.
# Installs what the tests need, then runs every test of the workspace, and the rapier tests
# once more with rapier's multi-threaded `parallel` feature (the contact hook then runs on
# several threads).
set -euo pipefail
cd "$(dirname "$0")/.."

export CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-$HOME/.cache/stickslip-target}"
export CARGO_TERM_COLOR="${CARGO_TERM_COLOR:-never}"

# The rerun CLI from PyPI `rerun-sdk` (its version must match the `rerun` crate, 0.36.3),
# in a venv under ~/.cache/stickslip. STICKSLIP_RERUN_CLI is the path of its `rerun` binary:
# crates/stickslip-cli/tests/cli_run.rs uses it to verify written .rrd files with rerun's own
# `rrd verify`/`rrd print` and to receive a live stream (`rerun --test-receive`).
RERUN_SDK_VERSION=0.36.3
install_rerun_cli() {
    local venv="$HOME/.cache/stickslip/rerun-sdk-$RERUN_SDK_VERSION"
    if [ ! -x "$venv/bin/rerun" ]; then
        python3 -m venv "$venv"
        "$venv/bin/python" -m pip install --quiet --disable-pip-version-check \
            "rerun-sdk==$RERUN_SDK_VERSION"
    fi
    "$venv/bin/rerun" analytics disable >/dev/null 2>&1 || true
    "$venv/bin/rerun" --version
    export STICKSLIP_RERUN_CLI="$venv/bin/rerun"
}
install_rerun_cli

# The workspace includes stickslip-rapier-035 and stickslip-035: stickslip-rapier's sources and
# the rapier test files (tests/rapier_*.rs, tests/ordinary_*.rs) built against rapier3d
# 0.35.0-glamx0.2, the rapier bevy_rapier3d 0.36 pins, besides 0.36.1.
cargo test --workspace
# The bevy add-ons with their optional parts, headless: stickslip-bevy (bevy_rapier) with
# contact gizmos (`debug`) and scenario files as bevy_rapier entities (`scenario`), and
# stickslip-avian (avian3d) with its contact gizmos (`debug`); their tests and doc tests. One
# invocation, so that one bevy build serves both (avian asks bevy_math for `approx`); the
# windowed examples are built and run by scripts/bevy_screenshot.sh in .ci/run.
cargo test -p stickslip-bevy -p stickslip-avian \
    --features stickslip-bevy/debug,stickslip-bevy/scenario,stickslip-avian/debug
cargo test -p stickslip --features parallel --test rapier_many_contacts --test rapier_popov --test rapier_snapshot --test rapier_drive --test shared_world --test rapier_recycling --test rapier_load_jump
# The 2D adapter (rapier2d) with rapier's multi-threaded `parallel` feature as well.
cargo test -p stickslip-rapier2d --features parallel --test snapshot --test shared_world --test stacks
