#!/usr/bin/env bash
# Long randomized property runs (not part of CI or README's test command, which use a fixed
# seed): `bash scripts/long_tests.sh [CASES]` runs every property test with CASES cases
# (default 20000) and a fresh random seed, printed first so that a failure can be replayed
# with `PROPTEST_RNG_SEED=<seed> PROPTEST_CASES=<cases> cargo test --release ...`.
set -euo pipefail
cd "$(dirname "$0")/.."
export CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-$HOME/.cache/stickslip-target}"
CASES="${1:-20000}"
SEED="${PROPTEST_RNG_SEED:-$(od -An -N8 -tu8 /dev/urandom | tr -d ' ')}"
echo "property tests: $CASES cases, seed $SEED"
export PROPTEST_CASES="$CASES" PROPTEST_RNG_SEED="$SEED"
cargo test --release -p stickslip --test ep_law_properties
cargo test --release -p stickslip-theory --test popov_theory
# The fuzz suites (nothing crashes, hangs or lies): parameters, running worlds, scenario
# files, command lines.
cargo test --release -p stickslip --test fuzz_parameters --test fuzz_world_states
cargo test --release -p stickslip-scenario --test fuzz_scenarios
cargo test --release -p stickslip-cli --test cli_fuzz
