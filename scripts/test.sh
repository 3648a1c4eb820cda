#!/usr/bin/env bash
# The test suite (README's test command): `bash scripts/test.sh` from the repository root.
# Installs what the tests need, then runs every test of the workspace, and the rapier tests
# once more with rapier's multi-threaded `parallel` feature (the contact hook then runs on
# several threads).
set -euo pipefail
cd "$(dirname "$0")/.."

# One package and feature selection for every cargo command (each dependency builds once).
source scripts/cargo_selection.sh

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

# Every test of the workspace, the bevy add-ons with their optional parts (contact gizmos,
# scenario files as bevy_rapier entities; the windowed examples are built here and run by
# scripts/bevy_screenshot.sh in .ci/run). The workspace includes stickslip-rapier-035 and
# stickslip-fixtures-035: stickslip-rapier's sources and the rapier test suite
# (crates/stickslip-fixtures/tests) built against rapier3d 0.35.0-glamx0.2, the rapier
# bevy_rapier3d 0.36 pins, besides 0.36.1.
# (STICKSLIP_TIMINGS=--timings writes cargo's per-crate timing report; .ci/run sets it.)
cargo test --workspace --features "$STICKSLIP_FEATURES" ${STICKSLIP_TIMINGS:-}
# The rapier tests that exercise the hook on several threads, once more with rapier's
# multi-threaded `parallel` feature, in 3D (stickslip-fixtures) and in 2D (stickslip-fixtures2d
# builds the same files for rapier2d).
cargo test --workspace --exclude stickslip-fixtures-035 --features "$STICKSLIP_PARALLEL_FEATURES" \
    --test rapier_many_contacts --test rapier_popov --test rapier_snapshot --test rapier_drive \
    --test shared_world --test rapier_recycling --test rapier_load_jump
