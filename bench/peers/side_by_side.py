#!/usr/bin/env python3
"""epac against LAMMPS 4Feb2025 on LAMMPS's own fcc benchmark scene, in one run, side by side.

The scene (LAMMPS's in.fcc_compress_model, copied in bench/peers/lammps/; epac: bench/peers/fcc_compress.toml):
10,976 spheres on an fcc lattice in a fully periodic box, compressed by an affine box deformation
to 0.88 (linear) in 500 steps, then held 200 steps; about 65,856 contacts in the hold phase. Both
codes are timed on the hold phase only (LAMMPS: the loop time of its last `run`; epac: the
steps after the deformation, `epac-run --time-after 500`), per active contact and step.

--scene settling (issue 20, item 5): a flow that mixes instead of the lattice. 46,464 of the same
beads, numbered in a random order, fall under gravity onto a floor in a box periodic in x and y
(settling_scene.py; LAMMPS reads the same spheres from a data file, bench/peers/lammps/in.settling).
Hertz-Mindlin against gran/hertz/history/omp only (LAMMPS's floor, fix wall/gran, takes that
style's coefficients). Timed: steps 2001-4000, while the bed forms (about 1e5 contacts), per pair
contact-step (timeseries.csv / thermo, every 100 steps).

For each law and thread count the LAMMPS and epac runs alternate, `--repeats` times, and the best
of each is kept (the machine is shared: compare the ratios of one run, never absolute times
across runs). Prints a markdown table and writes JSON (--json).

Usage:
  python3 bench/peers/side_by_side.py [--threads 1 2] [--repeats 3] [--laws hm jkr nan mdr mdr_growth mdr_authors]
                                      [--precision double float] [--json FILE] [--before-epac-run EXE]
                                      [--scene fcc|mixed|settling] [--ncell N] [--settling-grid NXY NZ]
LAMMPS is built on first use (about 2-5 min; cached in ~/.cache/lammps-peer) with the build scripts
of the LAMMPS peer kit supplied to developers beside the checkout (PEERS below; the kit's inputs
are copied in bench/peers/lammps/, see its README.md); epac-run is taken from $EPAC_BUILD_DIR (default build/) and built if missing.
Where that epac-run was built with -march=native, the LAMMPS it is compared with is built with
-march=native -fno-math-errno too, in ~/.cache/lammps-peer/build-native, and with GCC's
-mtune-ctrl=^use_gather as well where epac-run has it (its default, EPAC_NO_GATHER), in
~/.cache/lammps-peer/build-native-nogather (--lmp overrides all three).
"""
import argparse
import csv
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fcc_scene import ROOT, fcc_scene  # noqa: E402
import settling_scene  # noqa: E402

PEERS = os.path.normpath(os.path.join(ROOT, "..", "shared", "peers", "lammps"))
LMP_DEFAULT = os.path.expanduser("~/.cache/lammps-peer/build/lmp")
# An epac built for this machine's CPU (-march=native) is compared with a LAMMPS built the same way,
# in its own build folder (issue 20: both codes with the flags a user of this machine would use).
LMP_NATIVE = os.path.expanduser("~/.cache/lammps-peer/build-native/lmp")
NATIVE_FLAGS = "-march=native -fno-math-errno"
# epac's default native build adds GCC's -mtune-ctrl=^use_gather (cmake/EpacArchFlags.cmake,
# EPAC_NO_GATHER): the LAMMPS it is compared with then gets it too, in a folder of its own
NO_GATHER = "-mtune-ctrl=^use_gather"
LMP_NATIVE_NO_GATHER = os.path.expanduser("~/.cache/lammps-peer/build-native-nogather/lmp")

def law_block(model, extra_material="", extra_model=""):
    """The scene's material (E 1e9 Pa, nu 0.3, density 1000, restitution 0.5, friction 0.5, as
    LAMMPS's pair files) with a law's extra keys, and its [model] table."""
    return ("\n[materials.bead]\nyoungs_modulus = 1.0e9\npoisson_ratio = 0.3\ndensity = 1000.0\n"
            "restitution = 0.5\nfriction = 0.5\n" + extra_material + f"\n[model]\nname = \"{model}\"\n" + extra_model)


# law -> (LAMMPS pair files with their thread mode, epac materials + model block)
#   thread mode "omp": OPENMP style (-sf omp -pk omp N); "serial": no threaded style exists, so
#   LAMMPS runs it on one thread whatever N is (reported in the N column all the same).
LAWS = {
    "hm": {
        "title": "Hertz-Mindlin (friction, damping)",
        "lammps": [("hhist_omp", "omp", "gran/hertz/history/omp"),
                   ("hm_mindlin", "serial", "granular hertz/material + mindlin")],
        "epac": law_block("hertz_mindlin"),
    },
    "jkr": {
        "title": "JKR + Mindlin (surface energy 1 J/m^2)",
        "lammps": [("jkr_mindlin", "serial", "granular jkr + mindlin")],
        "epac": law_block("jkr", "surface_energy = 1.0\n"),
    },
    "nan": {
        "title": "Nan 2022 (adhesion 1 J/m^2, yield 5 MPa)",
        "lammps": [],
        "epac": law_block("nan2022", "surface_energy = 1.0\nyield_stress = 5.0e6\n"),
    },
    "mdr": {
        "title": "MDR, plasticity, no adhesion, no growth (Y 5 MPa)",
        "lammps": [("mdr", "serial", "granular mdr")],
        "epac": law_block("mdr", "yield_stress = 5.0e6\n", 'effects = ["plasticity", "friction", "damping"]\n'),
    },
    "mdr_growth": {
        "title": "MDR, plasticity + radius growth (Y 5 MPa)",
        "lammps": [("mdr", "serial", "granular mdr")],
        "epac": law_block("mdr", "yield_stress = 5.0e6\n",
                          'effects = ["plasticity", "radius_growth", "friction", "damping"]\n'),
    },
    # like with like: what pair.mdr runs (the authors' conventions, Part II's bulk response at
    # psi_b 0.5, the contact penalty, growth; k_t = 2/7 E R with R = 1 mm as in the LAMMPS input)
    "mdr_authors": {
        "title": "MDR as LAMMPS runs it: growth, bulk response psi_b 0.5, contact penalty, authors' conventions",
        "lammps": [("mdr", "serial", "granular mdr")],
        "epac": law_block("mdr", "yield_stress = 5.0e6\n",
                          'effects = ["plasticity", "radius_growth", "friction", "damping", "bulk_response"]\n'
                          'psi_b = 0.5\ncontact_penalty = "on"\npair_split = "geometric"\ndelta_max = "running_max"\n'
                          'damping = "authors"\nfriction = "authors"\ntangential_stiffness = 285714.2857142857\n'
                          'yield_onset = "hertz_40"\n'),
    },
}


def ensure_lammps(lmp, cxx_flags=None):
    """lmp, built first if missing: the peer kit's build, with cxx_flags (CMake's CXXFLAGS) if given."""
    if os.path.exists(lmp):
        return lmp
    build = os.path.dirname(lmp)
    print(f"[side_by_side] building LAMMPS into {build}{' with ' + cxx_flags if cxx_flags else ''} (first use only)",
          flush=True)
    tarball = subprocess.check_output(["bash", os.path.join(PEERS, "fetch-lammps-source.sh")], text=True).split()[-1]
    env = dict(os.environ)
    cmd = ["bash", os.path.join(PEERS, "build-lammps.sh"), tarball]
    if cxx_flags:
        env["CXXFLAGS"] = cxx_flags  # a fresh build folder takes CMAKE_CXX_FLAGS from it
        cmd += [os.path.expanduser("~/.cache/lammps-peer/src"), build]
    subprocess.check_call(cmd, stdout=subprocess.DEVNULL, env=env)
    return lmp


def march_of(flags):
    """The -march value in a flags line, or None."""
    m = re.search(r"-march=(\S+)", flags)
    return m.group(1) if m else None


def ensure_epac_run():
    build = os.environ.get("EPAC_BUILD_DIR", os.path.join(ROOT, "build"))
    exe = os.path.join(build, "drivers", "epac-run")
    if not os.path.exists(exe):
        subprocess.check_call(["cmake", "-S", ROOT, "-B", build, "-DCMAKE_BUILD_TYPE=Release"], stdout=subprocess.DEVNULL)
        subprocess.check_call(["cmake", "--build", build, "-j", str(os.cpu_count() or 2), "--target", "epac-run"],
                              stdout=subprocess.DEVNULL)
    return exe


def epac_build_flags(exe):
    """Compiler and flags epac-run was built with (the build's epac-build-flags.txt)."""
    f = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(exe))), "epac-build-flags.txt")
    return open(f).read().strip() if os.path.exists(f) else "unknown (a build without epac-build-flags.txt)"


def lammps_build_flags(lmp):
    """Compiler and flags of a LAMMPS CMake build, from the CMakeCache.txt beside its lmp."""
    f = os.path.join(os.path.dirname(os.path.realpath(lmp)), "CMakeCache.txt")
    if not os.path.exists(f):
        return "unknown (no CMakeCache.txt beside lmp)"
    cache = {}
    for line in open(f):
        m = re.match(r"^([A-Za-z_]+):[A-Z]+=(.*)$", line.strip())
        if m:
            cache[m.group(1)] = m.group(2)
    bt = cache.get("CMAKE_BUILD_TYPE", "")
    compiler = os.path.basename(cache.get("CMAKE_CXX_COMPILER", "c++"))
    return " ".join(x for x in (compiler, cache.get("CMAKE_CXX_FLAGS", ""), cache.get(f"CMAKE_CXX_FLAGS_{bt.upper()}", ""))
                    if x).strip()


def lammps_hold(lmp, pair, mode, threads, ncell, workdir, tag):
    """Runs LAMMPS; returns hold-phase loop seconds, steps and contacts (from its own log)."""
    log = os.path.join(workdir, f"log.{pair}.{threads}t.{tag}")
    cmd = [lmp, "-in", "in.fcc_compress_model", "-var", "model", pair, "-var", "ncell", str(ncell),
           "-log", log, "-screen", "none"]
    env = dict(os.environ, OMP_NUM_THREADS=str(threads if mode == "omp" else 1))
    if mode == "omp":
        cmd += ["-sf", "omp", "-pk", "omp", str(threads)]
    subprocess.check_call(cmd, cwd=PEERS, env=env)
    txt = open(log).read()
    blocks = txt.split("Loop time of ")
    last = blocks[-1]
    loop = float(last.split()[0])
    steps = int(re.search(r"for (\d+) steps", last).group(1))
    rows = [l.split() for l in blocks[-2].splitlines() if re.match(r"^\s+\d+\s+\d+\s", l)]
    contacts = float(rows[-1][3])
    pair_s = float(re.search(r"^Pair\s*\|\s*[0-9.eE+-]+\s*\|\s*([0-9.eE+-]+)", last, re.M).group(1))
    return {"loop_s": loop, "steps": steps, "contacts": contacts, "pair_s": pair_s,
            "ns_per_contact_step": 1e9 * loop / (contacts * steps)}


def run_epac(exe, scene, threads, precision, out, time_after):
    """Runs epac-run on a scene (threads unbound unless OMP_PROC_BIND is set); returns summary.json."""
    env = dict(os.environ, OMP_NUM_THREADS=str(threads), OMP_PROC_BIND=os.environ.get("OMP_PROC_BIND", "false"))
    subprocess.check_call([exe, scene, "--threads", str(threads), "--precision", precision, "--quiet",
                           "--out", out, "--overwrite", "--time-after", str(time_after)], env=env)
    return json.load(open(os.path.join(out, "summary.json")))


def epac_hold(exe, law, threads, precision, ncell, workdir, tag, deform_steps=500, order=None, spatial_sort=None):
    scene = os.path.join(workdir, f"fcc_{law}_{order}_{spatial_sort}.toml")
    with open(scene, "w") as f:
        f.write(fcc_scene(LAWS[law]["epac"], ncell, order=order, spatial_sort=spatial_sort))
    out = os.path.join(workdir, f"epac.{law}.{precision}.{threads}t.{tag}")
    s = run_epac(exe, scene, threads, precision, out, deform_steps)
    t = s["timed"]
    return {"loop_s": t["wall_s"], "steps": t["steps"], "contacts": t["active_contacts_mean"],
            "list_contacts": t["list_contacts_mean"], "force_s": (s.get("phases") or {}).get("force"),
            "ns_per_contact_step": 1e9 * t["wall_s"] / (t["active_contacts_mean"] * t["steps"])}


def legacy_hold(exe, law, threads, workdir, tag):
    """An epac-run without periodic boxes or --time-after (a "before" build) on the wall-wrapped
    scene (legacy_walls_scene.py): the hold phase is the 700-step run minus the 500-step run."""
    scene = os.path.join(workdir, f"fcc_walls_{law}.toml")
    if not os.path.exists(scene):
        with open(scene, "w") as f:
            f.write(subprocess.check_output([sys.executable, os.path.join(os.path.dirname(__file__), "legacy_walls_scene.py"),
                                             "--epac-run", ensure_epac_run(), "--law", law], text=True))
    env = dict(os.environ, OMP_NUM_THREADS=str(threads), OMP_PROC_BIND=os.environ.get("OMP_PROC_BIND", "false"))
    t = {}
    for steps in (500, 700):
        out = os.path.join(workdir, f"legacy.{law}.{threads}t.{steps}.{tag}")
        shutil.rmtree(out, ignore_errors=True)  # a fresh folder: old builds have no --overwrite
        subprocess.check_call([exe, scene, "--threads", str(threads), "--quiet", "--steps", str(steps), "--out", out],
                              env=env)
        t[steps] = json.load(open(os.path.join(out, "summary.json")))["wall_time_s"]
        if steps == 700:
            rows = list(csv.DictReader(open(os.path.join(out, "timeseries.csv"))))
            active = [float(r["pair_contacts"]) + float(r["wall_contacts"]) for r in rows if int(r["step"]) > 500]
    contacts = sum(active) / len(active)
    loop = t[700] - t[500]
    return {"loop_s": loop, "steps": 200, "contacts": contacts, "ns_per_contact_step": 1e9 * loop / (contacts * 200)}


# The settling scene (settling_scene.py): Hertz-Mindlin only, since LAMMPS's floor (fix wall/gran
# hertz/history) takes the coefficients of gran/hertz/history. Timed: the second half of the run.
SETTLING_LAMMPS = [("hhist_omp", "omp", "gran/hertz/history/omp")]
SETTLING_G = 20000.0  # m/s^2: the bed forms within the run's 4,000 steps of 5e-7 s (2 ms)
SETTLING_WARM, SETTLING_TIMED = 2000, 2000


def settling_files(workdir, law, nxy, nz):
    """Writes the scene for both codes once; returns (epac scene, epac scene unsorted, LAMMPS data)."""
    spheres, L, H = settling_scene.settling_spheres(nxy, nz)
    names = [os.path.join(workdir, f"settling_{law}.toml"), os.path.join(workdir, f"settling_{law}_unsorted.toml"),
             os.path.join(workdir, "settling.data")]
    if not os.path.exists(names[0]):
        text = settling_scene.epac_scene(LAWS[law]["epac"], spheres, L, H, SETTLING_G, SETTLING_WARM + SETTLING_TIMED)
        open(names[0], "w").write(text)
        open(names[1], "w").write(text.replace("[run]\n", "[run]\nspatial_sort = false\n", 1))
        open(names[2], "w").write(settling_scene.lammps_data(spheres, L, H))
    return names


def lammps_settling(lmp, pair, mode, threads, data, workdir, tag):
    """LAMMPS on the settling scene (bench/peers/lammps/in.settling): loop seconds of the timed run and
    the mean of its pair contacts (thermo every 100 steps, after the warm-up)."""
    log = os.path.join(workdir, f"log.settling.{pair}.{threads}t.{tag}")
    cmd = [lmp, "-in", "in.settling", "-var", "model", pair, "-var", "data", data, "-var", "g", repr(SETTLING_G),
           "-var", "nwarm", str(SETTLING_WARM), "-var", "nrun", str(SETTLING_TIMED), "-log", log, "-screen", "none"]
    env = dict(os.environ, OMP_NUM_THREADS=str(threads if mode == "omp" else 1))
    if mode == "omp":
        cmd += ["-sf", "omp", "-pk", "omp", str(threads)]
    subprocess.check_call(cmd, cwd=os.path.join(os.path.dirname(os.path.abspath(__file__)), "lammps"), env=env)
    last = open(log).read().split("Loop time of ")
    loop = float(last[-1].split()[0])
    rows = [l.split() for l in last[-2].splitlines() if re.match(r"^\s+\d+\s+\d+\s", l)]
    counts = [float(r[3]) for r in rows if int(r[0]) > SETTLING_WARM]
    contacts = sum(counts) / len(counts)
    pair_s = float(re.search(r"^Pair\s*\|\s*[0-9.eE+-]+\s*\|\s*([0-9.eE+-]+)", last[-1], re.M).group(1))
    return {"loop_s": loop, "steps": SETTLING_TIMED, "contacts": contacts, "pair_s": pair_s,
            "ns_per_contact_step": 1e9 * loop / (contacts * SETTLING_TIMED)}


def epac_settling(exe, scene, threads, precision, workdir, tag):
    """epac-run on the settling scene: the timed window's seconds per pair contact-step (the pair
    contacts of timeseries.csv after the warm-up, as LAMMPS's compute contact/atom counts them)."""
    out = os.path.join(workdir, f"epac.settling.{precision}.{threads}t.{tag}")
    s = run_epac(exe, scene, threads, precision, out, SETTLING_WARM)
    t = s["timed"]
    rows = list(csv.DictReader(open(os.path.join(out, "timeseries.csv"))))
    counts = [float(r["pair_contacts"]) for r in rows if int(r["step"]) > SETTLING_WARM]
    contacts = sum(counts) / len(counts)
    return {"loop_s": t["wall_s"], "steps": t["steps"], "contacts": contacts, "list_contacts": t["list_contacts_mean"],
            "force_s": (s.get("phases") or {}).get("force"),
            "ns_per_contact_step": 1e9 * t["wall_s"] / (contacts * t["steps"])}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--threads", type=int, nargs="+", default=[1, 2])
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--laws", nargs="+", default=list(LAWS), choices=list(LAWS))
    ap.add_argument("--precision", nargs="+", default=["double"], choices=["double", "float"])
    ap.add_argument("--ncell", type=int, default=14)
    ap.add_argument("--scene", default="fcc", choices=["fcc", "mixed", "settling"],
                    help="mixed: epac's particles in a random order ([particles] order = \"shuffled\"), the order a "
                         "long mixing flow ends in; epac's default spatial sort is timed against the same build with "
                         "spatial_sort = false (the 'before' column). LAMMPS runs its own input, which it sorts "
                         "spatially at the setup of every run (verlet.cpp), so its input order does not matter. "
                         "Use --ncell 30 (108,000 spheres, about 650,000 contacts). settling: spheres in a random "
                         "order fall onto a floor (settling_scene.py; Hertz-Mindlin against gran/hertz/history/omp, "
                         "--settling-grid), epac's default sort against spatial_sort = false as for mixed")
    ap.add_argument("--settling-grid", type=int, nargs=2, default=[44, 24], metavar=("NXY", "NZ"),
                    help="settling: spheres per grid row in x and y, and layers (default 44 24: 46,464 spheres, "
                         "about 1e5 contacts in the timed half)")
    ap.add_argument("--json", default=None, help="write the measurements here")
    ap.add_argument("--lmp", default=os.environ.get("LMP"),
                    help=f"the LAMMPS executable (default: {LMP_DEFAULT}, or {LMP_NATIVE} built with "
                         f"'{NATIVE_FLAGS}' when epac-run was built with -march=native, {LMP_NATIVE_NO_GATHER} "
                         f"with '{NO_GATHER}' added where epac-run has it too; built on first use)")
    ap.add_argument("--legacy-epac-run", default=None,
                    help="an older epac-run without periodic boxes (a 'before' build): also timed, on the "
                         "wall-wrapped scene (legacy_walls_scene.py)")
    ap.add_argument("--before-epac-run", default=None,
                    help="an epac-run built from an earlier commit (with periodic boxes and --time-after): timed "
                         "on the same scene and precisions, alternating with the current one (before/after a change)")
    args = ap.parse_args()

    exe = ensure_epac_run()
    exe_flags = epac_build_flags(exe)  # read once, used for the peer build and the table
    if args.lmp:
        lmp = ensure_lammps(args.lmp)
    elif march_of(exe_flags) == "native" and NO_GATHER in exe_flags:
        lmp = ensure_lammps(LMP_NATIVE_NO_GATHER, NATIVE_FLAGS + " " + NO_GATHER)
    elif march_of(exe_flags) == "native":
        lmp = ensure_lammps(LMP_NATIVE, NATIVE_FLAGS)
    else:
        lmp = ensure_lammps(LMP_DEFAULT)
    order = "shuffled" if args.scene == "mixed" else None
    settling = args.scene == "settling"
    if (args.scene == "mixed" and args.before_epac_run) or (args.scene != "fcc" and args.legacy_epac_run):
        ap.error(f"--scene {args.scene} times its own 'before' (spatial_sort = false): no --before/--legacy-epac-run")
    if settling and args.laws != ["hm"]:
        ap.error("--scene settling runs Hertz-Mindlin only (--laws hm): LAMMPS's floor, fix wall/gran hertz/history, "
                 "takes gran/hertz/history's coefficients")
    results = []
    with tempfile.TemporaryDirectory(prefix="epac-peers-") as work:
        for law in args.laws:
            for t in args.threads:
                best = {}
                styles = SETTLING_LAMMPS if settling else LAWS[law]["lammps"]
                if settling:
                    scene, unsorted, data = settling_files(work, law, *args.settling_grid)
                for r in range(args.repeats):
                    for pair, mode, title in styles:
                        if settling:
                            m = lammps_settling(lmp, pair, mode, t, data, work, f"r{r}")
                        else:
                            m = lammps_hold(lmp, pair, mode, t, args.ncell, work, f"r{r}")
                        key = ("lammps", pair)
                        if key not in best or m["ns_per_contact_step"] < best[key]["ns_per_contact_step"]:
                            best[key] = dict(m, title=title, mode=mode)
                    for prec in args.precision:
                        if settling:
                            # before: an earlier build on the same scene, or this one unsorted
                            runs = ((exe, ("epac", prec), scene),
                                    (args.before_epac_run or exe, ("before", prec), scene if args.before_epac_run else unsorted))
                            for x, key, sc in runs:
                                m = epac_settling(x, sc, t, prec, work, f"{key[0]}.r{r}")
                                if key not in best or m["ns_per_contact_step"] < best[key]["ns_per_contact_step"]:
                                    best[key] = m
                            continue
                        m = epac_hold(exe, law, t, prec, args.ncell, work, f"r{r}", order=order)
                        key = ("epac", prec)
                        if key not in best or m["loop_s"] < best[key]["loop_s"]:
                            best[key] = m
                        if order:
                            m = epac_hold(exe, law, t, prec, args.ncell, work, f"unsorted.r{r}", order=order,
                                          spatial_sort=False)
                            key = ("before", prec)
                            if key not in best or m["loop_s"] < best[key]["loop_s"]:
                                best[key] = m
                    if args.before_epac_run and not settling:
                        for prec in args.precision:
                            m = epac_hold(args.before_epac_run, law, t, prec, args.ncell, work, f"before.r{r}")
                            key = ("before", prec)
                            if key not in best or m["loop_s"] < best[key]["loop_s"]:
                                best[key] = m
                    if args.legacy_epac_run:
                        m = legacy_hold(args.legacy_epac_run, law, t, work, f"r{r}")
                        if "legacy" not in best or m["loop_s"] < best["legacy"]["loop_s"]:
                            best["legacy"] = m
                for prec in args.precision:
                    e = best[("epac", prec)]
                    row = {"law": law, "title": LAWS[law]["title"], "threads": t, "precision": prec,
                           "epac_ns": e["ns_per_contact_step"], "epac_contacts": e["contacts"], "peers": []}
                    if "legacy" in best:
                        row["before_ns"] = best["legacy"]["ns_per_contact_step"]
                        row["before_contacts"] = best["legacy"]["contacts"]
                    if ("before", prec) in best:
                        row["before_ns"] = best[("before", prec)]["ns_per_contact_step"]
                        row["before_contacts"] = best[("before", prec)]["contacts"]
                    for pair, mode, title in styles:
                        l = best[("lammps", pair)]
                        row["peers"].append({"style": title, "pair_file": f"pair.{pair}", "threaded": mode == "omp",
                                             "lammps_ns": l["ns_per_contact_step"], "lammps_contacts": l["contacts"],
                                             "lammps_pair_ns": 1e9 * l["pair_s"] / (l["contacts"] * l["steps"]),
                                             "speedup": l["ns_per_contact_step"] / e["ns_per_contact_step"]})
                    results.append(row)
                    print(json.dumps(row), flush=True)

    flags = {"epac": exe_flags, "lammps": lammps_build_flags(lmp)}
    if args.before_epac_run:
        flags["epac_before"] = epac_build_flags(args.before_epac_run)
    print()
    for k, v in flags.items():
        print(f"{k} built with: {v}")
    if march_of(flags["epac"]) != march_of(flags["lammps"]):
        def arch(code):
            return f"-march={march_of(flags[code])}" if march_of(flags[code]) else "no -march"
        print(f"warning: the two codes were built for different CPUs (epac {arch('epac')}, LAMMPS {arch('lammps')}): "
              "the speedups mix the codes with their flags")
    print()
    print(f"Hold phase, whole step loop, ns per active contact-step (best of {args.repeats}); "
          "speedup = LAMMPS time / epac time (> 1: epac faster)")
    if order:
        print(f"Scene: mixed (fcc ncell {args.ncell}, epac's particles shuffled); epac before = spatial_sort = false, "
              "epac = the default (auto)")
    if settling:
        nxy, nz = args.settling_grid
        print(f"Scene: settling ({nxy * nxy * nz} spheres in a random order falling onto a floor, gravity "
              f"{SETTLING_G:g} m/s^2, timed steps {SETTLING_WARM + 1}-{SETTLING_WARM + SETTLING_TIMED}; per pair "
              "contact-step); " + ("epac before = --before-epac-run" if args.before_epac_run else
                                  "epac before = spatial_sort = false, epac = the default (auto)"))
    print()
    legacy = args.legacy_epac_run is not None or args.before_epac_run is not None or args.scene != "fcc"
    print("| law | threads |" + (" epac before |" if legacy else "") + " epac |" + (" after / before |" if legacy else "")
          + " LAMMPS style | LAMMPS | speedup |")
    print("|---|---|" + ("---|---|" if legacy else "") + "---|---|---|---|")
    for row in results:
        label = f"{row['title']}" + (f" [{row['precision']}]" if len(args.precision) > 1 else "")
        before = f" {row['before_ns']:.1f} |" if legacy else ""
        ratio = f" {row['epac_ns'] / row['before_ns']:.2f} |" if legacy else ""
        if not row["peers"]:
            print(f"| {label} | {row['threads']} |{before} {row['epac_ns']:.1f} |{ratio} (no LAMMPS peer) | - | - |")
        for p in row["peers"]:
            note = "" if p["threaded"] else " (no threaded style: 1 thread)"
            print(f"| {label} | {row['threads']} |{before} {row['epac_ns']:.1f} |{ratio} {p['style']}{note} | "
                  f"{p['lammps_ns']:.1f} | {p['speedup']:.2f} |")
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"repeats": args.repeats, "ncell": args.ncell, "scene": args.scene,
                       "settling_grid": args.settling_grid if settling else None, "build_flags": flags,
                       "results": results}, f, indent=1)


if __name__ == "__main__":
    main()
