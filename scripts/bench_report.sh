#!/usr/bin/env bash
# Runs stickslip's benchmarks and writes BENCHMARKS.md:
#   0. (docs/bench-profile.md, the perf profile the report includes, is written by hand)
#   1. criterion benches `benches/benches/step_cost.rs` (package stickslip-benches) (step time of the same scenes with plain rapier,
#      a no-op hook and stickslip's laws; with STICKSLIP_BENCH_FULL=1 also the ~100k-contact
#      plane) plus their extra pass (contacts, allocations per step, live heap, interleaved
#      timings) into $OUT/cost.json;
#   2. the report binary `benches/src/bin/bench_report` (accuracy in rapier worlds, the seed's EP
#      versus Regul comparison), which reads both and writes the markdown;
#   3. the avian add-on's bench `crates/stickslip-avian/benches/avian_step.rs`, its section
#      appended by scripts/avian_bench_section.py;
#   4. the kernel bench `crates/stickslip-core/benches/kernel.rs`, its section appended by
#      scripts/kernel_bench_section.py.
#
# Usage: scripts/bench_report.sh [--quick] [--out FILE]
#   --quick   skip the ~100k-contact plane (the scaling target is then reported as not run)
#   --out     where to write the report (default: BENCHMARKS.md at the repository root)
# Environment: CARGO_TARGET_DIR (default: target/), extra cargo flags in CARGO_FLAGS.
#
# CI smoke (compiles and runs every bench and every report measurement once, on tiny sizes;
# .ci/run passes the workspace selection of scripts/cargo_selection.sh):
#   cargo test --workspace --bench step_cost --bin bench_report
set -euo pipefail
cd "$(dirname "$0")/.."

full=1
out="BENCHMARKS.md"
while [[ $# -gt 0 ]]; do
    case "$1" in
        --quick) full=0 ;;
        --out) out="$2"; shift ;;
        -h|--help) sed -n '2,20p' "$0"; exit 0 ;;
        *) echo "unknown argument: $1" >&2; exit 2 ;;
    esac
    shift
done

export CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-$PWD/target}"
work="$CARGO_TARGET_DIR/stickslip-bench"
mkdir -p "$work"
export CRITERION_HOME="$work/criterion"
rm -rf "$CRITERION_HOME"

secs() { date +%s; }
t0=$(secs)
# shellcheck disable=SC2086
cargo bench ${CARGO_FLAGS:-} -p stickslip-benches --bench step_cost --no-run
# shellcheck disable=SC2086
cargo build ${CARGO_FLAGS:-} --release -p stickslip-benches --bin bench_report
t1=$(secs)

bench_env=(STICKSLIP_BENCH_OUT="$work/cost.json")
if [[ $full == 1 ]]; then bench_env+=(STICKSLIP_BENCH_FULL=1); fi
# shellcheck disable=SC2086
env "${bench_env[@]}" cargo bench ${CARGO_FLAGS:-} -p stickslip-benches --bench step_cost | tee "$work/bench.log"
# Thread scaling: the same bench built with rapier's `parallel` feature, only its
# thread-scaling pass (pools of 1 and of all threads).
# shellcheck disable=SC2086
STICKSLIP_BENCH_THREADS_OUT="$work/threads.json" \
    cargo bench ${CARGO_FLAGS:-} -p stickslip-benches --features parallel --bench step_cost | tee "$work/threads.log"
t2=$(secs)

build_s=$((t1 - t0))
bench_s=$((t2 - t1))
"$CARGO_TARGET_DIR/release/bench_report" \
    --cost-json "$work/cost.json" \
    --criterion "$CRITERION_HOME" \
    --threads-json "$work/threads.json" \
    --profile docs/bench-profile.md \
    --note "Build (bench + report binaries): $build_s s; criterion benches and their extra pass: $bench_s s$([[ $full == 1 ]] && echo ', ~100k-contact plane included' || echo ', ~100k-contact plane skipped (--quick)')." \
    --out "$out"
# The avian add-on's step cost beside plain avian (its own package: avian and bevy stay out of
# stickslip-benches), appended as its own section.
# shellcheck disable=SC2086
cargo bench ${CARGO_FLAGS:-} -p stickslip-avian --bench avian_step | tee "$work/avian.log"
python3 scripts/avian_bench_section.py "$CRITERION_HOME" >> "$out"
# The engine-free contact kernel alone (per class of recorded contact steps), its own section.
# shellcheck disable=SC2086
cargo bench ${CARGO_FLAGS:-} -p stickslip-core --bench kernel | tee "$work/kernel.log"
python3 scripts/kernel_bench_section.py "$CRITERION_HOME" >> "$out"
t3=$(secs)
echo "build $build_s s, benches $bench_s s, report and avian $((t3 - t2)) s -> $out"
