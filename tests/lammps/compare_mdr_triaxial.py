#!/usr/bin/env python3
"""epac/mdr against LAMMPS's granular mdr on the MDR authors' own example in.triaxial.compaction.12.

The input ships with LAMMPS (examples/granular/in.triaxial.compaction.12 and spheres12.data): 12
spheres (diameters 0.8-1.2) in a box of six planar MDR walls (fix wall/gran/region granular mdr)
that close in at 10 m/s, E 1 GPa, nu 0.3, Y 50 MPa, no adhesion, psi_b 0.5, CoR 0.5, tangential
linear_history k_t = 2/7 E R, mu 0.5, damping none. It prints the force on three walls against the
wall displacement. The script runs it three times, changing nothing but the commented-out dumps
and what epac needs:

  lammps:       the input as shipped, plus a print of the smallest psi (Part II's free-area ratio);
  lammps_psi0:  the same with psi_b 0 (Part II's bulk response never triggers);
  epac_shipped: as epac below, with contact_penalty on (LAMMPS's MDR contact penalty, which
                granular mdr always applies) and psi_b as shipped (Part II's bulk response,
                mdr_bulk_response.hpp);
  epac_penalty: the same with psi_b 0;
  epac:         plugin load epacplugin.so; pair_style epac/mdr with the authors' choices (pair_split
                geometric delta_max running_max damping authors friction authors yield_onset
                hertz_40 surface_energy_share each_side_full adhesive_radius authors release
                zero_overlap, the last three without effect here: no adhesion); pair_coeff * * E nu
                Y gamma 0 CoR mu MU kt KT (psi_b 0); fix epac/mdr (radius growth); each fix
                wall/gran/region replaced by fix epac/wall on the same region; the contact-area
                output of the particle pair 1-12 (compute pair/local p13, granular only) removed.

Checks, each wall force relative to the peak of the LAMMPS curve:
  1. the shipped input against epac_shipped over the whole run (Part II's bulk response triggers
     at wall displacement 0.424 of 0.499): within --tol; the deviation up to the step before the
     bulk response triggers is printed too;
  2. psi_b 0 against epac_penalty over the whole run: within --tol-penalty (the contact penalty,
     mdr_contact_penalty.hpp, validated: both codes apply it);
  psi_b 0 against epac without the penalty is printed (what the penalty moves).
With --lammps-src (LAMMPS's src folder) a third check takes the penalty out of both codes: the
script compiles a small library that replaces fix granular/mdr's calculate_contact_penalty by a
no-op and reruns lammps_psi0 with it preloaded (LD_PRELOAD; a diagnostic, not a LAMMPS option):
  3. psi_b 0 without the penalty against epac without it over the whole run: within --tol-no-penalty.
--ranks 2 also runs epac_shipped on 2 MPI ranks (fix epac/wall's per-atom history migrates with
the atoms; the penalty walks each local atom's pairs, ghosts included; Part II's per-atom state and
mean surface displacement reach the ghosts by forward communication) and requires the printed
forces to agree with 1 rank to 1e-10 of the peak.
--sensitivity reruns epac with each of the authors' choices back at epac's default and prints how
far each moves the curves (why each convention is needed); no check.

  python3 tests/lammps/compare_mdr_triaxial.py --plugin build/drivers/lammps/epacplugin.so \
      --examples ~/.cache/epac/lammps/4Feb2025/src/lammps-4Feb2025/examples/granular
"""
import argparse
import os
import re
import sys

from authors_examples import (AUTHORS, DEFAULTS, add_common_arguments, build_no_penalty, prepare, read_rows,
                              run_example)

INPUT = "in.triaxial.compaction.12"
DATA = "spheres12.data"
SENSITIVITY_KEYS = ("pair_split", "delta_max", "damping", "friction", "yield_onset")  # the rest: adhesion (none here)


def replace_once(text, old, new, what):
    if old not in text:
        sys.exit(f"{INPUT}: expected line not found ({what}): {old!r}; the example changed, update this script")
    return text.replace(old, new, 1)


def lammps_input(shipped, psi_b):
    s = re.sub(r"^dump", "#dump", shipped, flags=re.M)
    s = s.replace("force_disp_triaxial12.csv", "walls.csv")
    if psi_b is not None:
        s, n = re.subn(r"^variable psi_b\s+equal .*$", f"variable psi_b equal {psi_b}", s, flags=re.M)
        if n != 1:
            sys.exit(f"{INPUT}: no 'variable psi_b equal' line")
    # the smallest psi per step (Part II's trigger), printed with the wall displacement
    s = replace_once(s, "\nrun 0\n", "\ncompute epac_psi all property/atom d_psi\n"
                     "compute epac_psimin all reduce min c_epac_psi\nvariable epac_psimin equal c_epac_psimin\n"
                     "fix epac_psi all print 1 \"${plane_disp} ${epac_psimin}\" file psi.csv screen no\nrun 0\n",
                     "run 0")
    return s


def epac_input(shipped, plugin, choices, psi_b="0"):
    s = re.sub(r"^dump", "#dump", shipped, flags=re.M)
    s = s.replace("force_disp_triaxial12.csv", "walls.csv")
    opts = " ".join(f"{k} {v}" for k, v in choices.items())
    s = replace_once(s, "pair_style granular",
                     f"plugin load {plugin}\npair_style epac/mdr {opts}\nfix epac_growth all epac/mdr", "pair_style")
    s = replace_once(s, "pair_coeff * * mdr ${YoungsModulus} ${PoissonsRatio} ${YieldStress} ${SurfaceEnergy} ${psi_b} "
                     "${CoR} tangential linear_history ${kt} ${xgammat} ${mu_s} damping none",
                     "pair_coeff * * ${YoungsModulus} ${PoissonsRatio} ${YieldStress} ${SurfaceEnergy} " + psi_b +
                     " ${CoR} mu ${mu_s} kt ${kt}", "pair_coeff")
    s, n = re.subn(r"^fix (\S+) all wall/gran/region \$\{wall_contact_string\} region (\S+) contacts$",
                   r"fix \1 all epac/wall region \2 contacts", s, flags=re.M)
    if n != 6:
        sys.exit(f"{INPUT}: expected 6 fix wall/gran/region lines, found {n}")
    # the pair 1-12 contact area comes from pair granular's per-contact output (compute pair/local p13)
    s, n = re.subn(r"^(compute Ac_1_12 .*|compute Ac_1_12_sum .*|variable Ac_1_12 .*|fix logArea .*)$", r"#\1", s,
                   flags=re.M)
    if n != 4:
        sys.exit(f"{INPUT}: expected the 4 lines of the pair 1-12 contact-area output, found {n}")
    return s


def run(args, label, text, ranks=1, preload=None):
    work = run_example(args, label, text, DATA, ranks=ranks, preload=preload)
    psi_file = os.path.join(work, "psi.csv")
    return read_rows(os.path.join(work, "walls.csv")), (read_rows(psi_file) if os.path.exists(psi_file) else None)


WALLS = ("xy_neg (z)", "xz_neg (y)", "yz_neg (x)")


def compare(ref, other, upto):
    """Per wall: max |dF| / peak |F_ref| over rows [0, upto)."""
    n = min(len(ref), len(other), upto)
    out = []
    for col in (1, 2, 3):
        peak = max(abs(r[col]) for r in ref[:n])
        dev = max(range(n), key=lambda k: abs(ref[k][col] - other[k][col]))
        rel = abs(ref[dev][col] - other[dev][col]) / peak if peak > 0 else 0.0
        out.append((rel, ref[dev][0], peak))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    add_common_arguments(ap)
    ap.add_argument("--mpirun", default="mpirun")
    ap.add_argument("--tol", type=float, default=1e-3)  # the issue asked 1%; both codes agree to 2e-4
    ap.add_argument("--lammps-src", default=None, help="LAMMPS's src folder: adds check 3 (no contact penalty)")
    ap.add_argument("--tol-no-penalty", type=float, default=1e-3)
    ap.add_argument("--tol-penalty", type=float, default=1e-3)
    ap.add_argument("--ranks", type=int, default=1)
    ap.add_argument("--sensitivity", action="store_true")
    args = ap.parse_args()
    shipped = prepare(args, INPUT, "epac_triaxial_")

    lmp_rows, psi = run(args, "lammps", lammps_input(shipped, None))
    psi0_rows, _ = run(args, "lammps_psi0", lammps_input(shipped, 0.0))
    epac_rows, _ = run(args, "epac", epac_input(shipped, args.plugin, AUTHORS))
    with_penalty = dict(AUTHORS, contact_penalty="on")
    pen_rows, _ = run(args, "epac_penalty", epac_input(shipped, args.plugin, with_penalty))
    shipped_rows, _ = run(args, "epac_shipped", epac_input(shipped, args.plugin, with_penalty, "${psi_b}"))
    psi_b = float(re.search(r"^variable psi_b\s+equal\s+(\S+)", shipped, flags=re.M).group(1))
    onset = next((k for k, r in enumerate(psi) if r[1] < psi_b), len(psi))
    # psi.csv and walls.csv print the same steps (fix print every step, defined in that order)
    if len(psi) != len(lmp_rows):
        sys.exit(f"psi.csv has {len(psi)} rows, walls.csv {len(lmp_rows)}")
    print(f"{INPUT}: {len(lmp_rows)} printed steps; Part II's bulk response (psi < psi_b = {psi_b}) "
          f"first at wall displacement {psi[onset][0] if onset < len(psi) else 'never'} (row {onset})")
    ok = True
    # check 1 against the peak of the shipped run's curve (the example's peak force); printed also
    # against the peak over the compared range
    whole_peak = compare(lmp_rows, lmp_rows, len(lmp_rows))
    checks = [("shipped input, whole run", lmp_rows, len(lmp_rows), args.tol, None, shipped_rows),
              ("shipped input, before bulk response", lmp_rows, onset, args.tol, [p for _, _, p in whole_peak],
               shipped_rows),
              ("psi_b 0, whole run", psi0_rows, len(psi0_rows), args.tol_penalty, None, pen_rows)]
    if args.lammps_src:
        lib = build_no_penalty(args)
        nopen_rows, _ = run(args, "lammps_psi0_no_penalty", lammps_input(shipped, 0.0), preload=lib)
        checks.append(("psi_b 0, no contact penalty, whole run", nopen_rows, len(nopen_rows), args.tol_no_penalty, None,
                       epac_rows))
    for name, ref, upto, tol, peaks, epac in checks:
        res = compare(ref, epac, upto)
        for k, (wall, (rel, at, peak)) in enumerate(zip(WALLS, res)):
            extra = ""
            if peaks:  # relative to the whole curve's peak; the range's own peak in the note
                extra = f"; {rel:.3e} of the peak {peak:.4e} N before the bulk response"
                rel, peak = rel * peak / peaks[k], peaks[k]
            flag = "ok" if rel <= tol else "FAIL"
            ok = ok and rel <= tol
            print(f"  {name:38s} wall {wall}: max |dF| / peak = {rel:.3e} (at displacement {at:.5f}, "
                  f"peak {peak:.4e} N{extra})  [{flag}, tol {tol}]")
    unpen = compare(psi0_rows, epac_rows, len(psi0_rows))
    print("  for scale: psi_b 0 against epac without the contact penalty, whole run: " +
          ", ".join(f"{w} {r:.3e}" for w, (r, _, _) in zip(WALLS, unpen)))
    full = compare(lmp_rows, psi0_rows, len(lmp_rows))
    print("  for scale: the shipped input against psi_b 0 (what Part II's bulk response adds), whole run: " +
          ", ".join(f"{w} {r:.3f}" for w, (r, _, _) in zip(WALLS, full)))

    if args.ranks > 1:
        two, _ = run(args, f"epac_shipped_{args.ranks}ranks",
                     epac_input(shipped, args.plugin, with_penalty, "${psi_b}"), ranks=args.ranks)
        res = compare(shipped_rows, two, len(shipped_rows))
        worst = max(r for r, _, _ in res)
        flag = "ok" if worst <= 1e-10 and len(two) == len(shipped_rows) else "FAIL"
        ok = ok and flag == "ok"
        print(f"  epac 1 against {args.ranks} ranks: max |dF| / peak = {worst:.3e}  [{flag}, tol 1e-10]")

    if args.sensitivity:
        print("sensitivity: epac with one of the authors' choices back at epac's default, against psi_b 0, whole run")
        for key in SENSITIVITY_KEYS:
            choices = dict(AUTHORS)
            choices[key] = DEFAULTS[key]
            rows, _ = run(args, f"epac_{key}_default", epac_input(shipped, args.plugin, choices))
            res = compare(psi0_rows, rows, len(psi0_rows))
            print(f"  {key} {DEFAULTS[key]:18s}: " + ", ".join(f"{w} {r:.4f}" for w, (r, _, _) in zip(WALLS, res)))
        rows, _ = run(args, "epac_all_default", epac_input(shipped, args.plugin, DEFAULTS))
        res = compare(psi0_rows, rows, len(psi0_rows))
        print(f"  {'all defaults':37s}: " + ", ".join(f"{w} {r:.4f}" for w, (r, _, _) in zip(WALLS, res)))
    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
