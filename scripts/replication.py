#!/usr/bin/python3
"""Two independent ensembles of the same scene against the dense Navier-Stokes blast, side by side:
does the second replicate the first? Reads the amplitudes.csv that `coldblast compare RUN --against
hydro` writes for each (docs/compare.md, "Against R/λ").

Usage: scripts/replication.py A.csv B.csv [--labels A B] [--at R/λ ...] [--amplitudes NAME ...] [--pooled]

For each chosen R/λ (the recorded time nearest to it in each file) and amplitude, prints a Markdown
row: MD/NS - 1 in per cent with its jackknife error in A and in B, and their difference in combined
standard errors, (a - b)/sqrt(σa² + σb²). That is the right σ only when the two ensembles share no
realization (different seeds): the script cannot check that, the caller must. With --pooled, a last
column holds the two ensembles' inverse-variance mean and its standard error, 1/sqrt(1/σa² + 1/σb²),
fair under the same condition. Nothing is fitted.
"""
import argparse
import csv
import math
import sys

AMPLITUDES = ["H/R", "n(centre)/n", "T(centre)/Rdot^2", "n0/n", "T0/Rdot^2", "R"]


def read(path):
    """{(R/λ, amplitude): (MD/NS - 1, its standard error)} from an amplitudes.csv."""
    with open(path) as f:
        rows = csv.DictReader(line for line in f if not line.startswith("#"))
        return {(float(r["R_over_lambda"]), r["amplitude"]): (float(r["md_over_ns_minus_1"]),
                                                             float(r["md_over_ns_minus_1_stderr"])) for r in rows}


def nearest(table, x):
    """The recorded R/λ of table nearest to x."""
    return min({rl for rl, _ in table}, key=lambda rl: abs(rl - x))


def difference(a, b):
    """(a - b) in combined standard errors of independent estimates a = (value, error), b likewise."""
    return (a[0] - b[0]) / math.hypot(a[1], b[1])


def pooled(a, b):
    """The inverse-variance mean of independent estimates a and b, (value, standard error)."""
    wa, wb = a[1] ** -2, b[1] ** -2
    return (wa * a[0] + wb * b[0]) / (wa + wb), (wa + wb) ** -0.5


def percent(v):
    return f"{100 * v[0]:+.2f} ± {100 * v[1]:.2f}".replace("-", "−")


def rows(a, b, at, amplitudes, with_pooled=False):
    """The Markdown table's rows: R/λ (A's), amplitude, A, B, the difference in σ (and the pooled mean)."""
    out = []
    for x in at:
        ra, rb = nearest(a, x), nearest(b, x)
        for name in amplitudes:
            if (ra, name) not in a or (rb, name) not in b:
                continue
            d = difference(a[(ra, name)], b[(rb, name)])
            both = f" {percent(pooled(a[(ra, name)], b[(rb, name)]))} |" if with_pooled else ""
            out.append(f"| {ra:.0f} | {name} | {percent(a[(ra, name)])} | {percent(b[(rb, name)])} | "
                       f"{d:+.1f} |{both}".replace("-", "−"))
    return out


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("a", metavar="A.csv", help="amplitudes.csv of the first ensemble")
    p.add_argument("b", metavar="B.csv", help="amplitudes.csv of the second, independent ensemble")
    p.add_argument("--labels", nargs=2, default=["A", "B"], metavar=("A", "B"), help="the columns' names")
    p.add_argument("--at", nargs="+", type=float, default=[36, 50, 71, 100, 141, 200, 259, 307],
                   help="R/λ at which to compare (the nearest recorded time in each file)")
    p.add_argument("--amplitudes", nargs="+", default=AMPLITUDES, choices=AMPLITUDES, metavar="NAME",
                   help="which rows (default: all): " + ", ".join(AMPLITUDES))
    p.add_argument("--pooled", action="store_true", help="add the two ensembles' inverse-variance mean")
    args = p.parse_args(argv)
    if any(x <= 0 for x in args.at):
        p.error("--at: each R/λ must be > 0")
    tables = []
    for path in (args.a, args.b):
        try:
            tables.append(read(path))
        except OSError as e:
            p.error(f"{path}: {e.strerror}")
        except (KeyError, ValueError) as e:
            p.error(f"{path}: not an amplitudes.csv of `coldblast compare --against hydro` ({e!r})")
    for path, table in zip((args.a, args.b), tables):
        if not table:
            p.error(f"{path}: no rows")
    a, b = tables
    print(f"| R/λ | amplitude | {args.labels[0]}: MD/NS − 1 (%) | {args.labels[1]} | difference (σ) |"
          + (" pooled |" if args.pooled else ""))
    print("|---|---|---|---|---|" + ("---|" if args.pooled else ""))
    print("\n".join(rows(a, b, args.at, args.amplitudes, args.pooled)))


if __name__ == "__main__":
    main(sys.argv[1:])
