#!/usr/bin/python3
"""The start's memory in one figure: each start's difference from the kick at equal R/λ, from the
comparison tables of scripts/start_memory.py (its --out CSV, one per start against the same kick).

Usage: scripts/start_memory_figure.py CSV [CSV...] --labels LABEL [LABEL...] --out FIGURE.png
                                      [--title TEXT]

Eight panels against R/λ (log): Δ = start/kick - 1 in per cent, with the paired jackknife errors
(one standard error), for n0/n, T0/Rdot^2, T0, H/R, R_imp, V_imp, C_imp, each start in its own
colour; where a table has the Navier-Stokes hot spot's own memory (its ns_delta column, the NS hot
spot against the NS self-similar start), it is drawn dashed in the start's colour. The eighth panel
is p_imp's <r^4>/<r^2>^2 itself: the kick's (from the first table) and each start's, with the
tracer's asymptotic value (docs/verification.md: 1.714 in 2D, 1.342 in 3D) as a grey line.
Nothing is fitted; the figure draws the tables' numbers.
"""
import argparse
import csv
import os
import subprocess
import tempfile

PANELS = [("n0/n", "n_0/n_∞"), ("T0/Rdot^2", "T_0/Ṙ^2"), ("T0", "T_0 (units E/(n λ^d))"), ("H/R", "H/R"),
          ("R_imp", "R_{imp}"), ("V_imp", "V_{imp}"), ("C_imp", "C_{imp}")]
COLOURS = ["#d62728", "#1f77b4", "#2ca02c", "#9467bd", "#ff7f0e"]
TRACER_ASYMPTOTE = {2: 1.714, 3: 1.342}  # p_imp's <r^4>/<r^2>^2 of the tracer at R/λ → ∞ (docs/verification.md)


def read_table(path):
    """{amplitude: [(x, kick, kick_err, other, other_err, delta, delta_err, ns_delta or None)]}."""
    with open(path) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    table = {}
    for r in rows:
        ns = r.get("ns_delta", "")
        table.setdefault(r["amplitude"], []).append(
            (float(r["R_over_lambda"]), float(r["kick"]), float(r["kick_err"]), float(r["hotspot"]),
             float(r["hotspot_err"]), float(r["delta"]), float(r["delta_err"]), float(ns) if ns else None))
    for name in table:
        table[name].sort()
    return table


def quoted(text):
    """A gnuplot double-quoted string."""
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def write_data(folder, tables):
    """One file per (table, amplitude): x, Δ %, error %, NS Δ % (NaN if none); p_imp: x, kick, err, start, err."""
    files = {}
    for k, table in enumerate(tables):
        for name, rows in table.items():
            path = os.path.join(folder, f"{k}-{name.replace('/', '_').replace('^', '')}.dat")
            with open(path, "w") as f:
                for x, kick, kick_e, other, other_e, delta, delta_e, ns in rows:
                    if name == "p_imp_ratio":
                        f.write(f"{x} {kick} {kick_e} {other} {other_e}\n")
                    else:
                        f.write(f"{x} {100 * delta} {100 * delta_e} {100 * ns if ns is not None else 'NaN'}\n")
            files[(k, name)] = path
    return files


def curve_styles(tables, labels):
    """Per start: its points' style and, if any of its tables has the NS column, its dashed NS line."""
    styles = []
    for k, label in enumerate(labels):
        colour = COLOURS[k % len(COLOURS)]
        has_ns = any(row[7] is not None for rows in tables[k].values() for row in rows)
        styles.append((f"pt 7 ps 0.6 lc rgb '{colour}'", f"dt 2 lw 1.5 lc rgb '{colour}'" if has_ns else None))
    return styles


def difference_panel(name, label, tables, labels, files, styles):
    plots = ["0 notitle lc 'black'"]
    for k in range(len(tables)):
        if name not in tables[k]:
            continue
        points, dashes = styles[k]
        plots.append(f"'{files[(k, name)]}' u 1:2:3 w yerrorlines {points} notitle")
        if dashes and any(row[7] is not None for row in tables[k][name]):
            plots.append(f"'{files[(k, name)]}' u 1:4 w lines {dashes} notitle")
    return (f"set title {quoted(label + ': start/kick - 1')}\nset ylabel 'per cent'\n"
            "plot " + ", ".join(plots) + "\n")


def ratio_panel(tables, labels, files, styles, d):
    plots = []
    if "p_imp_ratio" in tables[0]:
        plots.append(f"'{files[(0, 'p_imp_ratio')]}' u 1:2:3 w yerrorlines pt 5 ps 0.6 lc rgb 'black' notitle")
    for k in range(len(tables)):
        if "p_imp_ratio" in tables[k]:
            plots.append(f"'{files[(k, 'p_imp_ratio')]}' u 1:4:5 w yerrorlines {styles[k][0]} notitle")
    plots.append(f"{TRACER_ASYMPTOTE[d]} lc rgb '#888888' lw 2 notitle")
    return "set title \"p_{imp}'s <r^4>/<r^2>^2\"\nset ylabel 'ratio'\nplot " + ", ".join(plots) + "\n"


def legend(labels, styles):
    """A strip across the bottom: every curve of the figure once, in one row."""
    entries = ["NaN w linespoints pt 5 ps 0.6 lc rgb 'black' t 'kick'"]
    for label, (points, dashes) in zip(labels, styles):
        entries.append(f"NaN w linespoints {points} t {quoted(label)}")
        if dashes:
            entries.append(f"NaN w lines {dashes} t {quoted(label + ': NS, same start')}")
    entries.append("NaN w lines lc rgb '#888888' lw 2 t 'tracer, R/λ → ∞ (p_{imp})'")
    return ("set origin 0, 0\nset size 1, 0.07\nunset border\nunset tics\nunset grid\nunset title\n"
            "unset xlabel\nunset ylabel\nunset logscale x\nset xrange [0:1]\nset yrange [0:1]\n"
            "set key center center horizontal maxrows 1 samplen 3 width 1\nplot " + ", ".join(entries) + "\n")


def draw(tables, labels, path, title, d):
    """Eight panels on a 2 x 4 grid above a legend strip (plain multiplot: the positions are set here)."""
    with tempfile.TemporaryDirectory() as folder:
        files = write_data(folder, tables)
        styles = curve_styles(tables, labels)
        bodies = [difference_panel(name, label, tables, labels, files, styles) for name, label in PANELS]
        bodies.append(ratio_panel(tables, labels, files, styles, d))
        xs = [row[0] for table in tables for rows in table.values() for row in rows]
        bottom, top, width, height = 0.07, 0.95, 0.25, 0.44
        script = (f"set terminal pngcairo size 1800,900 font ',10'\nset output {quoted(path)}\n"
                  f"set multiplot title {quoted(title)}\nunset key\nset logscale x\nset xlabel 'R/λ'\n"
                  "set xtics (10, 15, 20, 30, 50, 70, 100, 150, 200, 300, 500)\n"
                  f"set grid\nset xrange [{0.95 * min(xs)}:{1.05 * max(xs)}]\n")
        for k, body in enumerate(bodies):
            row, column = divmod(k, 4)
            script += (f"set origin {column * width}, {top - (row + 1) * height}\n"
                       f"set size {width}, {height}\n" + body)
        assert top - 2 * height >= bottom - 1e-12
        script += legend(labels, styles) + "unset multiplot\n"
        subprocess.run(["gnuplot"], input=script, text=True, check=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("tables", nargs="+", help="scripts/start_memory.py --out CSVs, each against the same kick")
    parser.add_argument("--labels", nargs="+", required=True, help="one per table, e.g. 'hot spot r0 = λ'")
    parser.add_argument("--out", required=True, help="PNG to draw")
    parser.add_argument("--title", default="The start's memory: each start against the kick at equal R/λ")
    parser.add_argument("--d", type=int, default=2, choices=(2, 3), help="dimension (the tracer's asymptote)")
    args = parser.parse_args()
    if len(args.labels) != len(args.tables):
        parser.error(f"--labels: {len(args.labels)} given for {len(args.tables)} tables; give one per table")
    tables = [read_table(path) for path in args.tables]
    for path, table in zip(args.tables, tables):
        missing = [name for name, _ in PANELS if name not in table]
        if missing:
            parser.error(f"{path}: no rows for {', '.join(missing)} (not a scripts/start_memory.py table?)")
    draw(tables, args.labels, args.out, args.title, args.d)
    print(f"{args.out}: {len(tables)} starts against the kick, R/λ from "
          f"{min(r[0] for t in tables for r in t['n0/n']):.3g} to {max(r[0] for t in tables for r in t['n0/n']):.3g}")


if __name__ == "__main__":
    main()
