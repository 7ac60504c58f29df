"""What the analysis scripts share: a run directory's block sums (blocks.csv of `md run` and
`coldblast tracer`) and the delete-one-block jackknife of a statistic of them (docs/compare.md)."""
import csv
import io

import numpy as np


def block_sums(directory, names=None):
    """({block: {(t, observable): sum}}, {block: count}) from blocks.csv, for the observables in
    `names` (all when None)."""
    rows = [r for r in open(f"{directory}/blocks.csv") if not r.startswith("#")]
    sums, counts = {}, {}
    for r in csv.DictReader(io.StringIO("".join(rows))):
        if names is None or r["observable"] in names:
            sums.setdefault(int(r["block"]), {})[(float(r["t"]), r["observable"])] = float(r["sum"])
            counts[int(r["block"])] = float(r["count"])
    return sums, counts


def jackknife(parts, counts, statistic):
    """statistic(total, count) over all blocks and its delete-one-block jackknife error; `parts`
    holds one array of sums per block, `counts` its realizations."""
    total, count = sum(parts), sum(counts)
    value = statistic(total, count)
    leave_one_out = np.array([statistic(total - part, count - c) for part, c in zip(parts, counts)])
    n = len(parts)
    error = np.sqrt((n - 1) / n * ((leave_one_out - leave_one_out.mean(axis=0)) ** 2).sum(axis=0))
    return value, error


def time_series(directory, names, statistic):
    """t, statistic and its jackknife error at every recorded time: statistic(x, count) gets the
    summed inner values x[time, name] of `names` over `count` realizations."""
    sums, counts = block_sums(directory, names)
    times = sorted({t for block in sums.values() for (t, _) in block})
    parts = [np.array([[sums[b][(t, name)] for name in names] for t in times]) for b in sums]
    value, error = jackknife(parts, [counts[b] for b in sums], statistic)
    return np.array(times), value, error
