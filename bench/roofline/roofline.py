#!/usr/bin/env python3
"""A roofline line per contact law: flops, bytes and instructions per contact-step, and how far
the measured rate is from the machine's triad bandwidth and from this build's peak arithmetic.

Where each number comes from (all measured on this machine, this build):
- instructions, flops, divisions and square roots per contact: callgrind counts how often each
  machine instruction of the force kernel ran (--dump-instr, collection only inside
  epac::detail::pair_kernel and MDR's radius update) and the script classifies each executed
  instruction from objdump's disassembly: add/sub/mul/div/sqrt 1 flop per lane, fused
  multiply-add 2, min/max/compare/logic 0; lanes from the register width and the element type.
  Instruction counts do not depend on the machine's load (callgrind counts, it does not time).
- contact-steps per second: epac-law-throughput (one force pass = zero forces, the kernel, the
  sums, MDR's radius update) on the dense packing, OMP_NUM_THREADS threads.
- bytes per contact-step: epac-stream-triad's count of what one contact reads and writes with no
  cache reuse (an upper bound), and the triad bandwidth of the same threads (L2-sized and
  DRAM-sized arrays).
- peak arithmetic: epac-stream-triad's multiply-add loop at the best unroll, i.e. what this build's
  instructions (SSE2 without -march, FMA and wider vectors with it) reach on all threads; the
  contact kernels are scalar, so their own roof is that peak over the vector lanes.

  python3 bench/roofline/roofline.py [--build build] [--threads 1] [--contacts 1e5]
                                     [--laws hertz_mindlin,jkr,nan2022,mdr] [--scalars double,float]
                                     [--json roofline.json]
  python3 bench/roofline/roofline.py --self-test   # the classifier and parser, no build needed
Needs valgrind and objdump (Debian: valgrind, binutils).
"""
import argparse
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

LAWS = ["hertz_mindlin", "jkr", "nan2022", "mdr"]
# epac-stream-triad's byte-count names for the laws epac-law-throughput runs (mdr = all effects)
BYTES_NAME = {"hertz_mindlin": "hertz_mindlin", "jkr": "jkr", "nan2022": "nan2022", "mdr": "mdr_all_effects"}

_FP_BASE = re.compile(
    r"^v?(?P<op>fn?m(?:add|sub)(?:sub|add)?\d{3}|add|sub|mul|div|sqrt|rsqrt|rcp|min|max|cmp\w*|and|andn|or|xor|"
    r"round|hadd|hsub|addsub)(?P<kind>[sp][sd])$")


def classify(mnemonic, operands):
    """(flops, lanes, kind) of one x86 instruction in objdump's AT&T syntax; kind is 'fma', 'add',
    'mul', 'div', 'sqrt', 'other' for floating-point instructions, None for everything else."""
    m = _FP_BASE.match(mnemonic)
    if not m:
        return 0, 0, None
    op, kind = m.group("op"), m.group("kind")
    elem = 8 if kind[1] == "d" else 4
    if kind[0] == "s":
        lanes = 1
    else:
        width = 64 if "%zmm" in operands else 32 if "%ymm" in operands else 16
        lanes = width // elem
    if op.startswith("fm") or op.startswith("fnm"):
        return 2 * lanes, lanes, "fma"
    if op in ("add", "sub", "hadd", "hsub", "addsub"):
        return lanes, lanes, "add"
    if op == "mul":
        return lanes, lanes, "mul"
    if op in ("div", "rcp"):
        return lanes, lanes, "div"
    if op in ("sqrt", "rsqrt"):
        return lanes, lanes, "sqrt"
    return 0, lanes, "other"  # min, max, compares, logic, rounding: not flops


def parse_objdump(text):
    """{address: (mnemonic, operands)} from `objdump -d --no-show-raw-insn` output."""
    out = {}
    line_re = re.compile(r"^\s*([0-9a-f]+):\s+(\S+)\s*(.*)$")
    for line in text.splitlines():
        m = line_re.match(line)
        if m:
            out[int(m.group(1), 16)] = (m.group(2), m.group(3))
    return out


def parse_callgrind(text):
    """{object path: {address: executed count}} from a callgrind file written with --dump-instr=yes
    --dump-line=no --compress-pos=no --compress-strings=no (self cost only: the cost line after a
    calls= line is the callee's inclusive cost and is skipped)."""
    counts = {}
    obj = None
    skip_next = False
    for line in text.splitlines():
        if skip_next:
            skip_next = False
            continue
        if line.startswith("ob="):
            obj = line[3:].strip()
        elif line.startswith("calls="):
            skip_next = True
        elif line[:2] == "0x" and obj is not None:
            parts = line.split()
            if len(parts) >= 2:
                d = counts.setdefault(obj, {})
                addr = int(parts[0], 16)
                d[addr] = d.get(addr, 0) + int(parts[1])
    return counts


def tally(counts, disassemble):
    """Totals over every executed instruction: instructions, flops and per-kind lane counts."""
    t = {"instructions": 0, "flops": 0, "fp_instructions": 0, "packed_fp_instructions": 0,
         "fma": 0, "add": 0, "mul": 0, "div": 0, "sqrt": 0, "other": 0, "max_lanes": 0, "unknown": 0}
    for obj, per_addr in counts.items():
        asm = disassemble(obj)
        for addr, n in per_addr.items():
            t["instructions"] += n
            ins = asm.get(addr)
            if ins is None:
                t["unknown"] += n
                continue
            flops, lanes, kind = classify(*ins)
            if kind is None:
                continue
            t["fp_instructions"] += n
            t[kind] += n * lanes
            t["flops"] += n * flops
            suffix = ins[0][-2:]
            if suffix in ("pd", "ps") and kind != "other":
                t["packed_fp_instructions"] += n
                t["max_lanes"] = max(t["max_lanes"], lanes)
    return t


def peak_lanes(objdump_text):
    """Widest vector (lanes) the build used in epac-stream-triad's peak multiply-add loops, per
    scalar type: a scalar kernel's own roof is the measured peak over these lanes."""
    lanes = {"double": 1, "float": 1}
    current = None
    head = re.compile(r"^[0-9a-f]+ <(.*)>:$")
    for line in objdump_text.splitlines():
        h = head.match(line)
        if h:
            name = h.group(1)
            current = "double" if "multiply_add_gflops<double" in name else \
                "float" if "multiply_add_gflops<float" in name else None
            continue
        if current:
            ins = parse_objdump(line)
            for mnemonic, operands in ins.values():
                flops, n, kind = classify(mnemonic, operands)
                if kind in ("fma", "add", "mul"):
                    lanes[current] = max(lanes[current], n)
    return lanes


def run(cmd, env=None, **kw):
    return subprocess.run(cmd, env=env, check=True, text=True, capture_output=True, **kw)


def count_law(build, law, scalar, contacts, passes, work):
    exe = os.path.join(build, "bench", "epac-law-throughput")
    out = os.path.join(work, f"callgrind.{law}.{scalar}")
    js = os.path.join(work, f"count.{law}.{scalar}.json")
    env = dict(os.environ, OMP_NUM_THREADS="1", OMP_PROC_BIND="false")
    run(["valgrind", "--tool=callgrind", "--dump-instr=yes", "--dump-line=no", "--compress-pos=no",
         "--compress-strings=no", "--collect-atstart=no", "--toggle-collect=*pair_kernel*",
         "--toggle-collect=*mdr_update_radii*", f"--callgrind-out-file={out}", exe, "--contacts", str(contacts),
         "--passes", str(passes), "--laws", law, "--scalars", scalar, "--json", js], env=env)
    row = json.load(open(js))["results"][0]
    with open(out) as f:
        counts = parse_callgrind(f.read())
    cache = {}

    def disassemble(obj):
        if obj not in cache:
            cache[obj] = parse_objdump(run(["objdump", "-d", "--no-show-raw-insn", obj]).stdout) \
                if os.path.exists(obj) else {}
        return cache[obj]

    t = tally(counts, disassemble)
    # the two untimed passes run the kernel too: every pass evaluates every contact once
    evaluated = row["contacts"] * (row["passes"] + 2)
    per = {k: t[k] / evaluated for k in ("instructions", "flops", "fp_instructions", "packed_fp_instructions",
                                          "fma", "add", "mul", "div", "sqrt", "unknown")}
    per["max_lanes"] = t["max_lanes"]
    return per


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.environ.get("EPAC_BUILD_DIR", "build"))
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--contacts", default="1e5", help="contacts of the timed packing")
    ap.add_argument("--count-contacts", default="2e4", help="contacts of the packing run under callgrind")
    ap.add_argument("--laws", default=",".join(LAWS))
    ap.add_argument("--scalars", default="double,float")
    ap.add_argument("--seconds", type=float, default=1.0)
    ap.add_argument("--repeats", type=int, default=3, help="epac-stream-triad repetitions")
    ap.add_argument("--json")
    ap.add_argument("--self-test", action="store_true")
    a = ap.parse_args()
    if a.self_test:
        return self_test()
    for tool in ("valgrind", "objdump"):
        if not shutil.which(tool):
            sys.exit(f"roofline.py: {tool} not found (Debian: apt-get install valgrind binutils)")
    build = os.path.abspath(a.build)
    laws, scalars = a.laws.split(","), a.scalars.split(",")
    for law in laws:
        if law not in LAWS:
            sys.exit(f"roofline.py: --laws: unknown law '{law}' ({', '.join(LAWS)})")
    env = dict(os.environ, OMP_NUM_THREADS=str(a.threads), OMP_PROC_BIND="false")
    with tempfile.TemporaryDirectory() as work:
        tri = os.path.join(work, "triad.json")
        run([os.path.join(build, "bench", "epac-stream-triad"), "--repeats", str(a.repeats), "--json", tri], env=env)
        triad = json.load(open(tri))
        thr = os.path.join(work, "throughput.json")
        run([os.path.join(build, "bench", "epac-law-throughput"), "--contacts", a.contacts, "--seconds",
             str(a.seconds), "--laws", a.laws, "--scalars", a.scalars, "--json", thr], env=env)
        rates = {(r["law"], r["scalar"]): r for r in json.load(open(thr))["results"]}
        lanes_of = peak_lanes(run(["objdump", "-d", "-C", "--no-show-raw-insn",
                                   os.path.join(build, "bench", "epac-stream-triad")]).stdout)
        rows = []
        for law in laws:
            for scalar in scalars:
                try:
                    c = count_law(build, law, scalar, int(float(a.count_contacts)), 8, work)
                except subprocess.CalledProcessError as e:
                    # e.g. SIGILL: valgrind 3.19 (Debian 12) cannot run AVX-512 code (-march=native on
                    # such a CPU): the counted columns stay empty, the timed ones are still measured
                    print(f"roofline.py: {law}/{scalar}: callgrind failed ({e.returncode}): no counts for this build",
                          file=sys.stderr)
                    c = None
                r = rates[(law, scalar)]
                byts = triad["bytes_per_contact_step"][BYTES_NAME[law]][scalar]
                rate = r["contacts_per_s"]
                peak = triad["peak_GFLOPs"][scalar]
                lanes = lanes_of[scalar]
                row = {
                    "law": law, "scalar": scalar, "threads": a.threads, "contacts": r["contacts"],
                    "contact_steps_per_s": rate, "ns_per_contact_step": 1e9 / rate,
                    "bytes_per_contact_step": byts,
                    "GBps_no_reuse": byts * rate / 1e9,
                    "fraction_of_DRAM_triad": byts * rate / 1e9 / triad["triad_GBps"]["64MiB"],
                    "fraction_of_L2_triad": byts * rate / 1e9 / triad["triad_GBps"]["256KiB"],
                    "peak_vector_lanes": lanes,
                }
                rows.append(row)
                if c is None:
                    continue
                lat = triad["latency_ns"][scalar]
                # the divisions and roots of one contact, were they one dependent chain, on one
                # thread: a contact-step takes threads x ns_per_contact_step of one thread's time
                chain = c["div"] * lat["div"] + c["sqrt"] * lat["sqrt"]
                row.update({
                    **{k + "_per_contact": v for k, v in c.items() if k != "max_lanes"},
                    "max_vector_lanes_used": c["max_lanes"],
                    "flops_per_byte": c["flops"] / byts,
                    "div_sqrt_chain_ns": chain,
                    "div_sqrt_chain_fraction": chain / (a.threads * 1e9 / rate),
                    "GFLOPs": c["flops"] * rate / 1e9,
                    "G_instructions_per_s": c["instructions"] * rate / 1e9,
                    "instructions_per_cycle": c["instructions"] * rate / 1e9 / (triad["clock_GHz"] * a.threads)
                    if triad.get("clock_GHz") else None,
                    "fraction_of_peak": c["flops"] * rate / 1e9 / peak,
                    "fraction_of_scalar_peak": c["flops"] * rate / 1e9 / (peak / lanes),
                })
    ff = os.path.join(build, "epac-build-flags.txt")
    flags = open(ff).read().strip() if os.path.exists(ff) else "unknown"
    report = {"build_flags": flags, "threads": a.threads, "peak_vector_lanes": lanes_of,
              "clock_GHz": triad.get("clock_GHz"), "latency_ns": triad.get("latency_ns"),
              "triad_GBps": triad["triad_GBps"], "peak_GFLOPs": triad["peak_GFLOPs"], "rows": rows}
    lat = triad["latency_ns"]
    print(f"epac built with: {flags}")
    print(f"triad GB/s ({a.threads} thread(s)): L2-sized {triad['triad_GBps']['256KiB']:.1f}, DRAM-sized "
          f"{triad['triad_GBps']['64MiB']:.1f}; peak multiply-add GFLOP/s of this build: double "
          f"{triad['peak_GFLOPs']['double']:.1f} ({lanes_of['double']} lanes), float "
          f"{triad['peak_GFLOPs']['float']:.1f} ({lanes_of['float']} lanes); scalar peak = peak / lanes; clock "
          f"{triad.get('clock_GHz', 0):.2f} GHz (dependent adds); latency ns, double div {lat['double']['div']:.2f} "
          f"sqrt {lat['double']['sqrt']:.2f}, float div {lat['float']['div']:.2f} sqrt {lat['float']['sqrt']:.2f}")
    print("| law | scalar | ns/contact-step | instructions | IPC | flops | div | sqrt | div+sqrt chain ns (share) | "
          "packed FP | bytes (no reuse) | flops/byte | GFLOP/s | % peak (% scalar peak) | GB/s | % DRAM triad (% L2) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")

    def f(r, k, fmt, scale=1.0):
        v = r.get(k)
        return "n/a" if v is None else format(scale * v, fmt)

    for r in rows:
        print(f"| {r['law']} | {r['scalar']} | {r['ns_per_contact_step']:.1f} | {f(r, 'instructions_per_contact', '.0f')} | "
              f"{f(r, 'instructions_per_cycle', '.2f')} | {f(r, 'flops_per_contact', '.0f')} | "
              f"{f(r, 'div_per_contact', '.1f')} | {f(r, 'sqrt_per_contact', '.1f')} | "
              f"{f(r, 'div_sqrt_chain_ns', '.1f')} ({f(r, 'div_sqrt_chain_fraction', '.0%')}) | "
              f"{f(r, 'packed_fp_instructions_per_contact', '.1f')} | {r['bytes_per_contact_step']} | "
              f"{f(r, 'flops_per_byte', '.2f')} | {f(r, 'GFLOPs', '.2f')} | {f(r, 'fraction_of_peak', '.1f', 100)} "
              f"({f(r, 'fraction_of_scalar_peak', '.1f', 100)}) | {r['GBps_no_reuse']:.1f} | "
              f"{100 * r['fraction_of_DRAM_triad']:.0f} ({100 * r['fraction_of_L2_triad']:.0f}) |")
    if a.json:
        with open(a.json, "w") as f:
            json.dump(report, f, indent=1)
    return 0


def self_test():
    cases = [
        (("addsd", "%xmm1,%xmm0"), (1, 1, "add")),
        (("vfmadd231sd", "%xmm2,%xmm1,%xmm0"), (2, 1, "fma")),
        (("vfnmadd213ss", "%xmm2,%xmm1,%xmm0"), (2, 1, "fma")),
        (("mulpd", "%xmm1,%xmm0"), (2, 2, "mul")),
        (("vmulpd", "%ymm1,%ymm2,%ymm0"), (4, 4, "mul")),
        (("vaddps", "%zmm1,%zmm2,%zmm0"), (16, 16, "add")),
        (("divsd", "0x8(%rax),%xmm0"), (1, 1, "div")),
        (("vsqrtss", "%xmm0,%xmm0,%xmm0"), (1, 1, "sqrt")),
        (("sqrtpd", "%xmm1,%xmm1"), (2, 2, "sqrt")),
        (("maxsd", "%xmm1,%xmm0"), (0, 1, "other")),
        (("xorpd", "%xmm1,%xmm1"), (0, 2, "other")),
        (("movsd", "(%rax),%xmm0"), (0, 0, None)),
        (("addq", "$0x8,%rax"), (0, 0, None)),
        (("mulss", "%xmm2,%xmm3"), (1, 1, "mul")),
        (("subss", "%xmm2,%xmm3"), (1, 1, "add")),
    ]
    bad = [(i, classify(*i), want) for i, want in cases if classify(*i) != want]
    asm = parse_objdump("0000000000001000 <f>:\n    1000:\tmulsd  %xmm1,%xmm0\n    1004:\tvfmadd231sd %xmm2,%xmm1,%xmm0\n"
                        "    100a:\tdivsd  %xmm1,%xmm0\n    1010:\tcall   2000 <g>\n")
    cg = ("version: 1\npositions: instr\nevents: Ir\nob=/x/a.out\nfn=f\n0x1000 10\n0x1004 10\n0x100a 3\n"
          "cob=/x/a.out\ncfn=g\ncalls=3 0x2000\n0x1010 999\n0x1010 3\nob=/lib/libm.so\nfn=cbrt\n0x50 7\n")
    counts = parse_callgrind(cg)
    t = tally(counts, lambda obj: asm if obj == "/x/a.out" else {})
    want = {"instructions": 33, "flops": 10 + 20 + 3, "fma": 10, "mul": 10, "div": 3, "unknown": 7}
    bad += [(k, t[k], v) for k, v in want.items() if t[k] != v]
    if counts.get("/x/a.out", {}).get(0x1010) != 3:
        bad.append(("calls= inclusive cost line taken as self cost", counts.get("/x/a.out", {}).get(0x1010), 3))
    od = ("0000000000003000 <void multiply_add_gflops<double, 8>(int)::{lambda(int)#1}>:\n"
          "    3000:\tmulpd  %xmm1,%xmm0\n    3004:\taddpd  %xmm2,%xmm0\n"
          "0000000000004000 <other>:\n    4000:\tvmulpd %ymm1,%ymm2,%ymm0\n")
    if peak_lanes(od) != {"double": 2, "float": 1}:
        bad.append(("peak_lanes", peak_lanes(od), {"double": 2, "float": 1}))
    for b in bad:
        print("FAIL", b)
    print("roofline self-test:", "failed" if bad else "passed", f"({len(cases)} instructions, one callgrind file)")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
