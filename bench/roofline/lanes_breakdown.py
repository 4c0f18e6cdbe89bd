#!/usr/bin/env python3
"""Where the lanes kernel's time goes: one pass of the lanes kernel (kernels/epac/compute/
pair_lanes.hpp) timed with stages switched off, on the fcc scene's hold, against the same pass
with nothing off.

Each variant is the driver's model file for the law (drivers/driver/models/<law>.cpp) compiled
from a patched copy of kernels/ with the flags of an existing build, linked into a copy of
`epac-run`; the repository's kernels are not touched. In the hold (after the compression's 500
lane passes, one per step) the patched kernel first runs one extra pass with the variant's stages
off on copies of the history, forces and torques, timed on its own (sums begin/end included),
then the real pass: the run's physics is the unchanged one, and every timed pass starts from the
true state of its step. Variants:
  unchanged     nothing off (the reference, timed the same way)
  no_scatter    stage 6 off: no particle sums
  compute_only  also no particle gather (every lane loads the block's first pair, so the loads
                become broadcasts) and no Coulomb sliding stage: the arithmetic, the list and
                the history. Laws without normal history only (Hertz-Mindlin): with the first
                pair's overlap against another contact's history, Nan 2022's and JKR's lanes
                turn rare and take the one-contact code, which is not the common path's time
Runs alternate between the variants, pinned to one core (`taskset -c 0` where present), one
thread; each row is the best and the median over the runs of the timed passes' mean, in ns per
contact (list entry) of the pass, and the run's own force phase (two passes now) for reference.

  python3 bench/roofline/lanes_breakdown.py --build build --laws hm nan [--repeats 5] [--ncell 14]
  python3 bench/roofline/lanes_breakdown.py --self-test   # the patches still apply; no build
Needs a built `build` (epac-run) of a native build: the lanes run where `-DEPAC_ARCH` gives the
host vector width. About half a minute per variant to build, and 2-3 s per run.
"""
import argparse
import json
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "peers"))

LANES = os.path.join("epac", "compute", "pair_lanes.hpp")
MODEL_FILES = {"hm": "hertz_mindlin", "nan": "nan2022", "jkr": "jkr"}  # side_by_side.py's lane laws
NORMAL_HISTORY = {"nan", "jkr"}  # laws whose lanes keep normal history (no compute_only row)
HOLD_AFTER = 500  # lane passes before the variant's stages go off: the compression

# (anchor, replacement): each anchor must occur exactly once in pair_lanes.hpp. The kernel becomes
# pair_kernel_lanes_breakdown_impl with a template argument Off (1: no scatter; 2: no particle
# gather and no sliding stage), and a new pair_kernel_lanes (WRAPPER) runs it as before after
# timing one pass with the stages BREAKDOWN_OFF off on copies of the history and the sums.
SIGNATURE = ("template <int W, class Model, class T, class Device, class Policy>\n"
             "void pair_kernel_lanes(const Model& model, const Particles<T, Device>& p, const ContactList<Device>& c,\n"
             "                       const ContactHistory<T, Device>& h, T dt, const ForceSums<T, Device, Policy>& sums,\n"
             "                       const ContactOutputs<T, Device>& out) {",
             "template <int W, int Off, class Model, class T, class Device, class Policy>\n"
             "void pair_kernel_lanes_breakdown_impl(const Model& model, const Particles<T, Device>& p,\n"
             "    const ContactList<Device>& c, const ContactHistory<T, Device>& h, T dt,\n"
             "    const ForceSums<T, Device, Policy>& sums, const ContactOutputs<T, Device>& out) {\n"
             "  // at compile time: a stage that is on is the unchanged kernel's code (a runtime flag in the\n"
             "  // gather stopped the common path's vectorisation)\n"
             "  constexpr bool no_scatter = (Off & 1) != 0, no_gather = (Off & 2) != 0;")
GATHER = ("          const Index i = L_i[l], j = L_j[l];\n          const double dx",
          "          const Index i = no_gather ? L_i[0] : L_i[l], j = no_gather ? L_j[0] : L_j[l];\n"
          "          const double dx")
SLIDING = ("        if (friction)\n          for (int l = 0; l < lanes; ++l) {\n            if (L_slides[l] == T(0)) continue;",
           "        if (friction && !no_gather)\n          for (int l = 0; l < lanes; ++l) {\n"
           "            if (L_slides[l] == T(0)) continue;")
SCATTER = ("        // 6. scatter (the rare lanes are done)\n        for (int l = 0; l < lanes; ++l) {",
           "        // 6. scatter (the rare lanes are done)\n        for (int l = 0; l < (no_scatter ? 0 : lanes); ++l) {")
END = ("}  // namespace detail\n}  // namespace epac", None)
WRAPPER = """
struct LanesBreakdownReport {  // printed at exit: the timed passes' mean
  double seconds = 0, contact_steps = 0;
  long passes = 0;
  ~LanesBreakdownReport() {
    std::fprintf(stderr, "lanes_breakdown: off %d passes %ld ns_per_contact %.6f\\n", BREAKDOWN_OFF, passes,
                 contact_steps > 0 ? seconds / contact_steps * 1e9 : 0.0);
  }
};

template <int W, class Model, class T, class Device, class Policy>
void pair_kernel_lanes(const Model& model, const Particles<T, Device>& p, const ContactList<Device>& c,
                       const ContactHistory<T, Device>& h, T dt, const ForceSums<T, Device, Policy>& sums,
                       const ContactOutputs<T, Device>& out) {
  static long calls = 0;
  static LanesBreakdownReport report;
  if (++calls > BREAKDOWN_AFTER && c.count > 0) {
    // the same pass on copies (history, forces, torques): the hold's state, the stages off. The
    // copies are allocated once (a fresh allocation per pass would time its page faults)
    static ContactHistory<T, Device> hc;
    static Particles<T, Device> pc;
    static ForceSums<T, Device, Policy> sc;
    static bool hooked = false;
    if (!hooked) {  // Views must go before Kokkos::finalize
      Kokkos::push_finalize_hook([] {
        hc = ContactHistory<T, Device>();
        pc = Particles<T, Device>();
        sc = ForceSums<T, Device, Policy>();
      });
      hooked = true;
    }
    if (hc.data.extent(0) != h.data.extent(0) || hc.data.extent(1) != h.data.extent(1))
      hc.data = typename ContactHistory<T, Device>::data_view("breakdown.history", h.data.extent(0), h.data.extent(1));
    hc.fields = h.fields;
    Kokkos::deep_copy(hc.data, h.data);
    const auto force = pc.force, torque = pc.torque;
    pc = p;
    pc.force = static_cast<int>(force.extent(0)) == p.n ? force : decltype(p.force)("breakdown.force", p.n);
    pc.torque = static_cast<int>(torque.extent(0)) == p.n ? torque : decltype(p.torque)("breakdown.torque", p.n);
    if (!sc.bound_to(pc)) sc = ForceSums<T, Device, Policy>(pc);
    Kokkos::fence();
    Kokkos::Timer timer;
    sc.begin(true);
    pair_kernel_lanes_breakdown_impl<W, BREAKDOWN_OFF>(model, pc, c, hc, dt, sc, ContactOutputs<T, Device>{});
    sc.end(true);
    Kokkos::fence();
    report.seconds += timer.seconds();
    report.contact_steps += c.count;
    ++report.passes;
  }
  pair_kernel_lanes_breakdown_impl<W, 0>(model, p, c, h, dt, sums, out);
}

"""
HEADER = ("#include <stdexcept>\n", "#include <cstdio>\n#include <stdexcept>\n")

VARIANTS = {  # name: the stages off (BREAKDOWN_OFF)
    "unchanged": 0,
    "no_scatter": 1,
    "compute_only": 3,
}


def patch(text):
    """pair_lanes.hpp with the breakdown switches; raises if an anchor is missing or repeated."""
    for anchor, new in (HEADER, SIGNATURE, GATHER, SLIDING, SCATTER, END):
        n = text.count(anchor)
        if n != 1:
            raise SystemExit(f"lanes_breakdown: {LANES}: expected one\n{anchor}\nfound {n}: update the script's anchors")
        text = text.replace(anchor, new if new is not None else WRAPPER + anchor)
    return text


def build_flags(build):
    """(compiler, flags, defines, includes) of the driver library's objects in `build`."""
    flags_make = os.path.join(build, "drivers", "CMakeFiles", "epac_driver.dir", "flags.make")
    vals, compiler = {}, None
    for line in open(flags_make):
        m = re.match(r"^(CXX_FLAGS|CXX_DEFINES|CXX_INCLUDES)\s*=\s*(.*)$", line)
        if m:
            vals[m.group(1)] = m.group(2).strip()
        m = re.match(r"^# compile CXX with (\S+)", line)
        if m:
            compiler = m.group(1)
    if compiler is None or "CXX_FLAGS" not in vals:
        raise SystemExit(f"lanes_breakdown: cannot read {flags_make}")
    return compiler, vals["CXX_FLAGS"], vals.get("CXX_DEFINES", ""), vals.get("CXX_INCLUDES", "")


def build_variant(build, law, name, work):
    """A copy of epac-run whose <law> model object comes from the patched kernels."""
    off = VARIANTS[name]
    d = os.path.join(work, name)
    shutil.rmtree(d, ignore_errors=True)
    kernels = os.path.join(d, "kernels")
    shutil.copytree(os.path.join(ROOT, "kernels", "epac"), os.path.join(kernels, "epac"))
    lanes = os.path.join(kernels, LANES)
    text = patch(open(lanes).read())
    open(lanes, "w").write(text)
    compiler, flags, defines, includes = build_flags(build)
    drivers = os.path.join(build, "drivers")
    obj = os.path.join(d, MODEL_FILES[law] + ".cpp.o")
    cmd = (f"{compiler} {defines} -I{kernels} {includes} {flags} -DBREAKDOWN_AFTER={HOLD_AFTER} "
           f"-DBREAKDOWN_OFF={off} "
           f"-c {os.path.join(ROOT, 'drivers', 'driver', 'models', MODEL_FILES[law] + '.cpp')} -o {obj}")
    subprocess.run(cmd, shell=True, check=True)
    shutil.copy(os.path.join(drivers, "libepac_driver.a"), os.path.join(d, "libepac_driver.a"))
    # the archive's member has the object's file name: `ar r` replaces it
    subprocess.run(["ar", "r", os.path.join(d, "libepac_driver.a"), obj], check=True, capture_output=True)
    link = open(os.path.join(drivers, "CMakeFiles", "epac-run.dir", "link.txt")).read().strip()
    link = link.replace(" libepac_driver.a", " " + os.path.join(d, "libepac_driver.a"))
    link = re.sub(r"-o epac-run\b", "-o " + os.path.join(d, "epac-run"), link)
    subprocess.run(link, shell=True, check=True, cwd=drivers)
    return os.path.join(d, "epac-run")


def time_hold(exe, scene, out):
    """(whole loop, force phase, the timed passes) in ns per contact-step of the hold."""
    pin = ["taskset", "-c", "0"] if shutil.which("taskset") else []
    env = dict(os.environ, OMP_NUM_THREADS="1", OMP_PROC_BIND=os.environ.get("OMP_PROC_BIND", "false"))
    r = subprocess.run(pin + [exe, scene, "--threads", "1", "--quiet", "--out", out, "--overwrite", "--time-after",
                              str(HOLD_AFTER), "--phase-times"], check=True, capture_output=True, text=True, env=env)
    m = re.search(r"lanes_breakdown: off (\d+) passes (\d+) ns_per_contact ([0-9.]+)", r.stderr)
    if not m or int(m.group(2)) == 0:
        raise SystemExit(f"lanes_breakdown: {exe} timed no lanes pass (does this law run in lanes here?)")
    t = json.load(open(os.path.join(out, "summary.json")))["timed"]
    cs = t["active_contacts_mean"] * t["steps"]
    return t["wall_s"] / cs * 1e9, t["phases"]["force"] / cs * 1e9, float(m.group(3))


def self_test():
    text = open(os.path.join(ROOT, "kernels", LANES)).read()
    patched = patch(text)
    for word in ("no_scatter ? 0 : lanes", "no_gather ? L_i[0]", "!no_gather", "BREAKDOWN_AFTER",
                 "pair_kernel_lanes_breakdown_impl<W, 0>(model, p, c, h, dt, sums, out);"):
        assert word in patched, word
    try:
        patch("nothing to patch")
        raise AssertionError("a missing anchor must fail")
    except SystemExit:
        pass
    print("lanes_breakdown self-test: the patches apply to", LANES)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--laws", nargs="+", default=["hm"], choices=sorted(MODEL_FILES))
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--ncell", type=int, default=14)
    ap.add_argument("--work", default=None, help="folder for the variant builds (default: a temporary one)")
    ap.add_argument("--self-test", action="store_true")
    a = ap.parse_args()
    if a.self_test:
        return self_test()
    import fcc_scene
    import side_by_side
    work = a.work or tempfile.mkdtemp(prefix="lanes_breakdown_")
    os.makedirs(work, exist_ok=True)
    build = os.path.abspath(a.build)
    print("| law | variant | timed pass: best / median | minus the next variant | the run's force phase (best) |")
    print("|---|---|---|---|---|")
    for law in a.laws:
        scene = os.path.join(work, f"{law}.toml")
        open(scene, "w").write(fcc_scene.fcc_scene(side_by_side.LAWS[law]["epac"], a.ncell))
        names = [v for v in VARIANTS if v != "compute_only" or law not in NORMAL_HISTORY]
        exes = {v: build_variant(build, law, v, os.path.join(work, law)) for v in names}
        runs = {v: [] for v in names}
        for _ in range(a.repeats):
            for v, exe in exes.items():
                runs[v].append(time_hold(exe, scene, os.path.join(work, law, v, "out")))
        best = {v: min(x[2] for x in runs[v]) for v in names}
        for k, v in enumerate(names):
            passes = [x[2] for x in runs[v]]
            share = f"{best[v] - best[names[k + 1]]:.2f}" if k + 1 < len(names) else ""
            force = [x[1] for x in runs[v]]
            print(f"| {law} | {v} | {min(passes):.2f} / {statistics.median(passes):.2f} | {share} | "
                  f"{min(force):.2f} |")


if __name__ == "__main__":
    main()
