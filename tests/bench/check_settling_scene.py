#!/usr/bin/env python3
"""CI smoke test of the settling scene of bench/peers/side_by_side.py --scene settling
(bench/peers/settling_scene.py): a small grid (12 x 12 x 6 = 864 spheres, 3,000 steps, 1.5 ms)
written for both codes. epac-run must run it and the bed must form as the scene promises:
spheres in a random order, gravity pulling them down (potential energy falls), the floor
holding them (no sphere below it) and pair contacts in the second half. The LAMMPS data file
must name the same spheres. Never a timing."""
import argparse
import csv
import json
import os
import subprocess
import sys

ap = argparse.ArgumentParser()
ap.add_argument("--peers", required=True, help="bench/peers")
ap.add_argument("--exe", required=True)
ap.add_argument("--work", required=True)
a = ap.parse_args()
sys.path.insert(0, a.peers)
import settling_scene  # noqa: E402
import side_by_side  # noqa: E402

os.makedirs(a.work, exist_ok=True)
spheres, L, H = settling_scene.settling_spheres(12, 6)
scene = os.path.join(a.work, "settling.toml")
open(scene, "w").write(settling_scene.epac_scene(side_by_side.LAWS["hm"]["epac"], spheres, L, H,
                                                 side_by_side.SETTLING_G, 3000).replace(
    "[run]\n", "[run]\nparticle_output = true\n", 1))
data = settling_scene.lammps_data(spheres, L, H)
out = os.path.join(a.work, "out")
subprocess.check_call([a.exe, scene, "--threads", "2", "--quiet", "--out", out, "--overwrite", "--time-after", "1500"])
errors = []


def check(cond, what):
    if not cond:
        errors.append(what)


check(len(spheres) == 864, f"sphere count {len(spheres)}")
# a random order: consecutive spheres are rarely grid neighbours (in grid order nearly all are)
near = sum(1 for s, t in zip(spheres, spheres[1:])
           if sum((s[d] - t[d]) ** 2 for d in range(3)) < (1.5 * settling_scene.SPACING) ** 2)
check(near < len(spheres) // 20, f"random order: {near} consecutive spheres are grid neighbours")
check(data.count("\n") > 2 * len(spheres) and f"{len(spheres)} atoms" in data, "LAMMPS data: atoms and velocities")
rows = list(csv.DictReader(open(os.path.join(out, "timeseries.csv"))))
pe = [float(r["pe_gravity [J]"]) for r in rows]
# settling from the grid's solid fraction (about 0.44) towards a packing's (about 0.6) lowers the
# centre of mass to about 0.75 of its height: ask for a tenth at least
check(pe[-1] < 0.9 * pe[0], f"the spheres fall: potential energy {pe[0]:.4g} -> {pe[-1]:.4g} J")
late = [float(r["pair_contacts"]) for r in rows if int(r["step"]) > 1500]
check(min(late) > len(spheres), f"a bed: pair contacts in the second half {min(late):.0f}..{max(late):.0f}")
summary = json.load(open(os.path.join(out, "summary.json")))
check(summary["timed"]["steps"] == 1500, "timed window: steps 1501-3000")
prows = list(csv.DictReader(open(os.path.join(out, "particles.csv"))))
check(len(prows) > 0, "particles.csv")
if prows:
    final = max(int(r["step"]) for r in prows)
    low = min(float(r["z [m]"]) - float(r["R [m]"]) for r in prows if int(r["step"]) == final)
    check(low > -0.1 * settling_scene.R_MIN, f"the floor holds: lowest sphere bottom at {low:.3g} m")
if errors:
    print("settling scene smoke test FAILED:\n  " + "\n  ".join(errors))
    sys.exit(1)
print(f"settling scene smoke test passed: {len(spheres)} spheres, potential energy {pe[0]:.4g} -> {pe[-1]:.4g} J, "
      f"pair contacts {min(late):.0f}..{max(late):.0f} in the second half")
