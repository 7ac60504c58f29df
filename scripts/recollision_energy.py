#!/usr/bin/python3
"""The impurity's energy loss per first collision and per recollision in time windows, with
block-jackknife errors, from MD run directories that recorded C_imp, C_re, dE_first and dE_re
(docs/verification.md, "Recollisions in the MD"). Usage:

    scripts/recollision_energy.py data/recollisions/unit data/recollisions/heavy data/recollisions/large
"""
import csv
import io
import sys

import numpy as np

WINDOWS = [(0.0, 62.5), (62.5, 1000.0), (1000.0, 4000.0)]


def block_sums(directory):
    """{block: {(t, observable): sum}} from blocks.csv."""
    rows = [r for r in open(f"{directory}/blocks.csv") if not r.startswith("#")]
    sums = {}
    for r in csv.DictReader(io.StringIO("".join(rows))):
        sums.setdefault(int(r["block"]), {})[(float(r["t"]), r["observable"])] = float(r["sum"])
    return sums


def window_sums(block, t1, t2):
    """Energy lost and collisions counted in (t1, t2]: first collisions, then recollisions."""
    def at(t, name):
        return 0.0 if t == 0 else block[(t, name)]
    def change(name):
        return at(t2, name) - at(t1, name)
    return np.array([change("dE_first"), change("C_imp") - change("C_re"), change("dE_re"), change("C_re")])


def per_collision(x):
    first, re = x[0] / x[1], x[2] / x[3]
    return np.array([first, re, re / first])


def main(directories):
    for directory in directories:
        sums = block_sums(directory)
        times = sorted({t for block in sums.values() for (t, _) in block})
        print(directory)
        for t1, t2 in WINDOWS:
            t1 = 0.0 if t1 == 0 else min(times, key=lambda t: abs(t - t1))
            t2 = min(times, key=lambda t: abs(t - t2))
            parts = {b: window_sums(block, t1, t2) for b, block in sums.items()}
            total = sum(parts.values())
            value = per_collision(total)
            jackknife = np.array([per_collision(total - part) for part in parts.values()])
            n = len(parts)
            error = np.sqrt((n - 1) / n * ((jackknife - jackknife.mean(axis=0)) ** 2).sum(axis=0))
            print(f"  t in ({t1:g}, {t2:g}]: energy lost per first collision {value[0]:.4g} ± {error[0]:.2g}, "
                  f"per recollision {value[1]:.4g} ± {error[1]:.2g}, ratio {value[2]:.3f} ± {error[2]:.3f}")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(sys.argv[1:])
