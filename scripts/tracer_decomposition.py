#!/usr/bin/python3
"""The tracer/MD gap split in two (issue 32): at every common recorded time,

    tracer-in-NS - MD = [tracer-in-MD-fields - MD] + [tracer-in-NS - tracer-in-MD-fields],

the first bracket Eq. (36)'s own error (molecular chaos, local Maxwellian: the tracer runs in the
MD's own measured n, u, T, `coldblast tracer --background md --md-run MD`), the second the
Navier-Stokes background's (docs/verification.md, "The tracer in the MD's own fields").

R_imp, V_imp and C_imp come from each run's blocks.csv with delete-one-block jackknife errors
(block_jackknife.py, the catalogue's transforms: sqrt of the mean for R_imp and V_imp, Eq. (38));
the differences are in per cent of the MD's value, so the two brackets add up to the total exactly.
The two tracer runs are paired block by block when their blocks match (same seed and block size:
their kicks are the same, so the background term's error is the jackknife of the difference);
the MD is independent of both. p_imp's <r^4>/<r^2>^2 is each run's p_imp.csv histogram ratio
with its error propagated from the bins' errors (compare/figures.cpp's way); differences absolute.
Nothing is fitted.

--variants DIR...: other tracer-in-MD-fields runs, made in the fields of scripts/profile_variants.py
(coarser or perturbed profiles) with TRACER_MD_DIR's seed, and their paired changes from
TRACER_MD_DIR in per cent of the MD (p_imp's ratio: absolute): what the first bracket owes to the
profiles' binning and noise.

Usage:
    scripts/tracer_decomposition.py MD_DIR TRACER_NS_DIR TRACER_MD_DIR [--times 15.625,250,4000]
                                     [--figure decomposition.png] [--title TEXT] [--variants DIR...]
Prints markdown tables (all common times unless --times) and draws the figure with gnuplot. Times up
to a tracer's own start (summary.json's start_time) are left out: its R_imp and C_imp are 0 there by
construction.
"""
import argparse
import csv
import io
import json
import os
import subprocess
import tempfile

import numpy as np

from block_jackknife import block_sums, jackknife

OBSERVABLES = ("R_imp", "V_imp", "C_imp")
SQUARE_ROOT = {"R_imp": True, "V_imp": True, "C_imp": False}  # theory/observables.cpp's transforms


def transform(name):
    return (lambda x, count: np.sqrt(x / count)) if SQUARE_ROOT[name] else (lambda x, count: x / count)


def blocks(directory, name, times):
    """(parts, counts, block ids): per block the sums of `name`'s inner values at `times`."""
    sums, counts = block_sums(directory, [name])
    ids = sorted(sums)
    return [np.array([sums[b][(t, name)] for t in times]) for b in ids], [counts[b] for b in ids], ids


def recorded_times(directory, name):
    sums, _ = block_sums(directory, [name])
    return {t for block in sums.values() for (t, o) in block if o == name}


def observable(directory, name, times):
    """Values and jackknife errors of `name` at `times`."""
    parts, counts, _ = blocks(directory, name, times)
    return jackknife(parts, counts, transform(name))


def tracer_difference(ns, md_fields, name, times):
    """statistic(ns) - statistic(md_fields) and its error: paired jackknife over common blocks when
    the two runs have the same blocks and counts, else the two runs' errors in quadrature."""
    pa, ca, ia = blocks(ns, name, times)
    pb, cb, ib = blocks(md_fields, name, times)
    f = transform(name)
    if ia == ib and ca == cb:
        parts = [np.concatenate([a, b]) for a, b in zip(pa, pb)]
        k = len(times)
        value, error = jackknife(parts, ca, lambda x, count: f(x[:k], count) - f(x[k:], count))
        return value, error, True
    va, ea = jackknife(pa, ca, f)
    vb, eb = jackknife(pb, cb, f)
    return va - vb, np.hypot(ea, eb), False


def read_rows(path):
    with open(path) as handle:
        return list(csv.DictReader(io.StringIO("".join(l for l in handle if not l.startswith("#")))))


def moment_ratio(directory, t):
    """<r^4>/<r^2>^2 of p_imp.csv's histogram at t and its error from the bins' errors (moments as
    sums of r^k p dr over the bins, compare/figures.cpp)."""
    rows = [r for r in read_rows(os.path.join(directory, "p_imp.csv")) if abs(float(r["t"]) / t - 1) < 1e-9]
    if not rows:
        return np.nan, np.nan
    r = np.array([float(x["r"]) for x in rows])
    p = np.array([float(x["p"]) for x in rows])
    e = np.array([float(x["p_stderr"]) for x in rows])
    w = np.array([float(x["r_hi"]) - float(x["r_lo"]) for x in rows])
    e = np.where(np.isfinite(e), e, 0.0)
    m0, m2, m4 = (p * w).sum(), (r ** 2 * p * w).sum(), (r ** 4 * p * w).sum()
    if m0 <= 0 or m2 <= 0:
        return np.nan, np.nan
    ratio = m4 * m0 / m2 ** 2
    derivative = ratio * (r ** 4 / m4 + 1 / m0 - 2 * r ** 2 / m2) * w
    return ratio, float(np.sqrt(((derivative * e) ** 2).sum()))


def start_time(run):
    """The time a tracer run's trajectories start (summary.json's start_time; 0 if it records none)."""
    path = os.path.join(run, "summary.json")
    if not os.path.exists(path):
        return 0.0
    with open(path) as f:
        return float(json.load(f).get("start_time", 0.0))


def decomposition(md, ns, md_fields, times=None):
    """{name: rows}, each row (t, total, total_error, own, own_error, background, background_error)
    in per cent of the MD's value, and {"p_imp": rows (t, md, ns, md_fields ratios and errors)}."""
    common = recorded_times(md, "R_imp") & recorded_times(ns, "R_imp") & recorded_times(md_fields, "R_imp")
    # At a tracer's own start its R_imp and C_imp are 0 by construction (it counts from there), not a measurement.
    start = max(start_time(ns), start_time(md_fields))
    common = {t for t in common if t > start * (1 + 1e-9)}
    times = sorted(common if times is None else [t for t in common if any(abs(t / x - 1) < 1e-6 for x in times)])
    out = {"times": times, "paired": {}}
    np.seterr(divide="ignore", invalid="ignore")  # an MD value of 0 (C_imp at t_min) gives NaN, drawn as a gap
    for name in OBSERVABLES:
        m, dm = observable(md, name, times)
        a, da = observable(ns, name, times)
        b, db = observable(md_fields, name, times)
        diff, ddiff, paired = tracer_difference(ns, md_fields, name, times)
        out["paired"][name] = paired
        total = 100 * (a / m - 1)
        total_error = 100 * (a / m) * np.hypot(da / a, dm / m)
        own = 100 * (b / m - 1)
        own_error = 100 * (b / m) * np.hypot(db / b, dm / m)
        background = 100 * diff / m
        background_error = 100 * np.hypot(ddiff, diff * dm / m) / m
        out[name] = list(zip(times, total, total_error, own, own_error, background, background_error, m, dm))
    rows = []
    for t in times:
        rows.append((t,) + moment_ratio(md, t) + moment_ratio(ns, t) + moment_ratio(md_fields, t))
    out["p_imp"] = rows
    return out


def variant_changes(md, base, variants, times):
    """{name: rows (t, [(change, error) per variant])}: each variant's R_imp, V_imp, C_imp minus the
    base run's (paired jackknife when their blocks match), in per cent of the MD's value; "p_imp":
    the ratio's change, errors in quadrature."""
    out = {}
    for name in OBSERVABLES:
        m, _ = observable(md, name, times)
        columns = [tracer_difference(v, base, name, times)[:2] for v in variants]
        out[name] = [(t, [(100 * c[0][k] / m[k], 100 * c[1][k] / m[k]) for c in columns])
                     for k, t in enumerate(times)]
    rows = []
    for t in times:
        b, db = moment_ratio(base, t)
        rows.append((t, [(r - b, float(np.hypot(dr, db))) for r, dr in (moment_ratio(v, t) for v in variants)]))
    out["p_imp"] = rows
    return out


def variants_markdown(changes, variants):
    head = "| t | " + " | ".join(os.path.basename(os.path.normpath(v)) for v in variants) + " |"
    rule = "|---" * (len(variants) + 1) + "|"
    lines = []
    for name in OBSERVABLES + ("p_imp",):
        unit = "per cent of the MD's value" if name != "p_imp" else "⟨r⁴⟩/⟨r²⟩², absolute"
        lines += [f"**{name}**, variant − tracer-in-MD-fields ({unit}):", "", head, rule]
        digits = 3 if name == "p_imp" else 2
        for t, cells in changes[name]:
            lines.append(f"| {t:.4g} | " + " | ".join(pm(c, e, digits) for c, e in cells) + " |")
        lines.append("")
    return "\n".join(lines)


def pm(value, error, digits=1):
    return f"{value:+.{digits}f} ± {error:.{digits}f}"


def markdown(result):
    lines = []
    for name in OBSERVABLES:
        lines += [f"**{name}** (per cent of the MD's value):", "",
                  "| t | MD | tracer-in-NS − MD | = tracer-in-MD-fields − MD (Eq. (36)) | + tracer-in-NS − tracer-in-MD-fields (background) |",
                  "|---|---|---|---|---|"]
        for t, total, te, own, oe, bg, be, m, dm in result[name]:
            lines.append(f"| {t:.4g} | {m:.5g} ± {dm:.2g} | {pm(total, te)} | {pm(own, oe)} | {pm(bg, be)} |")
        lines.append("")
    lines += ["**p_imp's ⟨r⁴⟩/⟨r²⟩²** (histograms of p_imp.csv):", "",
              "| t | MD | tracer-in-NS − MD | = tracer-in-MD-fields − MD (Eq. (36)) | + tracer-in-NS − tracer-in-MD-fields (background) |",
              "|---|---|---|---|---|"]
    for t, m, dm, a, da, b, db in result["p_imp"]:
        lines.append(f"| {t:.4g} | {m:.3f} ± {dm:.3f} | {pm(a - m, np.hypot(da, dm), 3)} | "
                     f"{pm(b - m, np.hypot(db, dm), 3)} | {pm(a - b, np.hypot(da, db), 3)} |")
    return "\n".join(lines)


def quoted(text):
    """A gnuplot double-quoted string."""
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def draw(result, path, title):
    """Four panels against t (log): per observable the total, Eq. (36)'s own and the background's
    part with 1-sigma error bars; p_imp's ratio of the three runs."""
    with tempfile.TemporaryDirectory() as folder:
        for name in OBSERVABLES:
            with open(os.path.join(folder, f"{name}.dat"), "w") as f:
                for t, total, te, own, oe, bg, be, m, dm in result[name]:
                    f.write(f"{t} {total} {te} {own} {oe} {bg} {be}\n")
        with open(os.path.join(folder, "p_imp.dat"), "w") as f:
            for row in result["p_imp"]:
                f.write(" ".join(str(x) for x in row) + "\n")
        panels = []
        for name in OBSERVABLES:
            data = os.path.join(folder, f"{name}.dat")
            panels.append(
                f"set title {quoted(name.replace('_imp', '_{imp}') + ': tracer - MD, per cent of the MD')}\n"
                "set ylabel 'per cent'\n"
                f"plot 0 notitle lc 'black', "
                f"'{data}' u 1:2:3 w yerrorlines pt 7 ps 0.5 lc rgb '#000000' t 'tracer in NS - MD (total)', "
                f"'{data}' u 1:4:5 w yerrorlines pt 5 ps 0.5 lc rgb '#d62728' t 'tracer in MD fields - MD (Eq. (36))', "
                f"'{data}' u 1:6:7 w yerrorlines pt 9 ps 0.5 lc rgb '#1f77b4' t 'tracer in NS - in MD fields (background)'\n")
        data = os.path.join(folder, "p_imp.dat")
        panels.append(
            "set title \"p_{imp}'s <r^4>/<r^2>^2\"\nset ylabel 'ratio'\n"
            f"plot '{data}' u 1:2:3 w yerrorlines pt 7 ps 0.5 lc rgb '#000000' t 'MD', "
            f"'{data}' u 1:4:5 w yerrorlines pt 9 ps 0.5 lc rgb '#1f77b4' t 'tracer in NS', "
            f"'{data}' u 1:6:7 w yerrorlines pt 5 ps 0.5 lc rgb '#d62728' t 'tracer in MD fields'\n")
        script = (f"set terminal pngcairo size 1400,1000 font ',10'\nset output {quoted(path)}\n"
                  f"set multiplot layout 2,2 title {quoted(title)}\nset logscale x\nset xlabel 't'\nset grid\n"
                  "set key below\n" + "".join(panels) + "unset multiplot\n")
        subprocess.run(["gnuplot"], input=script, text=True, check=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("md")
    parser.add_argument("tracer_ns")
    parser.add_argument("tracer_md_fields")
    parser.add_argument("--times", help="comma-separated recorded times of the tables (default: all)")
    parser.add_argument("--figure", help="PNG to draw (all common times)")
    parser.add_argument("--title", default="tracer - MD = [Eq. (36) in the MD's fields] + [NS background]")
    parser.add_argument("--variants", nargs="+", default=[], help="tracer runs in profile_variants.py's fields")
    args = parser.parse_args()
    times = [float(x) for x in args.times.split(",")] if args.times else None
    result = decomposition(args.md, args.tracer_ns, args.tracer_md_fields, times)
    if times and len(result["times"]) != len(times):
        parser.error(f"--times: only {result['times']} are recorded by all three runs")
    print(markdown(result))
    paired = [n for n, p in result["paired"].items() if p]
    print(f"\n(background term: {'paired jackknife' if paired else 'independent errors'}; "
          f"MD independent)")
    if args.variants:
        print("\n" + variants_markdown(variant_changes(args.md, args.tracer_md_fields, args.variants,
                                                        result["times"]), args.variants))
    if args.figure:
        draw(decomposition(args.md, args.tracer_ns, args.tracer_md_fields), args.figure, args.title)


if __name__ == "__main__":
    main()
