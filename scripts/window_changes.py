#!/usr/bin/python3
"""When a run's impurity changes: in each time window (t1, t2], the factor by which V_imp falls,
V_imp(t2)/V_imp(t1), and the collisions made, C_imp(t2) - C_imp(t1), with block-jackknife errors,
for MD and tracer run directories alike (blocks.csv with V_imp and C_imp). Two runs that agree in
every late window but not in an early one made their difference early (docs/verification.md,
"Recollisions switched off"). Usage:

    scripts/window_changes.py tracer-heavy data/recollisions/heavy md-heavy-no-recollisions
"""
import csv
import io
import sys

import numpy as np

WINDOWS = [(15.625, 62.5), (62.5, 250.0), (250.0, 1000.0), (1000.0, 4000.0)]


def block_sums(directory):
    """({block: {(t, observable): sum}}, {block: count}) from blocks.csv."""
    rows = [r for r in open(f"{directory}/blocks.csv") if not r.startswith("#")]
    sums, counts = {}, {}
    for r in csv.DictReader(io.StringIO("".join(rows))):
        sums.setdefault(int(r["block"]), {})[(float(r["t"]), r["observable"])] = float(r["sum"])
        counts[int(r["block"])] = float(r["count"])
    return sums, counts


def window_values(sums, counts, t1, t2):
    """[V_imp(t2)/V_imp(t1), C_imp(t2) - C_imp(t1)] of the blocks summed in `sums` (V_imp = √ of
    the mean of its inner value, Eq. (38); the counts cancel in the ratio)."""
    return np.array([np.sqrt(sums[(t2, "V_imp")] / sums[(t1, "V_imp")]),
                     (sums[(t2, "C_imp")] - sums[(t1, "C_imp")]) / counts])


def windows(directory):
    """[(t1, t2, value, error)] for the recorded times nearest each of WINDOWS; value and error are
    arrays [V ratio, C increment] (block jackknife)."""
    sums, counts = block_sums(directory)
    times = sorted({t for block in sums.values() for (t, _) in block})
    keys = list(sums)
    result = []
    for w1, w2 in WINDOWS:
        t1 = min(times, key=lambda t: abs(t - w1))
        t2 = min(times, key=lambda t: abs(t - w2))
        if t1 >= t2:
            continue
        names = [(t1, "V_imp"), (t2, "V_imp"), (t1, "C_imp"), (t2, "C_imp")]
        total = {k: sum(sums[b][k] for b in keys) for k in names}
        count = sum(counts.values())
        value = window_values(total, count, t1, t2)
        jackknife = np.array([window_values({k: total[k] - sums[b][k] for k in names}, count - counts[b], t1, t2)
                              for b in keys])
        n = len(keys)
        error = np.sqrt((n - 1) / n * ((jackknife - jackknife.mean(axis=0)) ** 2).sum(axis=0))
        result.append((t1, t2, value, error))
    return result


def main(directories):
    for directory in directories:
        print(directory)
        for t1, t2, value, error in windows(directory):
            print(f"  t in ({t1:g}, {t2:g}]: V_imp(t2)/V_imp(t1) = {value[0]:.4f} ± {error[0]:.4f}, "
                  f"collisions {value[1]:.3f} ± {error[1]:.3f}")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(sys.argv[1:])
