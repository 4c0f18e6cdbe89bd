#!/usr/bin/env python3
"""The device run's report (cmake/device-run.sh): one JSON and one markdown table from the logs and
JSON files the run left in --dir (steps.tsv, tests.log, law_throughput.json, bench_contacts.json,
scaling.json). A file that is missing (a step that failed or did not run) is reported as such.

  python3 tests/device/device_report.py --dir REPORT_DIR [--build BUILD_DIR] [--total-s SECONDS]
"""
import argparse
import json
import os
import re
import subprocess


def load(path):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def gpu():
    try:
        out = subprocess.run(["nvidia-smi", "--query-gpu=name,compute_cap,driver_version,memory.total",
                              "--format=csv,noheader"], capture_output=True, text=True, timeout=30).stdout
        return out.strip().splitlines()[0] if out.strip() else None
    except (OSError, subprocess.SubprocessError):
        return None


def tests(path):
    """ctest's per-test lines: '  3/17 Test  #3: test_core ........   Passed    1.20 sec'."""
    rows = []
    try:
        text = open(path).read()
    except OSError:
        return rows
    for m in re.finditer(r"Test\s+#\d+: (\S+) \.*\s*(\*\*\*)?(\w[\w ]*?)\s+([\d.]+) sec", text):
        rows.append({"test": m.group(1), "result": m.group(3).strip(), "seconds": float(m.group(4))})
    return rows


def bench_contacts(path):
    data = load(path)
    if not data:
        return None
    rows = []
    for b in data.get("benchmarks", []):
        if "contacts_per_s" in b:
            rows.append({"name": b["name"], "contacts": b.get("contacts"), "contacts_per_s": b["contacts_per_s"],
                         "real_time_ms": b.get("real_time")})
    return {"context": data.get("context", {}), "results": rows}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--dir", required=True)
    ap.add_argument("--build", default=None)
    ap.add_argument("--total-s", type=float, default=None)
    args = ap.parse_args()
    d = args.dir
    steps = []
    try:
        for line in open(os.path.join(d, "steps.tsv")):
            name, status, sec = line.rstrip("\n").split("\t")
            steps.append({"step": name, "status": status, "seconds": float(sec)})
    except OSError:
        pass
    report = {
        "gpu": gpu(),
        "total_seconds": args.total_s,
        "steps": steps,
        "tests": tests(os.path.join(d, "tests.log")),
        "law_throughput": load(os.path.join(d, "law_throughput.json")),
        "bench_contacts": bench_contacts(os.path.join(d, "bench_contacts.json")),
        "scaling": load(os.path.join(d, "scaling.json")),
    }
    with open(os.path.join(d, "device_report.json"), "w") as f:
        json.dump(report, f, indent=1)

    md = ["# epac device run", "", f"GPU: {report['gpu'] or 'none found'}; total {args.total_s} s", "",
          "| step | status | s |", "|---|---|---|"]
    md += [f"| {s['step']} | {s['status']} | {s['seconds']:.0f} |" for s in steps]
    md += ["", "## Tests", "", "| test | result | s |", "|---|---|---|"]
    md += [f"| {t['test']} | {t['result']} | {t['seconds']:.1f} |" for t in report["tests"]] or ["| (no results) | | |"]
    md += ["", "## Contacts/s per law (one force pass)", "", "| law | scalar | contacts | contacts/s |", "|---|---|---|---|"]
    lt = report["law_throughput"]
    if lt:
        md += [f"| {r['law']} | {r['scalar']} | {r['contacts']} | {r['contacts_per_s']:.3g} |" for r in lt["results"]]
    else:
        md += ["| (not run) | | | |"]
    md += ["", "## Hertz-Mindlin kernel variants (epac-bench-contacts)", "", "| benchmark | contacts | contacts/s |",
           "|---|---|---|"]
    bc = report["bench_contacts"]
    if bc:
        md += [f"| {r['name']} | {r['contacts']:.0f} | {r['contacts_per_s']:.3g} |" for r in bc["results"]]
    else:
        md += ["| (not run) | | |"]
    md += ["", "## Scaling (epac-run, fcc compression scene)", "", "| kind | particles | contact-steps/s | force s |",
           "|---|---|---|---|"]
    sc = report["scaling"]
    if sc:
        for kind in ("strong", "weak"):
            for r in sc.get(kind, []):
                b = r["best"]
                force = (b.get("phases") or {}).get("force")
                md.append(f"| {kind} | {r['particles']} | {b['contact_steps_per_second']:.3g} | "
                          f"{force if force is not None else float('nan'):.3f} |")
    else:
        md += ["| (not run) | | | |"]
    with open(os.path.join(d, "device_report.md"), "w") as f:
        f.write("\n".join(md) + "\n")
    print("\n".join(md))


if __name__ == "__main__":
    main()
