#!/usr/bin/env python3
"""CI smoke test of bench/scaling/run_scaling.py: runs it with --smoke (a 256-sphere fcc scene,
40 steps, 1 and 2 threads) and checks the JSON it writes: every configuration present, with
positive finite rates, the phase times, and efficiencies. Never a timing threshold."""
import argparse
import json
import math
import os
import subprocess
import sys

ap = argparse.ArgumentParser()
ap.add_argument("--script", required=True)
ap.add_argument("--exe", required=True)
ap.add_argument("--work", required=True)
a = ap.parse_args()
os.makedirs(a.work, exist_ok=True)
js, png = os.path.join(a.work, "scaling.json"), os.path.join(a.work, "scaling.png")
for f in (js, png):
    if os.path.exists(f):
        os.remove(f)
subprocess.check_call([sys.executable, a.script, "--smoke", "--threads", "1", "2", "--exe", a.exe, "--json", js, "--png", png])
r = json.load(open(js))
errors = []
def check(cond, what):
    if not cond:
        errors.append(what)
check(r["backend"] in ("OpenMP", "Serial", "Threads", "HPX") or not r["host"], "backend/host flag")
for kind in ("strong", "weak"):
    rows = r[kind]
    check(len(rows) == (2 if r["host"] else len(rows)) and len(rows) > 0, f"{kind}: one row per thread count")
    for row in rows:
        b = row["best"]
        check(len(row["repeats"]) >= 1, f"{kind}: repeats")
        for key in ("contact_steps_per_second", "particle_steps_per_second", "wall_s"):
            check(math.isfinite(b[key]) and b[key] > 0, f"{kind} {row['threads']}: {key} = {b[key]}")
        check(b["particles"] == row["particles"] and row["particles"] > 0, f"{kind}: particles")
        check(b["contacts_mean"] > 0, f"{kind}: contacts")
        for ph in ("detection", "remap", "force", "growth", "integration", "output"):
            check(b["phases"].get(ph) is not None and b["phases"][ph] >= 0, f"{kind}: phase {ph}")
        check(math.isfinite(row["efficiency"]) and row["efficiency"] > 0, f"{kind}: efficiency")
    if r["host"]:
        check(rows[0]["efficiency"] == 1.0, f"{kind}: efficiency of the first row is 1 by definition")
if r["host"]:
    s = r["strong"]
    check(s[0]["particles"] == s[1]["particles"], "strong: same scene at every thread count")
    w = r["weak"]
    check(w[1]["particles"] > w[0]["particles"], "weak: the scene grows with the threads")
try:
    import matplotlib  # noqa: F401
    check(os.path.exists(png) and os.path.getsize(png) > 1000, "plot written")
except ImportError:
    pass
if errors:
    print("scaling smoke: FAILED:\n  " + "\n  ".join(errors))
    sys.exit(1)
print("scaling smoke: JSON complete,", sum(len(r[k]) for k in ("strong", "weak")), "configurations")
