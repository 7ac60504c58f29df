#!/usr/bin/python3
"""Several runs' amplitudes against the dense Navier-Stokes blast, against R/λ, in one figure: the
amplitudes.csv that `coldblast compare RUN --against hydro` writes (docs/compare.md, "Against R/λ"),
one per run, of the same scene at different depths.

Usage: scripts/amplitude_history_figure.py CSV [CSV...] --labels LABEL [LABEL...] --out FIGURE.png
                                           [--title TEXT] [--from R_OVER_LAMBDA]

One panel per amplitude the files share (n(centre)/n, H/R, T(centre)/Rdot^2, n0/n, T0/Rdot^2, R):
MD/NS - 1 in per cent with its one-standard-error bar, each run in its own colour, and the
continuum bound (Kn² of the NS core; λ/R for R) of the run that reaches furthest as a grey band.
--from drops the times below that R/λ (e.g. 25: where the kick's memory has faded). Nothing is
fitted; the figure draws the files' numbers.
"""
import argparse
import csv
import os
import subprocess
import tempfile

PANELS = [("n(centre)/n", "n(centre)/n_∞"), ("H/R", "H/R"), ("T(centre)/Rdot^2", "T(centre)/Ṙ^2"),
          ("n0/n", "n_0/n_∞ (100-particle ball)"), ("T0/Rdot^2", "T_0/Ṙ^2 (100-particle ball)"), ("R", "R (front)")]
COLOURS = ["#d62728", "#1f77b4", "#2ca02c", "#9467bd", "#ff7f0e"]

TOP = 0.93  # the panels' and the legend's top, in screen fractions: the title's two lines sit above
LEGEND_STRIP = 0.06  # the legend's own strip when the panels fill the grid


def layout(panels, columns):
    """The multiplot's grid in screen fractions: (rows, panel height, legend origin, legend size). The
    panels fill the height under the title's two lines (TOP), from the top left; the legend takes the
    first free slot, or, when every slot holds a panel, a strip of its own between the title and the
    panels."""
    rows = (panels + columns - 1) // columns
    if panels < rows * columns:
        height = TOP / rows
        return rows, height, ((panels % columns) / columns, TOP - (panels // columns + 1) * height), \
            (1 / columns, height)
    height = (TOP - LEGEND_STRIP) / rows
    return rows, height, (0.0, TOP - LEGEND_STRIP), (1.0, LEGEND_STRIP)


def read_history(path, start):
    """{amplitude: [(R/λ, 100 (MD/NS - 1), its error, 100 bound)]}, sorted in R/λ."""
    with open(path) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    table = {}
    for r in rows:
        x = float(r["R_over_lambda"])
        if x < start:
            continue
        table.setdefault(r["amplitude"], []).append(
            (x, 100 * float(r["md_over_ns_minus_1"]), 100 * float(r["md_over_ns_minus_1_stderr"]),
             100 * float(r["continuum_bound"])))
    for name in table:
        table[name].sort()
    return table


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("csv", nargs="+")
    parser.add_argument("--labels", nargs="+", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--title", default="")
    parser.add_argument("--from", dest="start", type=float, default=0.0)
    args = parser.parse_args()
    if len(args.labels) != len(args.csv):
        parser.error("--labels: give one label per CSV (%d files, %d labels)" % (len(args.csv), len(args.labels)))
    if not args.out.endswith(".png"):
        parser.error("--out: a .png path (the PDF is written beside it)")
    tables = [read_history(path, args.start) for path in args.csv]
    panels = [(name, label) for name, label in PANELS if all(name in t for t in tables)]
    if not panels:
        parser.error("the files share no amplitude at R/λ >= %g" % args.start)
    deepest = max(range(len(tables)), key=lambda i: max(x for x, *_ in tables[i][panels[0][0]]))
    x_lo = min(min(x for x, *_ in t[panels[0][0]]) for t in tables)
    x_hi = max(x for x, *_ in tables[deepest][panels[0][0]])
    with tempfile.TemporaryDirectory() as tmp:
        data = os.path.join(tmp, "history.dat")
        with open(data, "w") as f:
            for name, _ in panels:  # index 2k + i: run i of panel k; the band after the runs
                for t in tables:
                    for row in t[name]:
                        f.write("%.10g %.10g %.10g %.10g\n" % row)
                    f.write("\n\n")
                for row in tables[deepest][name]:
                    f.write("%.10g %.10g %.10g %.10g\n" % row)
                f.write("\n\n")
        columns = 3
        rows, height, legend_origin, legend_size = layout(len(panels), columns)
        lines = []
        for fmt, ext in (("pngcairo size 1800,%d font ',12'" % (520 * rows + 120), "png"),
                         ("pdfcairo size 12.5in,%gin font ',12'" % ((520 * rows + 120) / 144), "pdf")):
            out = args.out[:-4] + "." + ext
            lines += ["set terminal " + fmt, "set output '%s'" % os.path.abspath(out).replace("'", "''")]
            title = (args.title + "\\n" if args.title else "") + \
                "points: MD/NS - 1 with 1{/Symbol s} (jackknife); grey: the continuum bound Kn^2 (R: {/Symbol l}/R)"
            lines += ['set multiplot title "%s"' % title.replace('"', "'")]
            for k, (name, label) in enumerate(panels):
                block = k * (len(tables) + 1)
                lines += ["reset", "set origin %g,%g" % ((k % columns) / columns, (rows - 1 - k // columns) * height),
                          "set size %g,%g" % (1 / columns, height), "set logscale x",
                          "set xtics (10, 20, 30, 50, 100, 200, 300, 500, 1000)",
                          "set grid lt 1 lw 0.6 lc rgb '#d0d0d0' dt 3", "set xlabel 'R/{/Symbol l}'",
                          "set ylabel 'MD/NS - 1  [%]'", "set title '%s'" % label, "unset key",
                          "set xrange [%g:%g]" % (0.9 * x_lo, 1.15 * x_hi)]
                lo = min(min(y - e for _, y, e, _ in t[name]) for t in tables)
                hi = max(max(y + e for _, y, e, _ in t[name]) for t in tables)
                pad = 0.1 * (hi - lo if hi > lo else 1)
                lines += ["set yrange [%g:%g]" % (min(lo, 0) - pad, max(hi, 0) + pad)]
                plot = ["'%s' index %d u 1:(-$4):4 w filledcurves lc rgb '#e3e3e3' t ''"
                        % (data, block + len(tables)), "0 w l lc rgb 'black' t ''"]
                for i, lab in enumerate(args.labels):
                    plot.append("'%s' index %d u 1:2:3 w yerrorbars pt 7 ps 0.8 lc rgb '%s' t ''"
                                % (data, block + i, COLOURS[i % len(COLOURS)]))
                lines.append("plot " + ", ".join(plot))
            key = ("set key at graph 0.05,0.9 left top Left reverse box spacing 1.4 font ',12'"
                   if legend_size[0] < 1 else "set key at graph 0.5,0.5 center center Left reverse box horizontal "
                   "maxrows 1 width 2 font ',12'")
            lines += ["reset", "set origin %g,%g" % legend_origin, "set size %g,%g" % legend_size, "unset border",
                      "unset tics", "set xrange [0:1]", "set yrange [0:1]", key]
            entries = ["2 w p pt 7 ps 1.2 lc rgb '%s' t '%s'" % (COLOURS[i % len(COLOURS)], lab)
                       for i, lab in enumerate(args.labels)]
            entries.append("2 w l lw 14 lc rgb '#e3e3e3' t 'continuum bound: Kn^2 of the NS core (R: {/Symbol l}/R)'")
            lines.append("plot " + ", ".join(entries))
            lines += ["unset multiplot", "unset output"]
        script = os.path.join(tmp, "history.gp")
        with open(script, "w") as f:
            f.write("\n".join(lines) + "\n")
        subprocess.run(["gnuplot", script], check=True)
    print("wrote %s and its .pdf" % args.out)


if __name__ == "__main__":
    main()
