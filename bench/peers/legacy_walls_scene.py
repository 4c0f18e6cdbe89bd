#!/usr/bin/env python3
"""The fcc benchmark scene for an epac-run without periodic boxes (for "before" measurements).

Builds before epac had `[box]` (commit 9cd3127 and earlier) can only run the LAMMPS fcc scene
wrapped in walls: the same 10,976 spheres (positions and radii taken from the periodic scene's
lattice by running a current epac-run for 0 steps), six rigid walls a radius beyond the outermost
spheres, each moving inward so that the box shrinks to 0.88 of its edge in 500 steps, then held
200 steps. Surface spheres touch walls instead of periodic images (about 63,600 active contacts
against 65,856), so rates are compared per active contact.

  python3 bench/peers/legacy_walls_scene.py --epac-run build/drivers/epac-run > /tmp/fcc_walls.toml
  <old build>/drivers/epac-run /tmp/fcc_walls.toml --threads 1 --out /tmp/old
The law block of bench/peers/fcc_compress.toml is copied, so --law picks one of side_by_side.py's.
"""
import argparse
import csv
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fcc_scene import LATTICE_A, fcc_scene, set_key  # noqa: E402


def column(row, name):
    """CSV value by column name, with or without a ' [unit]' suffix in the header."""
    for k, v in row.items():
        if k == name or k.split(" [")[0] == name:
            return float(v)
    raise KeyError(name)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--epac-run", required=True, help="a current epac-run (with [particles.lattice])")
    ap.add_argument("--law", default=None, help="a law of side_by_side.py (default: the scene's Hertz-Mindlin)")
    args = ap.parse_args()
    law_block = None
    if args.law:
        from side_by_side import LAWS
        law_block = LAWS[args.law]["epac"]
    text = fcc_scene(law_block)
    with tempfile.TemporaryDirectory() as work:
        scene = os.path.join(work, "fcc.toml")
        with open(scene, "w") as f:
            f.write(set_key(text, "run", "output_interval", 1) + "particle_output = true\n")
        subprocess.check_call([args.epac_run, scene, "--steps", "0", "--quiet", "--out", work],
                              stdout=subprocess.DEVNULL, env=dict(os.environ, OMP_PROC_BIND="false"))
        rows = list(csv.DictReader(open(os.path.join(work, "particles.csv"))))
    L = 14 * LATTICE_A
    R = max(column(r, "R") for r in rows)
    lo = [min(column(r, c) for r in rows) - R for c in "xyz"]
    hi = [max(column(r, c) for r in rows) + R for c in "xyz"]
    dt, steps_in, steps = 5.0e-7, 500, 700
    # the periodic box shrinks by 0.12 L per axis; each wall moves half of that
    v = 0.5 * 0.12 * L / (steps_in * dt)
    law = text.split("# --- law ---")[1].split("# --- end law ---")[0]
    law = law.split("\n", 1)[1]  # drop the rest of the marker line
    out = ['description = "fcc 14^3 spheres of bench/peers/fcc_compress.toml wrapped in 6 moving walls (legacy builds)"',
           law.strip(), "", "[materials.wall]", "rigid = true", "poisson_ratio = 0.3", "restitution = 0.59",
           "friction = 0.5", ""]
    for axis, name in enumerate("xyz"):
        for side, (pt, sign) in enumerate(((lo[axis], 1.0), (hi[axis], -1.0))):
            point = [0.0, 0.0, 0.0]
            point[axis] = pt
            normal = [0.0, 0.0, 0.0]
            normal[axis] = sign
            vel = [0.0, 0.0, 0.0]
            vel[axis] = sign * v
            out += ["[[walls]]", f'name = "{name}{side}"', f"point = {point!r}", f"normal = {normal!r}",
                    'material = "wall"', f"motion = [{{duration = {steps_in * dt!r}, velocity = {vel!r}}}]", ""]
    out += ["[particles]", "allow_overlap = true", ""]
    for r in rows:
        out += ["[[particles.list]]",
                f"position = [{column(r, 'x')!r}, {column(r, 'y')!r}, {column(r, 'z')!r}]",
                f"radius = {column(r, 'R')!r}", 'material = "bead"', ""]
    out += ["[run]", f"dt = {dt!r}", f"steps = {steps}", "skin = 2.0e-4", "output_interval = 100", ""]
    sys.stdout.write("\n".join(out))


if __name__ == "__main__":
    main()
