#!/usr/bin/env python3
"""Strong and weak scaling of epac-run on the fcc benchmark scene (bench/peers/fcc_compress.toml).

  strong: one scene (--strong-ncell, default 17: 19,652 spheres, about 118,000 contacts in the
          hold phase), run with each thread count;
  weak:   about --weak-per-thread spheres per thread (fcc lattice of 4 n^3 spheres, n rounded),
          run with each thread count.
Each configuration runs --repeats times; the JSON keeps every repeat and the best (fastest) one,
with contact-steps/s, particle-steps/s and the seconds per phase of the step loop (detection,
remap, force, growth, integration, output: epac-run --phase-times). Efficiency: strong,
t(1) / (N t(N)); weak, t(1) / t(N) (times of the best repeats).

On a GPU build (the summary's backend is not a host backend) thread counts mean nothing: the
script runs the device once per size instead (strong: the one scene; weak: the sizes of the
host sweep, or the fcc sizes of --device-ncell: 4 n^3 spheres each), with the same JSON and plot,
so it runs unchanged there (cmake/device-run.sh uses --device-ncell 10 20 30).

Usage:
  python3 bench/scaling/run_scaling.py [--threads 1 2] [--repeats 3] [--steps 700] [--law hm]
                                       [--json scaling.json] [--png scaling.png] [--smoke]
--smoke: a seconds-long run (tiny scene, 1 repeat) for CI; it checks the JSON, never a timing.
epac-run: $EPAC_BUILD_DIR/drivers/epac-run (default build/), or --exe.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "peers"))
from fcc_scene import ROOT, fcc_scene  # noqa: E402

HOST_BACKENDS = {"OpenMP", "Serial", "Threads", "HPX"}
PHASES = ["detection", "remap", "force", "growth", "integration", "output"]


def run_once(exe, scene_text, threads, workdir, tag):
    scene = os.path.join(workdir, f"{tag}.toml")
    with open(scene, "w") as f:
        f.write(scene_text)
    out = os.path.join(workdir, tag)
    env = dict(os.environ, OMP_NUM_THREADS=str(threads), OMP_PROC_BIND=os.environ.get("OMP_PROC_BIND", "false"))
    # --overwrite: a rerun with the same --work replaces its outputs (epac-run refuses a used folder)
    subprocess.check_call([exe, scene, "--threads", str(threads), "--quiet", "--phase-times", "--out", out, "--overwrite"],
                          env=env)
    s = json.load(open(os.path.join(out, "summary.json")))
    return {
        "wall_s": s["wall_time_s"],
        "steps": s["steps"],
        "particles": s["particles"],
        "contacts_mean": s["contacts_mean"],
        "contact_steps_per_second": s["contact_steps_per_second"],
        "particle_steps_per_second": s["particle_steps_per_second"],
        "phases": {k: (s.get("phases") or {}).get(k) for k in PHASES},
        "backend": s["backend"],
        "threads": s["threads"],
    }


def sweep(exe, configs, repeats, workdir, label):
    rows = []
    for threads, ncell in configs:
        reps = []
        for r in range(repeats):
            reps.append(run_once(exe, configs[(threads, ncell)], threads, workdir, f"{label}_{threads}t_{ncell}_{r}"))
        best = min(reps, key=lambda m: m["wall_s"])
        rows.append({"threads": threads, "ncell": ncell, "particles": best["particles"], "best": best,
                     "repeats": reps})
        print(f"[scaling] {label}: {threads} threads, {best['particles']} particles: "
              f"{best['contact_steps_per_second']:.3g} contact-steps/s", flush=True)
    return rows


def plot(result, path):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("[scaling] matplotlib not available (Debian: python3-matplotlib; run with /usr/bin/python3): no plot",
              file=sys.stderr)
        return False
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for ax, kind in zip(axes, ["strong", "weak"]):
        rows = result[kind]
        x = [r["threads"] if result["host"] else r["particles"] for r in rows]
        ax.plot(x, [r["efficiency"] for r in rows], "o-", label="efficiency")
        ax.axhline(1.0, color="grey", lw=0.8)
        ax.set_ylim(0, 1.2)
        ax.set_xlabel("threads" if result["host"] else "particles")
        ax.set_ylabel("parallel efficiency")
        ax2 = ax.twinx()
        ax2.plot(x, [r["best"]["contact_steps_per_second"] for r in rows], "s--", color="C1")
        ax2.set_ylabel("contact-steps/s", color="C1")
        ax.set_title(f"{kind} scaling ({result['backend']}, {result['law']})")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    return True


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--threads", type=int, nargs="+", default=None, help="default: 1 .. number of cores")
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--steps", type=int, default=700, help="steps per run (compression is the first 5/7)")
    ap.add_argument("--strong-ncell", type=int, default=17)
    ap.add_argument("--weak-per-thread", type=int, default=10000)
    ap.add_argument("--json", default="scaling.json")
    ap.add_argument("--png", default="scaling.png")
    ap.add_argument("--exe", default=None)
    ap.add_argument("--smoke", action="store_true", help="tiny and fast, for CI (checks the JSON only)")
    ap.add_argument("--device-ncell", type=int, nargs="+", default=None,
                    help="on a GPU build: the fcc sizes (cells per side) of the size sweep")
    args = ap.parse_args()

    exe = args.exe or os.path.join(os.environ.get("EPAC_BUILD_DIR", os.path.join(ROOT, "build")), "drivers", "epac-run")
    if not os.path.exists(exe):
        sys.exit(f"{exe} not found: build it first (bash cmake/dev.sh run builds it) or pass --exe")
    threads = args.threads or list(range(1, (os.cpu_count() or 1) + 1))
    steps, strong_ncell, per_thread, repeats = args.steps, args.strong_ncell, args.weak_per_thread, args.repeats
    if args.smoke:
        steps, strong_ncell, per_thread, repeats = 40, 4, 256, 1
    deform = max(1, steps * 5 // 7)

    def scene(ncell):
        return fcc_scene(ncell=ncell, steps=steps, deform_steps=deform, output_interval=steps)

    def weak_ncell(t):
        return max(3, round((per_thread * t / 4.0) ** (1.0 / 3.0)))

    with tempfile.TemporaryDirectory(prefix="epac-scaling-") as work:
        probe = run_once(exe, scene(3), threads[0], work, "probe")
        host = probe["backend"] in HOST_BACKENDS
        if not host:
            threads = [1]
        strong_cfg = {(t, strong_ncell): scene(strong_ncell) for t in threads}
        if host:
            weak_cfg = {(t, weak_ncell(t)): scene(weak_ncell(t)) for t in threads}
        elif args.device_ncell:  # one device: weak scaling becomes a size sweep
            weak_cfg = {(1, n): scene(n) for n in args.device_ncell}
        else:  # at the host sweep's sizes
            weak_cfg = {(1, weak_ncell(t)): scene(weak_ncell(t)) for t in (args.threads or [1, 2, 4, 8])}
        result = {"backend": probe["backend"], "host": host, "law": "hertz_mindlin", "steps": steps,
                  "repeats": repeats, "strong": sweep(exe, strong_cfg, repeats, work, "strong"),
                  "weak": sweep(exe, weak_cfg, repeats, work, "weak")}

    s0 = result["strong"][0]["best"]
    for r in result["strong"]:
        b = r["best"]
        r["efficiency"] = s0["wall_s"] / (b["wall_s"] * (r["threads"] / result["strong"][0]["threads"])) if host else 1.0
    w0 = result["weak"][0]["best"]
    for r in result["weak"]:
        b = r["best"]
        # per-particle time ratio: sizes round to whole lattices, so compare particle-steps/s per thread
        per_thread_rate = b["particle_steps_per_second"] / (r["threads"] if host else 1)
        r["efficiency"] = per_thread_rate / (w0["particle_steps_per_second"] / (result["weak"][0]["threads"] if host else 1))
    with open(args.json, "w") as f:
        json.dump(result, f, indent=1)
    print(f"[scaling] wrote {args.json}")
    if plot(result, args.png):
        print(f"[scaling] wrote {args.png}")
    print("| kind | threads | particles | contact-steps/s | particle-steps/s | efficiency | force s | detection s |")
    print("|---|---|---|---|---|---|---|---|")
    for kind in ("strong", "weak"):
        for r in result[kind]:
            b = r["best"]
            ph = b["phases"]
            print(f"| {kind} | {r['threads']} | {r['particles']} | {b['contact_steps_per_second']:.3g} | "
                  f"{b['particle_steps_per_second']:.3g} | {r['efficiency']:.2f} | "
                  f"{ph['force'] if ph['force'] is not None else float('nan'):.3f} | "
                  f"{ph['detection'] if ph['detection'] is not None else float('nan'):.3f} |")


if __name__ == "__main__":
    main()
