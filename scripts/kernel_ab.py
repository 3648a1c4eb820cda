#!/usr/bin/env python3
"""Interleaved A/B of the kernel bench (`crates/stickslip-core/benches/kernel.rs`).

    python3 scripts/kernel_ab.py BASE_BIN NEW_BIN ROUNDS [criterion filter]

BASE_BIN and NEW_BIN are two builds of the bench binary (`cargo bench -p stickslip-core
--bench kernel --no-run` in two worktrees with their own CARGO_TARGET_DIR). Each round runs
both, one after the other, with short criterion runs; the script prints per class the
fastest of the rounds' estimates in ns per contact step (the fastest, because this machine's
neighbours only ever slow a run down) and the mean over the classes.
"""
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile

STEPS = 512  # recorded steps per class in the bench's full mode
CLASSES = 9  # `all` replays every class's steps: CLASSES * STEPS

base, new, rounds = sys.argv[1], sys.argv[2], int(sys.argv[3])
filt = sys.argv[4:]
unit = {"ns": 1e-3, "µs": 1.0, "us": 1.0, "ms": 1e3}
res = {"base": {}, "new": {}}
for _ in range(rounds):
    for name, binary in (("base", base), ("new", new)):
        home = tempfile.mkdtemp()
        # The full mode's recorded steps (STEPS a class), whatever the caller's environment.
        env = {k: v for k, v in os.environ.items() if k != "STICKSLIP_BENCH_QUICK"}
        env["CRITERION_HOME"] = home
        args = [binary, "--bench", "--warm-up-time", "0.5", "--measurement-time", "1.5", "--noplot"]
        run = subprocess.run(args + filt, capture_output=True, text=True, env=env)
        shutil.rmtree(home, ignore_errors=True)
        if run.returncode != 0:
            sys.exit(f"{binary} failed ({run.returncode}):\n{run.stderr}")
        out = run.stdout
        cls = None
        for line in out.splitlines():
            m = re.match(r"^kernel/step/(\S+)", line)
            if m:
                cls = m.group(1)
            t = re.search(r"time:\s+\[\S+ \S+ (\S+) (\S+)", line)
            if t and cls:
                steps = STEPS * (CLASSES if cls == "all" else 1)
                ns = float(t.group(1)) * unit[t.group(2)] * 1000 / steps
                res[name].setdefault(cls, []).append(ns)
                cls = None
for cls, runs in res["base"].items():
    b, n = min(runs), min(res["new"].get(cls, [float("nan")]))
    print(f"{cls:12} base {b:6.1f}  new {n:6.1f}  {100 * (n / b - 1):+5.1f}%")
mean = {k: statistics.mean([min(v) for c, v in r.items() if c != "all"] or [0.0]) for k, r in res.items()}
print(f"mean of classes: base {mean['base']:.1f} new {mean['new']:.1f}")
