#!/usr/bin/env python3
"""CI smoke test of bench/roofline/roofline.py on a tiny packing: checks the JSON it writes
(rows, finite positive counts, the instruction mix a force law must have), never a timing.
With --subbuild (a build whose flags enable AVX-512, which valgrind 3.19 cannot execute) it first
configures and builds epac-law-throughput and epac-stream-triad there with EPAC_ARCH=portable, and
runs the script on that build."""
import argparse
import json
import math
import os
import subprocess
import sys

ap = argparse.ArgumentParser()
ap.add_argument("--script", required=True)
ap.add_argument("--build", required=True)
ap.add_argument("--work", required=True)
ap.add_argument("--subbuild", help="portable sub-build folder to measure instead of --build")
ap.add_argument("--source", help="epac's source folder (with --subbuild)")
ap.add_argument("--cmake", default="cmake")
ap.add_argument("--cmake-arg", action="append", default=[], help="configure argument of the sub-build")
a = ap.parse_args()
os.makedirs(a.work, exist_ok=True)
if a.subbuild:
    subprocess.run([a.cmake, "-S", a.source, "-B", a.subbuild, "-DEPAC_ARCH=portable", "-DEPAC_BUILD_TESTS=OFF",
                    "-DEPAC_BUILD_DRIVERS=OFF", "-DEPAC_BUILD_BENCH=ON", *a.cmake_arg], check=True,
                   stdout=subprocess.DEVNULL)
    flags = open(os.path.join(a.subbuild, "epac-build-flags.txt")).read()
    if "-march" in flags:
        sys.exit(f"FAIL the portable sub-build's flags hold -march: {flags}")
    subprocess.run([a.cmake, "--build", a.subbuild, "--target", "epac-law-throughput", "epac-stream-triad"],
                   check=True, stdout=subprocess.DEVNULL)
    print("roofline smoke: measuring the portable sub-build", a.subbuild, "(", flags.strip(), ")")
    a.build = a.subbuild
out = os.path.join(a.work, "roofline.json")
subprocess.run([sys.executable, a.script, "--build", a.build, "--contacts", "3000", "--count-contacts", "3000",
                "--seconds", "0.05", "--repeats", "1", "--laws", "hertz_mindlin,nan2022", "--scalars", "double,float",
                "--json", out], check=True)
r = json.load(open(out))
errors = []
if len(r["rows"]) != 4:
    errors.append(f"{len(r['rows'])} rows, want 4")
for row in r["rows"]:
    name = f"{row['law']}/{row['scalar']}"
    for k in ("instructions_per_contact", "flops_per_contact", "bytes_per_contact_step", "contact_steps_per_s",
              "GFLOPs", "fraction_of_peak", "fraction_of_DRAM_triad"):
        v = row[k]
        if not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
            errors.append(f"{name}: {k} = {v}")
    # a force law with damping takes at least one square root per contact, and its flops are a
    # fraction of its instructions; the disassembly must cover what callgrind counted
    if row["sqrt_per_contact"] < 0.9:
        errors.append(f"{name}: {row['sqrt_per_contact']} square roots per contact")
    if not 0.05 < row["flops_per_contact"] / row["instructions_per_contact"] < 1.5:
        errors.append(f"{name}: flops/instructions {row['flops_per_contact'] / row['instructions_per_contact']}")
    if row["unknown_per_contact"] > 0.2 * row["instructions_per_contact"]:
        errors.append(f"{name}: {row['unknown_per_contact']} of {row['instructions_per_contact']} instructions "
                      "not found in the disassembly")
for e in errors:
    print("FAIL", e)
print("roofline smoke:", "failed" if errors else "passed")
sys.exit(1 if errors else 0)
