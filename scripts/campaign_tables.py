#!/usr/bin/python3
"""The Markdown tables of a finished campaign's section in docs/verification.md, from its folder.

Usage: scripts/campaign_tables.py CAMPAIGN_DIR [--at R/λ ...] [--times t ...] [--only last along tracer]

CAMPAIGN_DIR is what `scripts/campaigns.sh finish5|finish6` leaves (data/campaign6-3d-deep, for
example). Reads vs-hydro/amplitudes.csv (`coldblast compare MD --against hydro`) and, when present,
tracer-vs-md/tracer_vs_md.csv and tracer-mdfields-vs-md/tracer_vs_md.csv (`coldblast compare TRACER
--md-run MD`, the tracer in the NS background and in the MD's own fields). Prints three tables:
- every amplitude at the last recorded time: the MD with its jackknife error, MD/NS - 1 in per cent
  and in σ, compare's verdict word and the dense NS's value;
- MD/NS - 1 in per cent along the way, at the recorded R/λ nearest to each --at;
- tracer/MD - 1 of C_imp, R_imp and V_imp in both backgrounds, at the recorded times nearest to each
  --times.
Nothing is computed that compare did not write: the script only selects and formats.
"""
import argparse
import csv
import sys

from replication import nearest

AMPLITUDES = [("T(centre)/Rdot^2", "T(centre)/Ṙ²"), ("H/R", "H/R"), ("n(centre)/n", "n(centre)/n"),
              ("n0/n", "n0/n (100-particle ball)"), ("T0/Rdot^2", "T0/Ṙ² (100-particle ball)"), ("R", "R")]
TRACER = ["C_imp", "R_imp", "V_imp"]


def rows_of(path):
    with open(path) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def amplitudes(path):
    """{(R/λ, amplitude): row} from an amplitudes.csv, with t and R/λ as floats."""
    out = {}
    for r in rows_of(path):
        r["t"], r["R_over_lambda"] = float(r["t"]), float(r["R_over_lambda"])
        out[(r["R_over_lambda"], r["amplitude"])] = r
    return out


def tracer(path):
    """{(t, observable): row} from a tracer_vs_md.csv."""
    return {(float(r["t"]), r["observable"]): r for r in rows_of(path)}


def minus(text):
    return text.replace("-", "−")


def with_error(value, error, sign=""):
    """value ± error, the error to two significant figures and the value to the same decimal place;
    sign="+" prints a plus on positive values."""
    value, error = float(value), float(error)
    if error <= 0:
        return minus(f"{value:{sign}.6g}")
    digits = max(0, 1 - int(f"{error:e}".split("e")[1]))
    return minus(f"{value:{sign}.{digits}f} ± {error:.{digits}f}")


def last_table(table):
    t_last = max(r["t"] for r in table.values())
    rl = next(r["R_over_lambda"] for r in table.values() if r["t"] == t_last)
    out = [f"At t = {t_last:.6g} (R/λ = {rl:.1f}):", "",
           "| quantity | MD | MD/NS − 1 (σ) | verdict | dense NS |", "|---|---|---|---|---|"]
    for key, name in AMPLITUDES:
        r = table.get((rl, key))
        if r is None:
            continue
        rel = 100 * float(r["md_over_ns_minus_1"])
        out.append(f"| {name} | {with_error(r['md'], r['md_stderr'])} | {minus(f'{rel:+.2f}')} % "
                   f"({minus(format(float(r['deviation_sigma']), '+.1f'))}) | {r['verdict']} | {float(r['ns']):.5g} |")
    return out


def along_table(table, at):
    picks = sorted({nearest(table, x) for x in at})
    out = ["MD/NS − 1 in per cent along the way:", "",
           "| R/λ | " + " | ".join(f"{rl:.1f}" for rl in picks) + " |", "|---|" + "---|" * len(picks)]
    for key, name in AMPLITUDES:
        cells = [table.get((rl, key)) for rl in picks]
        if all(c is None for c in cells):
            continue
        out.append(f"| {name} | " + " | ".join(
            "–" if c is None else with_error(100 * float(c["md_over_ns_minus_1"]),
                                             100 * float(c["md_over_ns_minus_1_stderr"]), "+") for c in cells) + " |")
    return out


def tracer_table(ns, mdf, times, table):
    """tracer/MD - 1 in both backgrounds at the recorded times nearest to times; R/λ from table."""
    out = ["tracer/MD − 1, NS background and the MD's own fields:", "",
           "| t | R/λ | " + " | ".join(f"{o}, NS | {o}, MD's fields" for o in TRACER) + " |",
           "|---|---|" + "---|---|" * len(TRACER)]
    rl_of_t = {r["t"]: r["R_over_lambda"] for r in table.values()}
    for x in times:
        ta = min({t for t, _ in ns}, key=lambda s: abs(s - x))
        tb = min({t for t, _ in mdf}, key=lambda s: abs(s - x))
        rl = rl_of_t[min(rl_of_t, key=lambda s: abs(s - ta))]
        cells = []
        for o in TRACER:
            for rows, t in ((ns, ta), (mdf, tb)):
                r = rows.get((t, o))
                cells.append("–" if r is None else with_error(r["ratio_minus_1"], r["ratio_minus_1_stderr"], "+"))
        out.append(f"| {ta:.0f} | {rl:.0f} | " + " | ".join(cells) + " |")
    return out


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("campaign", metavar="CAMPAIGN_DIR", help="a finished campaign's folder (vs-hydro/, tracer-*-vs-md/)")
    p.add_argument("--at", nargs="+", type=float, default=[10, 20, 35, 50, 71, 100, 141, 200, 307],
                   help="R/λ of the along-the-way table's columns (the nearest recorded time)")
    p.add_argument("--times", nargs="+", type=float, default=[],
                   help="t of the tracer table's rows (the nearest recorded time); default: the last four --at")
    p.add_argument("--only", nargs="+", choices=["last", "along", "tracer"], default=["last", "along", "tracer"],
                   help="which tables to print (default: all three)")
    args = p.parse_args(argv)
    if any(x <= 0 for x in args.at + args.times):
        p.error("--at and --times: each value must be > 0")
    base = args.campaign.rstrip("/")
    try:
        table = amplitudes(f"{base}/vs-hydro/amplitudes.csv")
    except OSError as e:
        p.error(f"{base}/vs-hydro/amplitudes.csv: {e.strerror}")
    except (KeyError, ValueError) as e:
        p.error(f"{base}/vs-hydro/amplitudes.csv: not an amplitudes.csv of `coldblast compare --against hydro` ({e!r})")
    if not table:
        p.error(f"{base}/vs-hydro/amplitudes.csv: no rows")
    blocks = ([last_table(table)] if "last" in args.only else []) + ([along_table(table, args.at)] if "along" in args.only else [])
    print("\n\n".join("\n".join(b) for b in blocks))
    if "tracer" not in args.only:
        return
    try:
        ns, mdf = tracer(f"{base}/tracer-vs-md/tracer_vs_md.csv"), tracer(f"{base}/tracer-mdfields-vs-md/tracer_vs_md.csv")
    except OSError:
        return  # no tracer comparison in this folder: the amplitude tables are all there is
    times = args.times or sorted({table[(nearest(table, x), "R")]["t"] for x in args.at if (nearest(table, x), "R") in table})[-4:]
    print("\n".join(([""] if blocks else []) + tracer_table(ns, mdf, times, table)))


if __name__ == "__main__":
    main(sys.argv[1:])
