#!/usr/bin/env python3
"""epac/mdr against LAMMPS's granular mdr (the MDR authors' code) on MDR compaction.

Runs tests/lammps/in.mdr_compaction (fcc packing, isotropic compression by fix deform, then hold)
with
  lammps:       pair_style granular, mdr E nu Y 0 0 CoR (psi_b = 0: no Part II bulk response,
                which epac does not implement), tangential linear_nohistory 0 0, damping none;
                LAMMPS's mdr always grows radii;
  epac+growth:  plugin load epacplugin.so, pair_style epac/mdr, pair_coeff * * E nu Y 0 0 CoR,
                fix epac/mdr;
  epac:         the same without fix epac/mdr (no radius growth);
and compares the pressure curves (pressure at the same steps, hence the same strain): max |dP| /
peak |P| of the LAMMPS curve, over the compression and over the whole run. CoR = 1: no damping in
either code (LAMMPS's mdr: beta = -ln(CoR)/sqrt(ln^2 CoR + pi^2) = 0; epac: restitution 1 compiles
no damping), no friction in either: the difference is the normal law and the growth.

--equal-radii adds the same comparison with all radii equal (polyd 0): there epac's equal-pair
split (models/mdr/detail/mdr_pair_equal.hpp) and the authors' radical plane coincide. --ranks N also runs epac+growth on N
MPI ranks and compares the printed values with 1 rank digit by digit.

  python3 tests/lammps/compare_mdr_compaction.py --plugin /tmp/plugin-build-a/drivers/lammps/epacplugin.so
Exit status 1 when epac+growth departs from LAMMPS by more than --tol-compression (compression
phase), --tol-whole (whole run) or --tol-whole-equal (whole run, equal radii), relative to the peak,
or when the ranks differ by more than 1e-10.
"""
import argparse
import os
import sys
import tempfile

from mpi_session import run_lammps

HERE = os.path.dirname(os.path.abspath(__file__))
INPUT = os.path.join(HERE, "in.mdr_compaction")
DEFAULT_LMP = os.path.expanduser("~/.cache/epac/lammps/4Feb2025/build/lmp")


def run(args, label, style, coeffs, extra, workdir, ranks=1):
    out = os.path.join(workdir, label + ".dat")
    cmd = []
    if ranks > 1:
        cmd = [args.mpirun, "--allow-run-as-root", "--oversubscribe", "-np", str(ranks)]
    cmd += [args.lmp, "-in", INPUT, "-log", os.path.join(workdir, label + ".log"), "-screen", "none",
            "-var", "pstyle", style, "-var", "pcoeffs", coeffs, "-var", "out", out,
            "-var", "ncell", str(args.ncell), "-var", "strain", str(args.strain),
            "-var", "nsteps", str(args.nsteps), "-var", "nhold", str(args.nhold),
            "-var", "onerun", str(args.onerun)] + extra
    env = dict(os.environ, OMP_NUM_THREADS="1")
    r = run_lammps(cmd, workdir, env)
    if r.returncode != 0:
        log = open(os.path.join(workdir, label + ".log")).read() if os.path.exists(os.path.join(workdir, label + ".log")) else ""
        sys.exit(f"{label}: lmp failed ({r.returncode}):\n{r.stdout[-3000:]}\n{log[-3000:]}")
    rows = {}
    with open(out) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            v = line.split()
            rows[int(v[0])] = (v, [float(x) for x in v[1:]])  # strings (digit checks) and numbers
    return rows


def compare(ref, other, col=1):
    """max |dP| / peak |P_ref| over the common steps (col 1: pressure), and where it occurs."""
    steps = sorted(set(ref) & set(other))
    peak = max(abs(ref[s][1][col]) for s in steps)
    worst, at = max((abs(other[s][1][col] - ref[s][1][col]), s) for s in steps)
    return worst / peak, at, peak, steps


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--lmp", default=os.environ.get("EPAC_LMP", DEFAULT_LMP))
    ap.add_argument("--plugin", required=True)
    ap.add_argument("--mpirun", default="mpirun")
    ap.add_argument("--ncell", type=int, default=4)
    ap.add_argument("--strain", type=float, default=0.89)
    ap.add_argument("--nsteps", type=int, default=500)
    ap.add_argument("--nhold", type=int, default=200)
    ap.add_argument("--E", default="1e9")
    ap.add_argument("--nu", default="0.3")
    ap.add_argument("--Y", default="5e6")
    ap.add_argument("--CoR", default="1")
    ap.add_argument("--equal-radii", action="store_true")
    ap.add_argument("--pair-split", choices=["equal_pair", "balanced", "geometric"], default="equal_pair",
                    help="epac's pair split: equal_pair (default), balanced (the default before 0.x) or geometric (the authors' radical plane)")
    ap.add_argument("--delta-max", choices=["paper_19", "running_max"], default="paper_19",
                    help="epac's delta_max with growth: MDR (19) (default) or running_max (the authors' code)")
    ap.add_argument("--authors", action="store_true",
                    help="epac's documented conventions set to the authors' choices: pair_split geometric, "
                         "delta_max running_max, yield_onset hertz_40")
    ap.add_argument("--onerun", type=int, default=0,
                    help="1: compression and hold in one run (no setup pass between; see in.mdr_compaction)")
    ap.add_argument("--ranks", type=int, default=1)
    ap.add_argument("--tol-compression", type=float, default=None,
                    help="fail when epac+growth departs from LAMMPS by more than this (of the peak) while compressing")
    ap.add_argument("--tol-whole", type=float, default=None,
                    help="the same over the whole run (compression and hold), polydisperse radii")
    ap.add_argument("--tol-whole-equal", type=float, default=None,
                    help="the same over the whole run with equal radii (--equal-radii)")
    ap.add_argument("--workdir", default=None)
    args = ap.parse_args()
    args.plugin = os.path.abspath(args.plugin)
    workdir = args.workdir or tempfile.mkdtemp(prefix="epac-mdr-compaction-")
    os.makedirs(workdir, exist_ok=True)

    lmp_coeffs = f"mdr {args.E} {args.nu} {args.Y} 0 0 {args.CoR} tangential linear_nohistory 0 0 damping none"
    epac_coeffs = f"{args.E} {args.nu} {args.Y} 0 0 {args.CoR}"
    plug = ["-var", "plugin", args.plugin]
    if args.authors:
        args.pair_split, args.delta_max = "geometric", "running_max"
    epac_style = f"epac/mdr pair_split {args.pair_split} delta_max {args.delta_max}"
    if args.authors:  # (no friction and CoR 1 here: damping and friction conventions do not enter)
        epac_style += " yield_onset hertz_40"
    failed = False
    print(f"scene: ncell {args.ncell} ({4 * args.ncell ** 3} atoms), strain {args.strain} in {args.nsteps} steps, "
          f"hold {args.nhold}; E {args.E} nu {args.nu} Y {args.Y} CoR {args.CoR}; {epac_style}; files in {workdir}")
    cases = [("", [])]
    if args.equal_radii:
        cases.append(("_equal", ["-var", "polyd", "0"]))
    for suffix, geo in cases:
        ref = run(args, "lammps" + suffix, "granular", lmp_coeffs, geo, workdir)
        grow = run(args, "epac_growth" + suffix, epac_style, epac_coeffs, plug + ["-var", "grow", "1"] + geo, workdir)
        nogrow = run(args, "epac_nogrowth" + suffix, epac_style, epac_coeffs, plug + geo, workdir)
        end = args.nsteps
        title = "equal radii (0.94 R)" if suffix else "polydisperse radii [0.94, 0.99] R"
        print(f"\n{title}: pressure, max |dP| / peak P(lammps) over the whole run (steps 0-{end + args.nhold})")
        for name, rows in (("epac/mdr + fix epac/mdr", grow), ("epac/mdr, no growth", nogrow)):
            rel, at, peak, steps = compare(ref, rows)
            relc, atc, _, _ = compare(ref, {s: rows[s] for s in rows if s <= end})
            last = steps[-1]
            dend = (rows[last][1][1] - ref[last][1][1]) / abs(ref[last][1][1])
            print(f"  {name:26s} {rel:9.3%} (step {at}); compression only {relc:9.3%} (step {atc}); "
                  f"at step {last}: {dend:+.3%}; largest radius {rows[last][1][4]:.6g} vs lammps "
                  f"{ref[last][1][4]:.6g} (peak P {peak:.6g} Pa)")
            if name.startswith("epac/mdr +"):
                tol_w = args.tol_whole_equal if suffix else args.tol_whole
                for what, value, tol in (("compression", relc, args.tol_compression), ("whole run", rel, tol_w)):
                    if tol is not None:
                        ok = value <= tol
                        print(f"  {'ok  ' if ok else 'FAIL'} {what}: {value:.3%} <= {tol:.1%}")
                        failed = failed or not ok
        print("  strain  P_lammps  P_epac+growth  P_epac  (every 50 steps)")
        for s in sorted(ref):
            if s % 50 == 0 and s in grow and s in nogrow:
                print(f"  {ref[s][1][0]:.4f} {ref[s][1][1]:13.6g} {grow[s][1][1]:13.6g} {nogrow[s][1][1]:13.6g}")

    if args.ranks > 1:
        one = run(args, "epac_growth_np1", epac_style, epac_coeffs, plug + ["-var", "grow", "1"], workdir)
        many = run(args, f"epac_growth_np{args.ranks}", epac_style, epac_coeffs, plug + ["-var", "grow", "1"],
                   workdir, ranks=args.ranks)
        # with newton off each rank sums its atoms' contacts in its own neighbour order: the last
        # printed digits may differ (summation order), so the test bound is 1e-10 relative
        worst, at = 0.0, None
        for s_ in sorted(one):
            if s_ not in many:
                worst, at = float("inf"), s_
                break
            for a, b in zip(one[s_][1], many[s_][1]):
                d = abs(a - b) / max(abs(a), abs(b), 1e-300)
                if d > worst:
                    worst, at = d, s_
        same = sum(one[s_][0] == many.get(s_, (None,))[0] for s_ in one)
        print(f"\n1 vs {args.ranks} ranks ({epac_style} + fix epac/mdr): {same} of {len(one)} printed lines "
              f"equal to 15 digits; largest relative difference {worst:.1e} (step {at}; bound 1e-10)")
        failed = failed or not worst < 1e-10
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
