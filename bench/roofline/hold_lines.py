#!/usr/bin/env python3
"""Instructions per contact-step of the fcc scene's hold, per source file and line, for one or two
laws: where a law's whole step loop spends its instructions, and where two laws differ.

callgrind counts every instruction of `epac-run` on the side-by-side's fcc scene
(bench/peers/side_by_side.py, its law blocks) run for the compression alone (500 steps) and for
the compression and the hold (500 + --hold steps); the difference is the hold, divided by its
active contact-steps (summary.json "timed"). Instructions are attributed to the source line they
were compiled from, inlined code to its own header, so a build with -g gives lines (without it,
files are "???"). Counts, not times: they do not depend on the machine's load, and they are not
the time (see docs/performance.md: in the native build Nan 2022's extra instructions over
Hertz-Mindlin were not all on its critical path).

valgrind 3.19 cannot run AVX-512: use a build without it, e.g. the same lane code at 256 bits,
  cmake -S . -B build-v3 -DCMAKE_BUILD_TYPE=Release -DEPAC_ARCH=x86-64-v3 -DCMAKE_CXX_FLAGS=-g
  cmake --build build-v3 -j2 --target epac-run
  python3 bench/roofline/hold_lines.py --build build-v3 --laws hm nan [--ncell 14] [--hold 200] [--top 40]
  python3 bench/roofline/hold_lines.py --self-test   # the callgrind parser, no build needed
Needs valgrind (Debian: valgrind). About 2-4 minutes per law at ncell 14 (two runs under callgrind).
"""
import argparse
import collections
import json
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "peers"))


def parse_callgrind(lines, function=None):
    """Self cost (the first event, Ir) per (file, line) of a callgrind output written with
    --compress-strings=no --compress-pos=no. Inlined code counts to its own file (fi=/fe=); the
    inclusive cost line after calls= is skipped (the callee's lines count on their own).
    function: a regex; only functions whose name matches it count (None: all)."""
    cost = collections.Counter()
    fl = fi = None
    counted = function is None
    after_call = False
    pattern = re.compile(function) if function else None
    for line in lines:
        if line.startswith("fl="):
            fl, fi = line[3:].strip(), None
        elif line.startswith(("fi=", "fe=")):
            fi = line[3:].strip()
        elif line.startswith("fn="):
            fi = None
            counted = pattern is None or bool(pattern.search(line[3:]))
        elif line.startswith("calls="):
            after_call = True
        elif line[:1].isdigit():
            if after_call:
                after_call = False
                continue
            if counted:
                parts = line.split()
                if len(parts) >= 2:
                    cost[(fi or fl, int(parts[0]))] += int(parts[1])
    return cost


def short_path(path):
    for marker in ("/kernels/", "/drivers/", "/include/"):
        if marker in path:
            return path.split(marker, 1)[1]
    return os.path.basename(path)


def count_run(exe, scene, steps, hold_from, workdir, tag, function):
    out = os.path.join(workdir, f"out.{tag}")
    cg = os.path.join(workdir, f"callgrind.{tag}")
    cmd = ["valgrind", "--tool=callgrind", "--compress-strings=no", "--compress-pos=no", f"--callgrind-out-file={cg}",
           exe, scene, "--threads", "1", "--quiet", "--steps", str(steps), "--out", out, "--overwrite"]
    if hold_from is not None:
        cmd += ["--time-after", str(hold_from)]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                   env=dict(os.environ, OMP_NUM_THREADS="1", OMP_PROC_BIND="false"))
    with open(cg) as f:
        cost = parse_callgrind(f, function)
    summary = json.load(open(os.path.join(out, "summary.json")))
    return cost, summary


def hold_counts(exe, law, ncell, hold, workdir, function):
    import side_by_side  # the law blocks
    from fcc_scene import fcc_scene
    scene = os.path.join(workdir, f"fcc_{law}.toml")
    with open(scene, "w") as f:
        f.write(fcc_scene(side_by_side.LAWS[law]["epac"], ncell))
    before, _ = count_run(exe, scene, 500, None, workdir, f"{law}.500", function)
    after, summary = count_run(exe, scene, 500 + hold, 500, workdir, f"{law}.{500 + hold}", function)
    timed = summary["timed"]
    contact_steps = timed["active_contacts_mean"] * timed["steps"]
    per = collections.Counter()
    for (path, line), n in after.items():
        per[(short_path(path), line)] += n
    for (path, line), n in before.items():
        per[(short_path(path), line)] -= n
    return {k: v / contact_steps for k, v in per.items()}


def report(laws, counts, top):
    files = collections.defaultdict(lambda: [0.0] * len(laws))
    lines = collections.defaultdict(lambda: [0.0] * len(laws))
    for i, law in enumerate(laws):
        for (path, line), v in counts[law].items():
            files[path][i] += v
            lines[(path, line)][i] += v
    head = " | ".join(laws) + (f" | {laws[1]} - {laws[0]}" if len(laws) == 2 else "")
    print("instructions per contact-step of the hold, whole step loop: "
          + ", ".join(f"{law} {sum(counts[law].values()):.1f}" for law in laws))
    key = (lambda v: -abs(v[1] - v[0])) if len(laws) == 2 else (lambda v: -v[0])
    for title, table in (("file", files), ("file:line", lines)):
        print(f"\n| {title} | {head} |\n|---|" + "---|" * (len(laws) + (len(laws) == 2)))
        rows = sorted(table.items(), key=lambda kv: key(kv[1]))
        for name, v in rows[: (top if title == "file:line" else len(rows))]:
            if max(abs(x) for x in v) < 0.05:
                continue
            label = name if title == "file" else f"{name[0]}:{name[1]}"
            extra = f" | {v[1] - v[0]:+.2f}" if len(laws) == 2 else ""
            print(f"| {label} | " + " | ".join(f"{x:.2f}" for x in v) + extra + " |")


def self_test():
    text = """version: 1
events: Ir
fl=/src/kernels/epac/compute/pair_lanes.hpp
fn=epac::detail::pair_kernel_lanes<8>
10 5
11 7
fi=/src/kernels/epac/core/vec3.hpp
20 3
fe=/src/kernels/epac/compute/pair_lanes.hpp
12 1
cfn=memcpy
calls=2 0
12 100
13 2
fn=main
fl=/src/drivers/main.cpp
5 50
"""
    c = parse_callgrind(text.splitlines(True))
    expect = {("/src/kernels/epac/compute/pair_lanes.hpp", 10): 5, ("/src/kernels/epac/compute/pair_lanes.hpp", 11): 7,
              ("/src/kernels/epac/core/vec3.hpp", 20): 3, ("/src/kernels/epac/compute/pair_lanes.hpp", 12): 1,
              ("/src/kernels/epac/compute/pair_lanes.hpp", 13): 2, ("/src/drivers/main.cpp", 5): 50}
    assert dict(c) == expect, dict(c)
    only = parse_callgrind(text.splitlines(True), r"pair_kernel")
    assert sum(only.values()) == 18 and ("/src/drivers/main.cpp", 5) not in only, dict(only)
    assert short_path("/w/kernels/epac/core/vec3.hpp") == "epac/core/vec3.hpp"
    print("hold_lines self-test: ok")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.environ.get("EPAC_BUILD_DIR", "build"))
    ap.add_argument("--laws", nargs="+", default=["hm", "nan"], help="side_by_side.py law keys (one or two)")
    ap.add_argument("--ncell", type=int, default=14)
    ap.add_argument("--hold", type=int, default=200, help="hold steps counted after the 500 of compression")
    ap.add_argument("--function", help="regex: count only functions whose name matches (default: all)")
    ap.add_argument("--top", type=int, default=40)
    ap.add_argument("--json")
    ap.add_argument("--self-test", action="store_true")
    a = ap.parse_args()
    if a.self_test:
        self_test()
        return
    if not 1 <= len(a.laws) <= 2:
        raise SystemExit("hold_lines.py: --laws takes one or two laws")
    cache = os.path.join(a.build, "CMakeCache.txt")
    if os.path.exists(cache) and re.search(r"^EPAC_ARCH:STRING=(auto|native)$", open(cache).read(), re.M):
        print(f"hold_lines.py: warning: {a.build} may be built with -march=native; valgrind 3.19 stops at the first "
              "AVX-512 instruction (build with -DEPAC_ARCH=x86-64-v3 or portable)", file=sys.stderr)
    exe = os.path.join(a.build, "drivers", "epac-run")
    counts = {}
    with tempfile.TemporaryDirectory(prefix="hold_lines.") as work:
        for law in a.laws:
            counts[law] = hold_counts(exe, law, a.ncell, a.hold, work, a.function)
    report(a.laws, counts, a.top)
    if a.json:
        with open(a.json, "w") as f:
            json.dump({law: {f"{p}:{ln}": v for (p, ln), v in c.items()} for law, c in counts.items()}, f, indent=1)


if __name__ == "__main__":
    main()
