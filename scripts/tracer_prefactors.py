#!/usr/bin/env python3
"""Prefactors of a `coldblast tracer` run at chosen R/lambda (its prefactors.csv, docs/kinetic.md).

usage: scripts/tracer_prefactors.py RUN_DIR [R_OVER_LAMBDA ...] [--cxx SOURCE_INDEX]

For each target R/lambda (default 1e2 ... 1e6 and the scene's t_max) the recording time nearest in
ln(R/lambda) is printed: R/lambda, then per observable the prefactor ± stderr and the running
exponent in R/lambda ± stderr. With --cxx the rows are printed as theory/computed_prefactors.cpp
entries (d from summary.json).
"""
import csv
import json
import math
import os
import sys


def rows(run):
    with open(os.path.join(run, "prefactors.csv")) as f:
        return [r for r in csv.DictReader(line for line in f if not line.startswith("#"))]


def main(argv):
    cxx = None
    if "--cxx" in argv:
        i = argv.index("--cxx")
        cxx = int(argv[i + 1])
        argv = argv[:i] + argv[i + 2:]
    run = argv[1]
    table = [r for r in rows(run) if r["R_imp_prefactor"] != "nan"]
    targets = [float(x) for x in argv[2:]] or [float(table[-1]["R_over_lambda"])] + [10.0 ** k for k in range(2, 7)]
    d = json.load(open(os.path.join(run, "summary.json")))["scene"]["d"]
    names = ["R_imp", "V_imp", "C_imp"]
    seen = set()
    for target in sorted(targets):
        r = min(table, key=lambda r: abs(math.log(float(r["R_over_lambda"]) / target)))
        if abs(math.log(float(r["R_over_lambda"]) / target)) > 0.2 or r["t"] in seen:
            continue
        seen.add(r["t"])
        if cxx is not None:
            for n in names:
                print(f'    {{{d}, "{n}", {r["t"]}, {float(r["R_over_lambda"]):.6g}, '
                      f'{float(r[n + "_prefactor"]):.6g}, {float(r[n + "_prefactor_stderr"]):.3g}, {cxx}}},')
            continue
        cells = [f'{float(r["R_over_lambda"]):10.4g}']
        for n in names:
            cells.append(f'{n} {float(r[n + "_prefactor"]):.5g} ± {float(r[n + "_prefactor_stderr"]):.2g}'
                         f' (exp {float(r[n + "_exponent"]):.4f} ± {float(r[n + "_exponent_stderr"]):.4f})')
        print("  ".join(cells))


if __name__ == "__main__":
    main(sys.argv)
