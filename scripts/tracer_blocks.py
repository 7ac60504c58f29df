#!/usr/bin/env python3
"""Block-jackknife statistics of `coldblast tracer` (or `md run`) run directories from blocks.csv.

usage:
  scripts/tracer_blocks.py starts THERMAL KICK      two starts compared at every recording time
                                                      t >= t_max/10 (docs/verification.md)
  scripts/tracer_blocks.py diffusion RUN T1          tracer diffusion coefficient from R_imp

starts: THERMAL started later (at its summary.json's start_time t_s) than KICK. Per time, THERMAL/KICK - 1
for R_imp, V_imp, C_imp and C_imp since t_s (KICK's collisions after t_s, per realization, against
THERMAL's, which start at t_s), with the combined standard error and the deviation in sigma; then per
observable the largest |deviation|/sigma over t >= t_max/10. t_s must be a recording time of KICK.

diffusion: D = (<|r(t2)|^2> - <|r(t1)|^2>) / (2 d (t2 - t1)) with t1 the recording time nearest T1 and
t2 = 2 t1 (the difference removes the ballistic offset; R_imp's inner value is |r|^2/2,
docs/md-output.md), block-jackknife standard error. Standard library only.
"""
import csv
import json
import math
import os
import sys


def read_blocks(run):
    """{(t, observable): {block: (sum, count)}} of RUN/blocks.csv."""
    table = {}
    with open(os.path.join(run, "blocks.csv")) as f:
        for r in csv.DictReader(line for line in f if not line.startswith("#")):
            key = (float(r["t"]), r["observable"])
            table.setdefault(key, {})[int(r["block"])] = (float(r["sum"]), int(r["count"]))
    return table


def jackknife(blocks, f):
    """f(mean) of the summed blocks and its delete-one-block jackknife standard error.
    blocks: {block: [(sum, count), ...]} (one pair per series f reads), f(list of means)."""
    ids = sorted(blocks)
    k = len(blocks[ids[0]])
    total = [(sum(blocks[b][j][0] for b in ids), sum(blocks[b][j][1] for b in ids)) for j in range(k)]
    value = f([s / c for s, c in total])
    leave = []
    for b in ids:
        leave.append(f([(total[j][0] - blocks[b][j][0]) / (total[j][1] - blocks[b][j][1]) for j in range(k)]))
    m = sum(leave) / len(leave)
    error = math.sqrt((len(ids) - 1) / len(ids) * sum((x - m) ** 2 for x in leave))
    return value, error


def series(table, *keys):
    """Blocks holding every key, as {block: [(sum, count) per key]}."""
    common = set.intersection(*(set(table[k]) for k in keys))
    return {b: [table[k][b] for k in keys] for b in common}


def nearest(times, t):
    return min(times, key=lambda x: abs(math.log(x / t)))


def starts(thermal, kick):
    a, b = read_blocks(thermal), read_blocks(kick)
    t_s = json.load(open(os.path.join(thermal, "summary.json")))["start_time"]
    t_max = json.load(open(os.path.join(kick, "summary.json")))["scene"]["t_max"]
    kick_times = sorted({t for t, o in b if o == "C_imp"})
    t_start = nearest(kick_times, t_s)
    if abs(t_start / t_s - 1) > 1e-9:
        sys.exit(f"start time {t_s} of {thermal} is not a recording time of {kick}")
    times = [t for t in kick_times if t >= t_max / 10 and (t, "C_imp") in a]
    root, first = (lambda m: math.sqrt(m[0])), (lambda m: m[0])
    columns = [  # name, THERMAL's series and function, KICK's series and function
        ("R_imp", lambda t: [(t, "R_imp")], root, lambda t: [(t, "R_imp")], root),
        ("V_imp", lambda t: [(t, "V_imp")], root, lambda t: [(t, "V_imp")], root),
        ("C_imp", lambda t: [(t, "C_imp")], first, lambda t: [(t, "C_imp")], first),
        ("C_imp since t_s", lambda t: [(t, "C_imp")], first, lambda t: [(t, "C_imp"), (t_start, "C_imp")],
         lambda m: m[0] - m[1]),
    ]
    print(f"thermal start at t_s = {t_s:g}, kick at its t_min; {len(times)} times t >= t_max/10 = {t_max / 10:g}")
    print("t          " + "  ".join(f"{c[0] + ' thermal/kick-1':>30}" for c in columns))
    worst = {c[0]: (0.0, None) for c in columns}
    for t in times:
        cells = []
        for name, a_keys, a_f, b_keys, b_f in columns:
            x, dx = jackknife(series(a, *a_keys(t)), a_f)
            y, dy = jackknife(series(b, *b_keys(t)), b_f)
            ratio = x / y - 1
            error = (x / y) * math.hypot(dx / x, dy / y)
            z = ratio / error
            if abs(z) >= abs(worst[name][0]):
                worst[name] = (z, t)
            cells.append(f"{ratio:+10.5f} ± {error:.5f} ({z:+5.1f}σ)".rjust(30))
        print(f"{t:<10.4g} " + "  ".join(cells))
    for name, (z, t) in worst.items():
        print(f"{name}: largest |deviation| {abs(z):.1f}σ (at t = {t:.4g})")


def diffusion(run, t1_target):
    table = read_blocks(run)
    summary = json.load(open(os.path.join(run, "summary.json")))
    d = summary["scene"]["d"]
    times = sorted({t for t, o in table if o == "R_imp"})
    t1 = nearest(times, t1_target)
    t2 = nearest(times, 2 * t1)
    if abs(t2 / (2 * t1) - 1) > 1e-9:
        sys.exit(f"2 t1 = {2 * t1} is not a recording time")
    D, error = jackknife(series(table, (t2, "R_imp"), (t1, "R_imp")), lambda m: (m[0] - m[1]) / (d * (t2 - t1)))
    print(f"t1 = {t1:.6g}, t2 = {t2:.6g}: D = {D:.6g} ± {error:.2g} "
          f"({summary['realizations']} trajectories, {len(series(table, (t1, 'R_imp')))} blocks)")


def main(argv):
    if len(argv) == 4 and argv[1] == "starts":
        starts(argv[2], argv[3])
    elif len(argv) == 4 and argv[1] == "diffusion":
        diffusion(argv[2], float(argv[3]))
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main(sys.argv)
