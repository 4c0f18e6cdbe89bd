#!/usr/bin/env python3
"""epac's LAMMPS plugin styles against LAMMPS's own styles, in LAMMPS, on its fcc scene, in one run.

The scene is LAMMPS's fcc compression benchmark input, in.fcc_compress_model, unchanged (fcc
packing of polydisperse spheres, 0.94-0.99 R, fully periodic, compressed to 0.88 linear in 500
steps, then held 200 steps; `newton off`, as LAMMPS's MDR requires); only the included pair file
differs: LAMMPS's (pair.*) or the plugin's (bench/peers/lammps_plugin/pair.epac_*). The input and
LAMMPS's pair files are copied in bench/peers/lammps/ (see its README.md); this script runs the
copies of the LAMMPS peer kit supplied to developers beside the checkout (PEERS below).
Timed: the hold phase (the last `run`), its loop time and its Pair time, per active contact and
step, on 1 and 2 MPI ranks (1 OpenMP thread each). Runs alternate LAMMPS/epac per law and the best
of --repeats is kept: compare the ratios of one run.

Usage: python3 bench/peers/plugin_vs_lammps.py [--ranks 1 2] [--repeats 1] [--ncell 14]
         [--laws hm jkr nan mdr mdr_authors mdr_nogrowth] [--json FILE]
lmp and epacplugin.so come from drivers/lammps/build.sh (EPAC_BUILD_DIR, default build/; LAMMPS
cached under ~/.cache/epac/lammps/4Feb2025); run that first.
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
PEERS = os.path.normpath(os.path.join(ROOT, "..", "shared", "peers", "lammps"))
MINE = os.path.join(ROOT, "bench", "peers", "lammps_plugin")
LMP = os.path.expanduser(os.environ.get("EPAC_LAMMPS_PREFIX", "~/.cache/epac/lammps/4Feb2025")) + "/build/lmp"

# law -> (title, LAMMPS pair file, epac pair file)
LAWS = {
    "hm": ("Hertz-Mindlin (friction 0.5, damping)", "hm_mindlin", "epac_hertz_mindlin"),
    "jkr": ("JKR + Mindlin (1 J/m^2, friction, damping)", "jkr_mindlin", "epac_jkr"),
    "nan": ("Nan 2022 (1 J/m^2, Y 5 MPa, friction, damping)", None, "epac_nan2022"),
    "mdr": ("MDR (Y 5 MPa, friction, damping) + radius growth", "mdr", "epac_mdr"),
    "mdr_authors": ("MDR + radius growth, the authors' choices (pair_split geometric, delta_max running_max, "
                    "damping/friction authors, yield_onset hertz_40)",
                    "mdr", "epac_mdr_authors"),
    "mdr_nogrowth": ("MDR without radius growth (epac only; LAMMPS always grows)", None, "epac_mdr_nogrowth"),
}


def run(lmp, plugin, work, model, ranks, ncell):
    cmd = []
    if ranks > 1:
        cmd = ["mpirun", "-np", str(ranks), "--oversubscribe"] + (["--allow-run-as-root"] if os.geteuid() == 0 else [])
    cmd += [lmp, "-in", "in.fcc_compress_model", "-var", "model", model, "-var", "ncell", str(ncell),
            "-var", "plugin", plugin, "-log", f"log.{model}.{ranks}", "-screen", "none"]
    env = dict(os.environ, OMP_NUM_THREADS="1", OMP_PROC_BIND="false")
    r = subprocess.run(cmd, cwd=work, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    log = open(os.path.join(work, f"log.{model}.{ranks}")).read()
    if r.returncode != 0 or "ERROR" in log:
        print(log[-2000:], r.stdout[-2000:])
        raise SystemExit(f"{model} on {ranks} ranks failed")
    loops = re.findall(r"Loop time of (\S+) on (\d+) procs for (\d+) steps", log)
    loop, _, steps = loops[-1]
    pair = re.findall(r"^Pair\s+\|\s+\S+\s+\|\s+(\S+)\s+\|", log, re.M)[-1]  # average over ranks
    thermo = re.findall(r"^\s*(\d+)\s+(\d+)\s+\S+\s+(\S+)\s+\S+\s+(\S+)\s*$", log, re.M)
    contacts = float(thermo[-1][2])
    steps = int(steps)
    return {"loop_ns": float(loop) / (steps * contacts) * 1e9, "pair_ns": float(pair) / (steps * contacts) * 1e9,
            "contacts": contacts, "press": float(thermo[-1][3])}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--ranks", type=int, nargs="+", default=[1, 2])
    ap.add_argument("--repeats", type=int, default=1)
    ap.add_argument("--ncell", type=int, default=14)
    ap.add_argument("--laws", nargs="+", default=list(LAWS), choices=list(LAWS))
    ap.add_argument("--lmp", default=LMP)
    ap.add_argument("--plugin", default=os.path.join(os.environ.get("EPAC_BUILD_DIR", os.path.join(ROOT, "build")),
                                                     "drivers", "lammps", "epacplugin.so"))
    ap.add_argument("--json", default="")
    args = ap.parse_args()
    for f in (args.lmp, args.plugin):
        if not os.path.exists(f):
            raise SystemExit(f"{f} missing: run `bash drivers/lammps/build.sh --no-run` first")
    work = tempfile.mkdtemp(prefix="epac-plugin-bench-")
    shutil.copy(os.path.join(PEERS, "in.fcc_compress_model"), work)
    for d in (PEERS, MINE):
        for f in os.listdir(d):
            if f.startswith("pair."):
                shutil.copy(os.path.join(d, f), work)
    results = {}
    for law in args.laws:
        title, peer, mine = LAWS[law]
        for n in args.ranks:
            best = {}
            for _ in range(args.repeats):
                for who, model in (("lammps", peer), ("epac", mine)):
                    if model is None:
                        continue
                    r = run(args.lmp, os.path.abspath(args.plugin), work, model, n, args.ncell)
                    if who not in best or r["loop_ns"] < best[who]["loop_ns"]:
                        best[who] = r
            results[f"{law}/{n}"] = best
            line = f"{title}, {n} rank(s): "
            for who in ("lammps", "epac"):
                if who in best:
                    b = best[who]
                    line += f"{who} loop {b['loop_ns']:.1f} pair {b['pair_ns']:.1f} ns ({b['contacts']:.0f} contacts, P {b['press']:.4g}); "
            if "lammps" in best:
                line += f"LAMMPS/epac loop {best['lammps']['loop_ns'] / best['epac']['loop_ns']:.2f}x"
            print(line, flush=True)
    print("\n| law | ranks | LAMMPS style: loop (pair) ns | epac plugin: loop (pair) ns | LAMMPS / epac (loop) |")
    print("|---|---|---|---|---|")
    for law in args.laws:
        for n in args.ranks:
            b = results[f"{law}/{n}"]
            lam = f"{b['lammps']['loop_ns']:.1f} ({b['lammps']['pair_ns']:.1f})" if "lammps" in b else "-"
            ep = f"{b['epac']['loop_ns']:.1f} ({b['epac']['pair_ns']:.1f})"
            ratio = f"{b['lammps']['loop_ns'] / b['epac']['loop_ns']:.2f}x" if "lammps" in b else "-"
            print(f"| {LAWS[law][0]} | {n} | {lam} | {ep} | {ratio} |")
    if args.json:
        with open(args.json, "w") as f:
            json.dump(results, f, indent=1)
    shutil.rmtree(work)


if __name__ == "__main__":
    main()
