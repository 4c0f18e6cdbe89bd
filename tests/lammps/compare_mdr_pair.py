#!/usr/bin/env python3
"""An MDR pair in epac/mdr (+ fix epac/mdr) against LAMMPS's granular mdr (the authors' code).

tests/lammps/in.mdr_pair presses two spheres together by prescribed motion (load to 0.3 R1, unload
to 0.1 R1, reload to 0.4 R1, unload to a gap) and records the pair force every 10 steps. For radius
ratios R2/R1 = 1, 2, 5, plastic (E/Y = 200) and elastic (Y = 1e12 Pa), both with radius growth,
no damping (CoR 1), no friction, no adhesion, psi_b 0, it compares epac's force with LAMMPS's at the
same steps: max |F_epac - F_lammps| / peak |F_lammps|.
  - epac's documented conventions set to the authors' choices (pair_style epac/mdr pair_split
    geometric delta_max running_max yield_onset hertz_40): every case within 1% (asserted);
  - epac's defaults (equal_pair split, delta_max by (19)): equal radii within 1% (asserted), elastic
    unequal pairs within 0.1% up to delta = 0.1 R* (asserted: both are Hertz with E*, R* there),
    the rest printed (the equal-pair sides follow the similarity of same-material spheres, the
    authors' radical plane does not: docs/models.md "MDR conventions").
  python3 tests/lammps/compare_mdr_pair.py --lmp LMP --plugin epacplugin.so [--workdir DIR]
"""
import argparse
import os
import sys
import tempfile

from mpi_session import run_lammps

HERE = os.path.dirname(os.path.abspath(__file__))
INPUT = os.path.join(HERE, "in.mdr_pair")
N = 2000  # steps per segment of in.mdr_pair (its variable N): the first loading is steps 0..N


def run(args, workdir, label, variables):
    out = os.path.join(workdir, label + ".dat")
    cmd = [args.lmp, "-in", INPUT, "-log", os.path.join(workdir, label + ".log"), "-screen", "none",
           "-var", "out", out]
    for k, v in variables:
        cmd += ["-var", k, v]
    env = dict(os.environ, OMP_NUM_THREADS="1", OMP_PROC_BIND="false")
    r = run_lammps(cmd, workdir, env)
    if r.returncode != 0:
        sys.exit(f"{label}: lmp failed:\n{r.stdout[-3000:]}")
    rows = {}
    for line in open(out):
        if line.startswith("#"):
            continue
        v = line.split()
        rows[int(v[0])] = [float(x) for x in v[1:]]  # dl, F, rmin, rmax
    return rows


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--lmp", default=os.path.expanduser("~/.cache/epac/lammps/4Feb2025/build/lmp"))
    ap.add_argument("--plugin", required=True)
    ap.add_argument("--workdir", default=None)
    args = ap.parse_args()
    workdir = args.workdir or tempfile.mkdtemp(prefix="epac-mdr-pair-")
    os.makedirs(workdir, exist_ok=True)
    plugin = os.path.abspath(args.plugin)
    failed = False
    print("| E/Y | R2/R1 | peak F [N] | authors' choices | epac's defaults | epac's defaults, delta <= 0.1 R* | F_default / F_lammps at 0.4 R1 |")
    print("|---|---|---|---|---|---|---|")
    for Y in ("5e6", "1e12"):
        for R2 in ("1.0e-3", "2.0e-3", "5.0e-3"):
            tag = f"{Y}_{R2}"
            R_star = 1e-3 * float(R2) / (1e-3 + float(R2))
            base = [("R2", R2)]
            ref = run(args, workdir, "lammps_" + tag,
                      base + [("pcoeffs", f"mdr 1e9 0.3 {Y} 0 0 1 tangential linear_nohistory 0 0 damping none")])
            peak = max(abs(v[1]) for v in ref.values())
            res = {}
            for split, style in (("geometric", "epac/mdr pair_split geometric delta_max running_max yield_onset hertz_40"),
                                 ("default", "epac/mdr")):
                e = run(args, workdir, f"epac_{split}_{tag}",
                        base + [("plugin", plugin), ("pstyle", style),
                                ("pcoeffs", f"1e9 0.3 {Y} 0 0 1"), ("grow", "1")])
                steps = sorted(set(ref) & set(e))
                # the first loading up to delta = 0.1 R* (small contact: Hertz with E*, R* in both)
                small = [st for st in steps if st <= N and ref[st][0] <= 0.1 * R_star]
                res[split] = (max(abs(e[st][1] - ref[st][1]) for st in steps) / peak, e,
                              max(abs(e[st][1] - ref[st][1]) for st in small) / peak)
            ratio = res["default"][1][6000][1] / ref[6000][1]
            ey = 1e9 / float(Y)
            rr = float(R2) / 1e-3
            print(f"| {'elastic' if Y == '1e12' else f'{ey:.3g}'} | {rr:.0f} | {peak:.4g} | {res['geometric'][0]:.3%} | {res['default'][0]:.3%} | {res['default'][2]:.3%} | {ratio:.3f} |")
            # authors' choices: the authors' construction, every case within 1% of the peak.
            # defaults: equal radii are the same construction (1%, whole path); unequal elastic
            # pairs are Hertz with E*, R* in both codes while the contact is small, so within 0.1%
            # of the peak up to delta = 0.1 R* (measured 0.024% at ratio 5); beyond that MDR's
            # large-deformation terms act on different sides (the authors' own spheres on the
            # radical plane, epac's equal-pair sides), neither a reference: printed.
            checks = [("geometric", res["geometric"][0], 0.01)]
            if rr == 1:
                checks.append(("default", res["default"][0], 0.01))
            elif Y == "1e12":
                checks.append(("default up to delta = 0.1 R*", res["default"][2], 0.001))
            for name, value, tol in checks:
                if not value <= tol:
                    print(f"  FAIL {name}, E/Y {ey:.3g}, R2/R1 {rr:.0f}: {value:.3%} > {tol:.1%} of the peak")
                    failed = True
    print("files in", workdir)
    print("FAILED" if failed else "all asserted cases within their bounds")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
