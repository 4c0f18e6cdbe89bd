#!/usr/bin/env python3
"""Rolling resistance on a heap: epac's plugin against LAMMPS's `rolling sds`, statistically.

  compare_rolling_heap.py --lmp LMP --plugin epacplugin.so --workdir DIR

A column of 1,400 polydisperse spheres (R 0.9-1.1 mm, E 1 MPa, e 0.5, friction 0.5, rolling sds
k_r 500 N/m, gamma_r 1e-3 N s/m, mu_r 0.3) settles in a cylinder of radius 10 mm on a rough floor
(tests/lammps/in.rolling_heap, LAMMPS's own law); the cylinder is removed and the column spreads
into a heap for 0.5 s. The collapse is chaotic, so it is compared as an ensemble: LAMMPS's
`granular hertz/material ... tangential mindlin ... rolling sds ... damping coeff_restitution` with
atom 1 nudged by 0, 1, ..., 5 x 1e-12 m, and epac/hertz_mindlin with the same coefficients
(`E nu e mu rolling sds ...`) nudged by 0, 1, 2 x 1e-12 m. The heap's flank angle: the mean top of
the three highest spheres in each 2 mm ring about the axis, a straight line fitted to the rings
past r = 6 mm whose top lies between 3.5 mm (above the one-layer carpet) and 0.85 of the central
height (rings within 6 mm). Passes when the two ensembles' mean angles differ by less than twice
the standard error of that difference plus 0.5 degrees (the two laws' damping and tangential
conventions differ slightly, drivers/lammps/README.md), and when LAMMPS without rolling
resistance gives an angle further from LAMMPS's ensemble than that bound (the comparison can tell
rolling resistance from none). Exits 1 on a failure.
"""
import argparse
import math
import os
import shutil
import sys
from concurrent.futures import ThreadPoolExecutor

from mpi_session import run_lammps

HERE = os.path.dirname(os.path.abspath(__file__))
INPUT = os.path.join(HERE, "in.rolling_heap")
ROLL = "rolling sds 500 0.001 0.3"
LAMMPS = "hertz/material 1e6 0.5 0.3 tangential mindlin NULL 1.0 0.5 {roll} damping coeff_restitution"
EPAC = "1e6 0.3 0.5 0.5 {roll}"


def lmp(args, tag, variables):
    cmd = [args.lmp, "-var", "plugin", args.plugin, "-in", INPUT, "-log", tag + ".log", "-screen", "none"]
    for k, v in variables:
        cmd += ["-var", k, v]
    env = dict(os.environ, OMP_NUM_THREADS="1", OMP_PROC_BIND="false")
    r = run_lammps(cmd, args.workdir, env)
    log_path = os.path.join(args.workdir, tag + ".log")
    log = open(log_path).read() if os.path.exists(log_path) else ""
    if r.returncode != 0 or "ERROR" in log:
        print(" ".join(cmd))
        print(r.stdout[-2000:])
        print(log[-2000:])
        raise SystemExit(f"LAMMPS failed ({tag})")


def heap(path):
    """(flank angle [deg], central height [m]) of a final dump."""
    lines = open(path).read().splitlines()
    s = next(i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS")) + 1
    rings = {}
    for l in lines[s:]:
        v = l.split()
        x, y, z, R = map(float, v[1:5])
        rings.setdefault(int(math.hypot(x, y) / 0.002), []).append(z + R)
    prof = {(b + 0.5) * 0.002: sum(sorted(h)[-3:]) / len(sorted(h)[-3:]) for b, h in rings.items()}
    centre = [h for r, h in prof.items() if r < 0.006]
    H = sum(centre) / len(centre)
    flank = [(r, h) for r, h in prof.items() if r >= 0.006 and 0.0035 < h < 0.85 * H]
    if len(flank) < 3:
        raise SystemExit(f"{path}: no flank to fit ({len(flank)} rings)")
    mx = sum(p[0] for p in flank) / len(flank)
    my = sum(p[1] for p in flank) / len(flank)
    slope = sum((p[0] - mx) * (p[1] - my) for p in flank) / sum((p[0] - mx) ** 2 for p in flank)
    return math.degrees(math.atan(-slope)), H


def stats(v):
    m = sum(v) / len(v)
    sd = math.sqrt(sum((x - m) ** 2 for x in v) / (len(v) - 1))
    return m, sd


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--lmp", required=True)
    ap.add_argument("--plugin", required=True)
    ap.add_argument("--workdir", required=True)
    ap.add_argument("--jobs", type=int, default=2)
    args = ap.parse_args()
    args.plugin = os.path.abspath(args.plugin)
    if os.path.isdir(args.workdir):
        shutil.rmtree(args.workdir)
    os.makedirs(args.workdir)
    lmp(args, "fill", [("stage", "fill"), ("steps", "40000"), ("coeffs", LAMMPS.format(roll=ROLL))])
    runs = [(f"lammps{k}", "granular", LAMMPS.format(roll=ROLL), k) for k in range(6)]
    runs += [(f"epac{k}", "epac/hertz_mindlin", EPAC.format(roll=ROLL), k) for k in range(3)]
    runs += [("lammps_no_rolling", "granular", LAMMPS.format(roll=""), 0)]

    def collapse(run):
        tag, style, coeffs, k = run
        lmp(args, tag, [("stage", "collapse"), ("style", style), ("coeffs", coeffs), ("nudge", f"{k}e-12"),
                        ("steps", "50000"), ("out", tag + ".dump")])
        return tag, heap(os.path.join(args.workdir, tag + ".dump"))

    with ThreadPoolExecutor(max_workers=args.jobs) as pool:
        result = dict(pool.map(collapse, runs))
    for tag, (angle, H) in result.items():
        print(f"  {tag:18s} flank angle {angle:6.2f} deg, central height {1e3 * H:6.2f} mm")
    la = [result[f"lammps{k}"][0] for k in range(6)]
    ea = [result[f"epac{k}"][0] for k in range(3)]
    (ml, sl), (me, se) = stats(la), stats(ea)
    bound = 2 * math.sqrt(sl ** 2 / len(la) + se ** 2 / len(ea)) + 0.5
    none = result["lammps_no_rolling"][0]
    failures = 0
    ok = abs(me - ml) < bound
    print(f"  {'ok  ' if ok else 'FAIL'} epac {me:.2f} +- {se:.2f} deg against LAMMPS {ml:.2f} +- {sl:.2f} deg "
          f"(sd): |difference| {abs(me - ml):.2f} < {bound:.2f}")
    failures += not ok
    ok = abs(none - ml) > bound
    print(f"  {'ok  ' if ok else 'FAIL'} without rolling resistance LAMMPS gives {none:.2f} deg: "
          f"{abs(none - ml):.2f} from the ensemble, beyond the bound {bound:.2f}")
    failures += not ok
    if failures:
        print(f"{failures} check(s) failed")
        sys.exit(1)
    print("all checks passed")


if __name__ == "__main__":
    main()
