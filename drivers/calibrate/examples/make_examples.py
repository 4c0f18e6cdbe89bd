#!/usr/bin/env python3
"""Writes the example curves of epac-calibrate from Nan et al. 2022 Table 2 (the paper's
digitised numbers, cleaned where the digitised text was garbled). These are RECONSTRUCTED
curves, not measured data: each curve is the piecewise-linear path that has exactly Table 2's
f_max, alpha_max, alpha_p and f_cp.

  loading    the common envelope through (0, 0) and the peaks (alpha_max, f_max) of the curves,
             followed up to this curve's own peak (so consecutive peaks give Nan (51)'s k_p)
  unloading  the line of slope k_e = f_max / (alpha_max - alpha_p) (Nan (50)) through
             (alpha_p, 0) down to the pull-off point (alpha_cp, -f_cp), alpha_cp = alpha_p - f_cp/k_e
  cohesive   slope k_c = k_e / (k_el/k_cl) with Table 3's ratio (1.8 Ning, 3.9 Du; illustrative
             only: the calibration reads f_cp but not this tail) to detachment at -5 f_cp / 9

Ning: one CSV with a column pair per curve (overlap in nm, force in uN).
Du:   one CSV per curve (overlap in nm, force in uN).
Run from this folder: python3 make_examples.py
"""

SAMPLES = 20  # per straight segment

CASES = {
    "ning": dict(ratio=1.8, curves=[(42.4, 210.5, 177.3, 8.4), (20.9, 112.6, 91.1, 6.1), (8.3, 53.9, 41.3, 4.6)]),
    "du": dict(ratio=3.9, curves=[(8584.4, 53.7, 33.4, 321.5), (5170.7, 35.7, 20.2, 239.7),
                                  (2132.2, 17.9, 8.2, 170.8)]),
}
HEADER = ("# Reconstructed from Nan et al. 2022 Table 2 ({case}; digitised values, cleaned where garbled),\n"
          "# NOT measured data: piecewise-linear loading envelope through the peaks, unloading line of\n"
          "# Nan (50) through alpha_p, pull-off at -f_cp, illustrative cohesive tail. See make_examples.py.\n"
          "# Units: overlap nm, force uN (epac-calibrate --overlap-unit nm --force-unit uN).\n")


def segment(a0, f0, a1, f1, include_start):
    pts = []
    for k in range(0 if include_start else 1, SAMPLES + 1):
        t = k / SAMPLES
        pts.append((a0 + t * (a1 - a0), f0 + t * (f1 - f0)))
    return pts


def curve(peaks, own, ratio):
    f_max, a_max, a_p, f_cp = own
    env = [(0.0, 0.0)] + sorted((p[1], p[0]) for p in peaks)
    pts = [(0.0, 0.0)]
    for (a0, f0), (a1, f1) in zip(env, env[1:]):
        if a0 >= a_max:
            break
        pts += segment(a0, f0, a1, f1, False)
    pts[-1] = (a_max, f_max)  # exact peak
    k_e = f_max / (a_max - a_p)
    a_cp = a_p - f_cp / k_e
    k_c = k_e / ratio
    a_jp = a_cp - (4.0 / 9.0) * f_cp / k_c
    pts += segment(a_max, f_max, a_p, 0.0, False)
    pts[-1] = (a_p, 0.0)  # exact zero crossing
    pts += segment(a_p, 0.0, a_cp, -f_cp, False)
    pts[-1] = (a_cp, -f_cp)  # exact pull-off
    pts += segment(a_cp, -f_cp, a_jp, -5.0 / 9.0 * f_cp, False)
    return pts


def fmt(x):
    return "%.10g" % x


def main():
    for case, d in CASES.items():
        curves = [curve(d["curves"], c, d["ratio"]) for c in d["curves"]]
        if case == "ning":
            with open("ning_table2.csv", "w") as f:
                f.write(HEADER.format(case="Ning, R = 2.45 um, E = 1.2 GPa, nu = 0.3, Gamma = 0.2 J/m2, p_y = 35.3 MPa"))
                f.write(",".join("overlap_nm_%d,force_uN_%d" % (i + 1, i + 1) for i in range(len(curves))) + "\n")
                for k in range(max(len(c) for c in curves)):
                    cells = []
                    for c in curves:
                        cells += [fmt(c[k][0]), fmt(c[k][1])] if k < len(c) else ["", ""]
                    f.write(",".join(cells) + "\n")
        else:
            for i, c in enumerate(curves):
                with open("du_table2_curve%d.csv" % (i + 1), "w") as f:
                    f.write(HEADER.format(case="Du, R = 4 um, E = 410 GPa, nu = 0.3, Gamma = 1.0 J/m2, p_y = 5.52 GPa, curve %d" % (i + 1)))
                    f.write("overlap_nm,force_uN\n")
                    for a, fo in c:
                        f.write(fmt(a) + "," + fmt(fo) + "\n")


if __name__ == "__main__":
    main()
