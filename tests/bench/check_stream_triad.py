#!/usr/bin/env python3
"""Runs epac-stream-triad once and checks what it writes (bench/bandwidth/stream_triad.cpp): the
JSON's fields, finite positive rates, and a core clock inside what x86-64 cores run at. Never a
timing: the machine's load moves every rate, so only ranges no loaded machine leaves are checked.

The clock's range (0.3-7 GHz, no x86-64 core runs faster) catches a clock loop that the CPU
shortcuts: a chain of `add $1` measured 16-19 "GHz" on a 4.1 GHz Intel Xeon with AMX, whose
renamer folds small immediates, and the roofline's instructions per cycle came out 4x too low.

usage: check_stream_triad.py --exe build/bench/epac-stream-triad --work DIR
"""
import argparse
import json
import math
import os
import platform
import subprocess
import sys

def problems_of(d, machine):
    """The list of what is wrong with the JSON d written on a `machine` (platform.machine())."""
    bad = []

    def positive(name, v):
        if not isinstance(v, (int, float)) or not math.isfinite(v) or v <= 0:
            bad.append(f"{name} = {v!r}: expected a finite number > 0")

    if not isinstance(d.get("threads"), int) or d["threads"] < 1:
        bad.append(f"threads = {d.get('threads')!r}: expected an integer >= 1")
    triad = d.get("triad_GBps", {})
    for size in ["32KiB", "256KiB", "2MiB", "64MiB"]:
        positive(f"triad_GBps.{size}", triad.get(size))
    for s in ["double", "float"]:
        positive(f"peak_GFLOPs.{s}", d.get("peak_GFLOPs", {}).get(s))
        lat = d.get("latency_ns", {}).get(s, {})
        for op in ["add", "div", "sqrt"]:
            positive(f"latency_ns.{s}.{op}", lat.get(op))
    ghz = d.get("clock_GHz")
    if machine in ("x86_64", "AMD64"):
        if not isinstance(ghz, (int, float)) or not 0.3 <= ghz <= 7.0:
            bad.append(f"clock_GHz = {ghz!r}: an x86-64 core runs at 0.3-7 GHz (a clock loop the CPU shortcuts?)")
    elif ghz != 0:
        bad.append(f"clock_GHz = {ghz!r}: not measured off x86-64, expected 0")
    b = d.get("bytes_per_contact_step", {})
    if not b:
        bad.append("bytes_per_contact_step: no law")
    for law, e in b.items():
        if not (isinstance(e.get("double"), int) and isinstance(e.get("float"), int) and 0 < e["float"] < e["double"]):
            bad.append(f"bytes_per_contact_step.{law} = {e!r}: expected 0 < float < double")
    return bad


def self_test():
    good = {"threads": 1, "triad_GBps": {"32KiB": 90.0, "256KiB": 120.0, "2MiB": 29.0, "64MiB": 16.0},
            "peak_GFLOPs": {"double": 63.0, "float": 130.0}, "clock_GHz": 4.06,
            "latency_ns": {s: {"add": 0.49, "div": 3.3, "sqrt": 4.7} for s in ["double", "float"]},
            "bytes_per_contact_step": {"hertz_mindlin": {"double": 424, "float": 240}}}
    assert problems_of(good, "x86_64") == [], problems_of(good, "x86_64")
    folded = dict(good, clock_GHz=19.03)  # the immediate-add loop on that Xeon
    assert any("clock_GHz" in p for p in problems_of(folded, "x86_64"))
    assert any("clock_GHz" in p for p in problems_of(good, "aarch64"))
    assert problems_of(dict(good, clock_GHz=0), "aarch64") == []
    nan_triad = dict(good, triad_GBps=dict(good["triad_GBps"], **{"2MiB": float("nan")}))
    assert any("2MiB" in p for p in problems_of(nan_triad, "x86_64"))
    assert any("no law" in p for p in problems_of(dict(good, bytes_per_contact_step={}), "x86_64"))
    swapped = dict(good, bytes_per_contact_step={"jkr": {"double": 256, "float": 456}})
    assert any("jkr" in p for p in problems_of(swapped, "x86_64"))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--exe", required=True)
    ap.add_argument("--work", required=True)
    a = ap.parse_args()
    self_test()
    os.makedirs(a.work, exist_ok=True)
    path = os.path.join(a.work, "stream.json")
    subprocess.check_call([a.exe, "--repeats", "1", "--json", path])
    bad = problems_of(json.load(open(path)), platform.machine())
    for p in bad:
        print("check_stream_triad:", p, file=sys.stderr)
    print("check_stream_triad:", "FAILED" if bad else "ok", path)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
