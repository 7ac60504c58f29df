#!/usr/bin/python3
"""Tracer run directory against an MD run directory at every common recording time.

Usage: scripts/tracer_vs_md.py TRACER_DIR MD_DIR [--t T_PIMP]
Prints, per time, tracer/MD - 1 for R_imp, V_imp, C_imp (with the combined standard error and the
deviation in sigma), and at T_PIMP (default: the last common time) both p_imp histograms' moment
ratio <r^4>/<r^2>^2 (histogram moments, as compare/ computes them) and the chi^2/dof between the
two histograms (combined per-bin errors). Standard library only (docs/kinetic.md).
"""
import csv
import math
import sys


def read_rows(path):
    with open(path) as f:
        lines = [line for line in f if not line.startswith("#")]
    return list(csv.DictReader(lines))


def observables(directory):
    table = {}
    for row in read_rows(directory + "/observables.csv"):
        table[(round(float(row["t"]), 6), row["observable"])] = (float(row["mean"]), float(row["stderr"]))
    return table


def p_imp(directory, t):
    rows = [r for r in read_rows(directory + "/p_imp.csv") if abs(float(r["t"]) - t) < 1e-6 * t]
    return [(float(r["r"]), float(r["p"]), float(r["p_stderr"]), float(r["r_hi"]) - float(r["r_lo"])) for r in rows]


def moment_ratio(hist):
    m2 = sum(p * w * r * r for r, p, e, w in hist)
    m4 = sum(p * w * r ** 4 for r, p, e, w in hist)
    return m4 / (m2 * m2)


def main():
    tracer, md = sys.argv[1], sys.argv[2]
    t_pimp = float(sys.argv[sys.argv.index("--t") + 1]) if "--t" in sys.argv else None
    a, b = observables(tracer), observables(md)
    times = sorted({t for t, o in a if (t, o) in b})
    print("t          " + "  ".join(f"{o + ' tracer/MD-1':>26}" for o in ("R_imp", "V_imp", "C_imp")))
    for t in times:
        cells = []
        for o in ("R_imp", "V_imp", "C_imp"):
            (x, dx), (y, dy) = a[(t, o)], b[(t, o)]
            if x <= 0 or y <= 0:
                cells.append(f"{'-':>26}")
                continue
            ratio = x / y - 1
            error = (x / y) * math.sqrt((dx / x) ** 2 + (dy / y) ** 2)
            cells.append(f"{ratio:+9.4f} ± {error:.4f} ({ratio / error:+7.1f}σ)")
        print(f"{t:<10.5g} " + "  ".join(cells))
    t = t_pimp or times[-1]
    h1, h2 = p_imp(tracer, t), p_imp(md, t)
    if h1 and h2 and len(h1) == len(h2):
        chi2, dof = 0.0, 0
        for (r1, p1, e1, w1), (r2, p2, e2, w2) in zip(h1, h2):
            if abs(r1 / r2 - 1) > 1e-9:
                sys.exit("p_imp bins differ: same scene and A_d needed")
            if e1 > 0 and e2 > 0 and (p1 > 0 or p2 > 0):
                chi2 += (p1 - p2) ** 2 / (e1 * e1 + e2 * e2)
                dof += 1
        print(f"p_imp at t = {t:g}: <r^4>/<r^2>^2 tracer {moment_ratio(h1):.4f}, MD {moment_ratio(h2):.4f}; "
              f"chi^2/dof of the difference {chi2 / dof:.2f} ({dof} bins)")


if __name__ == "__main__":
    main()
