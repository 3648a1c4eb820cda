#!/usr/bin/env python3
"""Prints BENCHMARKS.md's kernel section from the criterion results of
crates/stickslip-core/benches/kernel.rs (the group kernel/step/<class> in the criterion directory
given as the only argument): each class's mean time per contact step (criterion's mean per
iteration over the class's recorded steps) against the targets (mean over the classes at most
100 ns, every class at most 300 ns)."""
import json
import pathlib
import sys

root = pathlib.Path(sys.argv[1]) / "kernel" / "step"
CLASSES = [
    ("hold", "a loaded contact held at 0.6 of its capacity"),
    ("slide", "a steady slide at 0.1 m/s (the exact α = 1 solution)"),
    ("creep", "a steady slide at 5 mm/s, just below the band's top"),
    ("approach", "the creep with the normal force ±2 % every step"),
    ("enter", "break-away over and over (8 steps held, 8 slipping at 1 mm/s)"),
    ("reverse", "a slide at 5 mm/s reversing every 4 steps"),
    ("turn", "a slide at 5 mm/s turning by 30° every step"),
    ("turn_sharp", "the same on a sharp band (μ_ba = μ_max)"),
    ("vibrating", "a slide at 0.1 m/s under normal vibration (ratio 0.5, 20 Hz)"),
]


def per_step_ns(name: str):
    d = root / name
    try:
        est = json.loads((d / "new" / "estimates.json").read_text())
        n = json.loads((d / "new" / "benchmark.json").read_text())["throughput"]["Elements"]
    except (OSError, KeyError, ValueError):
        return None
    return est["mean"]["point_estimate"] / n


print("## The contact kernel alone\n")
print("From `cargo bench -p stickslip-core --bench kernel` in the same run "
      "(`crates/stickslip-core/benches/kernel.rs`): `contact::step_contact` replayed on the "
      "states and inputs a closed loop records for each class (the bench law: c = 1e4 /m, "
      "μ_ba 0.5, μ_max 0.55, flat curve, 10 N, 60 Hz). Mean time per contact step "
      "(criterion). Targets: at most 100 ns over the classes, 300 ns in the worst class.\n")
print("| class | what it records | ns per step | target | verdict |")
print("|---|---|---|---|---|")
times = []
for name, what in CLASSES:
    t = per_step_ns(name)
    if t is None:
        print(f"| `{name}` | {what} | not run | ≤ 300 | not run |")
        continue
    times.append(t)
    verdict = "met" if t <= 300 else "**missed**"
    print(f"| `{name}` | {what} | {t:.0f} | ≤ 300 | {verdict} |")
if times:
    mean = sum(times) / len(times)
    verdict = "met" if mean <= 100 else "**missed**"
    print(f"| mean over the classes | | {mean:.0f} | ≤ 100 | {verdict} |")
    everything = per_step_ns("all")
    if everything is not None:
        print(f"| `all` (every class's steps in one sequence) | | {everything:.0f} | — | — |")
print()
