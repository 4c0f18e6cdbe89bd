#!/usr/bin/python3
"""Plots of the MDR validation scenes (drivers/scenes/mdr_*.toml), in the style of Zunker & Kamrin
Part I, Figs 8-13. Reads the CSV outputs of epac-run and writes PNGs.

    /usr/bin/python3 bench/plots/plot_mdr.py RUNS_DIR [--scenes drivers/scenes] [--png-dir DIR]

RUNS_DIR holds one folder per scene, named after the scene file without .toml (what
bench/plots/run_mdr_scenes.sh writes). Scenes whose folder is missing are skipped. Needs numpy
and matplotlib (Debian: python3-matplotlib); the scene parameters are read from the TOML files.

Writes: mdr_two_flats_force.png (Fig. 8), mdr_two_flats_area.png (Fig. 9),
mdr_two_flats_pressure.png (Fig. 10), mdr_two_flats_volume.png (Fig. 11),
mdr_adhesive.png (Fig. 13(a) and the plastic adhesive runs), mdr_die_compaction.png (Fig. 12),
mdr_pairs.png (particle pairs).
"""
import argparse
import csv
import math
import os
import sys

try:
    import tomllib
except ImportError:  # Python < 3.11
    tomllib = None

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

EY_VALUES = [200, 100, 50, 25, 12.5, 6.25]  # Figs 8-11 (a)-(f)


def read_csv(path):
    """Columns by name without the unit ("time [s]" -> "time"); numbers where they parse, else strings."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    head, body = rows[0], rows[1:]
    cols = {}
    for k, name in enumerate(head):
        name = name.split(" [")[0]
        vals = [r[k] for r in body]
        try:
            cols[name] = np.array([float(v) for v in vals])
        except ValueError:
            cols[name] = np.array(vals)
    return cols


def scene_params(scenes_dir, stem):
    path = os.path.join(scenes_dir, stem + ".toml")
    if tomllib is None:
        sys.exit("plot_mdr.py needs Python >= 3.11 (tomllib)")
    with open(path, "rb") as f:
        s = tomllib.load(f)
    m = s["materials"]["sphere"]
    R = s["particles"]["list"][0]["radius"]
    return {
        "E": m["youngs_modulus"],
        "nu": m.get("poisson_ratio", 0.3),
        "Y": m.get("yield_stress", math.inf),
        "gamma": m.get("surface_energy", 0.0),
        "R": R,
    }


def wall_rows(contacts, wall_name):
    sel = contacts["wall_name"] == wall_name
    return {k: v[sel] for k, v in contacts.items()}


def split_load_unload(x):
    """Index of the largest x (end of loading)."""
    return int(np.argmax(x))


def plot_two_flats(runs, scenes, out):
    data = []
    for ey in EY_VALUES:
        stem = "mdr_two_flats_EY%g" % ey
        d = os.path.join(runs, stem)
        if not os.path.isdir(d):
            continue
        p = scene_params(scenes, stem)
        ts = read_csv(os.path.join(d, "timeseries.csv"))
        ct = wall_rows(read_csv(os.path.join(d, "contacts.csv")), "top")
        pa = read_csv(os.path.join(d, "particles.csv"))
        data.append((ey, p, ts, ct, pa))
    if not data:
        return []
    written = []

    def grid(title, ylabel, fn, name, extra=None):
        fig, axes = plt.subplots(2, 3, figsize=(12, 7), constrained_layout=True)
        for ax, (ey, p, ts, ct, pa) in zip(axes.flat, data):
            x, y = fn(p, ts, ct, pa)
            k = split_load_unload(x)
            ax.plot(x[: k + 1], y[: k + 1], "-", color="C0", label="loading")
            ax.plot(x[k:], y[k:], "--", color="C3", label="unloading")
            if extra:
                extra(ax, p, x)
            ax.set_title("E/Y = %g" % ey)
            ax.set_xlabel(r"$\delta_o/R_o$")
            ax.set_ylabel(ylabel)
            ax.set_xlim(0, 0.52)
            ax.grid(alpha=0.3)
        axes.flat[0].legend(loc="upper left", fontsize=8)
        fig.suptitle(title)
        path = os.path.join(out, name)
        fig.savefig(path, dpi=110)
        plt.close(fig)
        written.append(path)

    grid("MDR: sphere between two rigid flats, force (cf. Part I Fig. 8)", r"$F/(E R_o^2)$",
         lambda p, ts, ct, pa: (ts["displacement_top"] / p["R"], ts["force_top"] / (p["E"] * p["R"] ** 2)),
         "mdr_two_flats_force.png")
    grid("MDR: contact area pi a^2 (= (42) on loading) (cf. Part I Fig. 9)", r"$A_C/(\pi R_o^2)$",
         lambda p, ts, ct, pa: (contact_disp(ts, ct) / p["R"], contact_area(ct) / (math.pi * p["R"] ** 2)),
         "mdr_two_flats_area.png")

    def hardening(ax, p, x):
        xs = np.linspace(0, 0.5, 200)
        ax.plot(xs, 1.75 * np.exp(-4.4 * xs) + 1.0, ":", color="k", lw=1, label="hardening (16)")

    grid("MDR: mean contact pressure (cf. Part I Fig. 10)", r"$\bar p / Y$",
         lambda p, ts, ct, pa: (contact_disp(ts, ct) / p["R"], mean_pressure(ct) / p["Y"]),
         "mdr_two_flats_pressure.png", extra=hardening)
    grid("MDR: particle volume (39) (cf. Part I Fig. 11)", r"$V/V_o$",
         lambda p, ts, ct, pa: (ts["displacement_top"] / p["R"],
                                pa["volume"] / (4.0 / 3.0 * math.pi * p["R"] ** 3)),
         "mdr_two_flats_volume.png")

    # all E/Y on one plot (Fig. 5(a) style)
    fig, ax = plt.subplots(figsize=(6, 4.5), constrained_layout=True)
    for ey, p, ts, ct, pa in data:
        ax.plot(ts["displacement_top"] / p["R"], ts["force_top"] / (p["E"] * p["R"] ** 2), label="E/Y = %g" % ey)
    ax.set_xlabel(r"$\delta_o/R_o$")
    ax.set_ylabel(r"$F/(E R_o^2)$")
    ax.set_yscale("log")
    ax.set_ylim(1e-4, 1)
    ax.set_xlim(0, 0.52)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_title("MDR two-flat scene, all E/Y (load and unload)")
    path = os.path.join(out, "mdr_two_flats_force_all.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    written.append(path)
    return written


def contact_area(ct):
    """pi a^2 of the MDR contact half-width (equals (42) on plastic loading and vanishes with the
    force on unloading); the (42) column where the driver predates it."""
    return ct["area_from_radius"] if "area_from_radius" in ct else ct["area"]


def mean_pressure(ct):
    A = contact_area(ct)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(A > 0, ct["mdr_force"] / A, np.nan)


def contact_disp(ts, ct):
    """The flat's displacement at each contacts.csv row (rows are written at the output steps)."""
    return np.interp(ct["step"], ts["step"], ts["displacement_top"])


def jkr_curve(p):
    """JKR sphere against a rigid flat: delta(a), F(a) with E* = E/(1-nu^2)."""
    Es = p["E"] / (1 - p["nu"] ** 2)
    R, g = p["R"], p["gamma"]
    a0 = (2 * math.pi * g / Es) ** (1 / 3) * R ** (2 / 3)
    a = np.linspace(1e-4 * a0, 3 * a0, 2000)
    delta = a ** 2 / R - np.sqrt(2 * math.pi * g * a / Es)
    F = 4 * Es * a ** 3 / (3 * R) - np.sqrt(8 * math.pi * g * Es) * a ** 1.5
    return delta, F


def plot_adhesive(runs, scenes, out):
    stems = ["mdr_adhesive_elastic", "mdr_adhesive_plastic_0.1", "mdr_adhesive_plastic_0.4"]
    present = [s for s in stems if os.path.isdir(os.path.join(runs, s))]
    if not present:
        return []
    fig, axes = plt.subplots(1, len(present), figsize=(5 * len(present), 4.2), constrained_layout=True, squeeze=False)
    for ax, stem in zip(axes.flat, present):
        p = scene_params(scenes, stem)
        ts = read_csv(os.path.join(runs, stem, "timeseries.csv"))
        fc = 1.5 * math.pi * p["gamma"] * p["R"]
        x = ts["displacement_top"] / p["R"]
        y = ts["force_top"] / fc
        k = split_load_unload(x)
        ax.plot(x[: k + 1], y[: k + 1], "-", color="C0", label="MDR loading")
        ax.plot(x[k:], y[k:], "--", color="C3", label="MDR unloading")
        if stem.endswith("elastic"):
            dj, Fj = jkr_curve(p)
            ax.plot(dj / p["R"], Fj / fc, ":", color="k", label="JKR")
            xs = np.linspace(0, x.max(), 200)
            Es = p["E"] / (1 - p["nu"] ** 2)
            ax.plot(xs, 4 / 3 * Es * math.sqrt(p["R"]) * (xs * p["R"]) ** 1.5 / fc, "-.", color="gray", lw=1, label="Hertz")
            ax.set_xlim(x.min(), x.max())
            ax.set_ylim(-1.5, max(y.max(), 1.0) * 1.05)
            ax.set_title(r"elastic, $E^* R_o/\Delta\gamma$ = %.3g (cf. Fig. 13(a))" % (Es * p["R"] / p["gamma"]))
        else:
            ax.set_title(r"E/Y = %g, to $\delta_o/R_o$ = %s" % (p["E"] / p["Y"], stem.split("_")[-1]))
            ax.set_ylim(y.min() * 1.3, y.min() * -6)
        ax.axhline(0, color="k", lw=0.5)
        ax.set_xlabel(r"$\delta_o/R_o$")
        ax.set_ylabel(r"$F / (1.5 \pi \Delta\gamma R_o)$")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    path = os.path.join(out, "mdr_adhesive.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return [path]


def plot_die(runs, scenes, out):
    stem = "mdr_die_compaction"
    d = os.path.join(runs, stem)
    if not os.path.isdir(d):
        return []
    p = scene_params(scenes, stem)
    ts = read_csv(os.path.join(d, "timeseries.csv"))
    ct = read_csv(os.path.join(d, "contacts.csv"))
    pa = read_csv(os.path.join(d, "particles.csv"))
    x = ts["displacement_top"] / p["R"]
    k = split_load_unload(x)
    fs = p["E"] * p["R"] ** 2
    sec = np.mean([ts["force_" + w] for w in ("xminus", "xplus", "yminus", "yplus")], axis=0)
    fig, axes = plt.subplots(2, 2, figsize=(10, 8), constrained_layout=True)
    for ax, y, lab in ((axes[0, 0], ts["force_top"] / fs, "(a) primary contact force"),
                       (axes[0, 1], sec / fs, "(b) secondary contact force (mean of 4)")):
        ax.plot(x[: k + 1], y[: k + 1], "-", color="C0", label="loading")
        ax.plot(x[k:], y[k:], "--", color="C3", label="unloading")
        ax.set_ylabel(r"$F/(E R_o^2)$")
        ax.set_title(lab)
    # areas from contacts.csv
    for ax, names, lab in ((axes[1, 0], ("top",), "(c) primary contact area"),
                           (axes[1, 1], ("xminus",), "(d) secondary contact area (x-)")):
        r = wall_rows(ct, names[0])
        xd = np.interp(r["step"], ts["step"], ts["displacement_top"]) / p["R"]
        kk = split_load_unload(xd) if len(xd) else 0
        A = contact_area(r)
        ax.plot(xd[: kk + 1], A[: kk + 1] / (math.pi * p["R"] ** 2), "-", color="C0", label="loading")
        ax.plot(xd[kk:], A[kk:] / (math.pi * p["R"] ** 2), "--", color="C3", label="unloading")
        ax.set_ylabel(r"$A_C/(\pi R_o^2)$")
        ax.set_title(lab)
    ax2 = axes[0, 1].twinx()
    ax2.plot(ts["displacement_top"][: len(pa["R"])] / p["R"], pa["R"] / pa["R0"], ":", color="k", lw=1)
    ax2.set_ylabel(r"$R/R_o$ (dotted)")
    for ax in axes.flat:
        ax.set_xlabel(r"$\delta_o/R_o$ (primary contact)")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8, loc="upper left")
    fig.suptitle("MDR die compaction of one sphere, E/Y = %g (cf. Part I Fig. 12)" % (p["E"] / p["Y"]))
    path = os.path.join(out, "mdr_die_compaction.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return [path]


def plot_pairs(runs, scenes, out):
    stems = [s for s in ("mdr_pair", "mdr_pair_adhesive") if os.path.isdir(os.path.join(runs, s))]
    if not stems:
        return []
    fig, axes = plt.subplots(1, len(stems), figsize=(5.5 * len(stems), 4.2), constrained_layout=True, squeeze=False)
    for ax, stem in zip(axes.flat, stems):
        p = scene_params(scenes, stem)
        ct = read_csv(os.path.join(runs, stem, "contacts.csv"))
        pa = read_csv(os.path.join(runs, stem, "particles.csv"))
        # per-sphere displacement: particle 0 moves from x = -R toward +x
        p0 = pa["id"] == 0
        disp = np.interp(ct["step"], pa["step"][p0], pa["x"][p0] + p["R"]) / p["R"]
        fs = p["E"] * p["R"] ** 2
        ax.plot(disp, ct["force"] / fs, "-", color="C0", label="pair force")
        ax.plot(disp, ct["side0_force"] / fs, ":", color="C1", label="side 0")
        ax.plot(disp, ct["side1_force"] / fs, "--", color="C2", label="side 1", lw=0.8)
        ax.set_xlabel(r"displacement of each sphere $/R_o$")
        ax.set_ylabel(r"$F/(E R_o^2)$")
        ax.set_title(stem)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    path = os.path.join(out, "mdr_pairs.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return [path]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("runs")
    here = os.path.dirname(os.path.abspath(__file__))
    ap.add_argument("--scenes", default=os.path.join(here, "..", "..", "drivers", "scenes"))
    ap.add_argument("--png-dir", default=None)
    a = ap.parse_args()
    out = a.png_dir or a.runs
    os.makedirs(out, exist_ok=True)
    written = []
    for fn in (plot_two_flats, plot_adhesive, plot_die, plot_pairs):
        written += fn(a.runs, a.scenes, out)
    for w in written:
        print("wrote", w)
    if not written:
        sys.exit("plot_mdr.py: no scene outputs found in " + a.runs)


if __name__ == "__main__":
    main()
