#!/usr/bin/env python3
"""Prints BENCHMARKS.md's avian section from the criterion results of
crates/stickslip-avian/benches/avian_step.rs (the groups avian_rest_N and avian_slide_N in the
criterion directory given as the only argument): each setup's mean step time and its ratio to
plain avian measured in the same run, against the targets (at rest 1.1x, active 1.25x)."""
import json
import pathlib
import sys

root = pathlib.Path(sys.argv[1])
SCENES = [("avian_rest", "at rest", 1.10), ("avian_slide", "active (sliding)", 1.25)]
SETUPS = [("static_coefficient", "avian's `Friction` with a static coefficient"),
          ("ep", "stickslip's default EP material on every collider")]


def mean_ms(group: pathlib.Path, setup: str) -> float:
    est = json.loads((group / setup / "new" / "estimates.json").read_text())
    return est["mean"]["point_estimate"] / 1e6


print("## stickslip in avian (avian3d 0.7)\n")
print("From `cargo bench -p stickslip-avian --bench avian_step` in the same run "
      "(`crates/stickslip-avian/benches/avian_step.rs`): 400 boxes on a floor, sleeping off, "
      "60 Hz, 6 substeps; every setup beside plain avian with the same `Friction` "
      "components. Mean step time (criterion).\n")
print("| scene | plain avian | setup | stickslip | ÷ plain | target | verdict |")
print("|---|---|---|---|---|---|---|")
for prefix, label, target in SCENES:
    groups = sorted(root.glob(f"{prefix}_*"))
    if not groups:
        print(f"| {label} | not run | | | | ≤ {target:.2f}× | not run |")
        continue
    group = groups[-1]
    plain = mean_ms(group, "plain_avian")
    for setup, what in SETUPS:
        t = mean_ms(group, setup)
        ratio = t / plain
        verdict = "met" if ratio <= target else "**missed**"
        print(f"| {label}, `{group.name}` | {plain:.3f} ms | {what} | {t:.3f} ms | "
              f"{ratio:.2f}× | ≤ {target:.2f}× | {verdict} |")
print()
