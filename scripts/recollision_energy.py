#!/usr/bin/python3
"""The impurity's energy loss per first collision and per recollision in time windows, with
block-jackknife errors, from MD run directories that recorded C_imp, C_re, dE_first and dE_re
(docs/verification.md, "Recollisions in the MD"). With --figure FILE it also draws, against t, the
share of the collisions that are recollisions and the share of the impurity's energy loss they
carry (matplotlib, Debian's python3-matplotlib). Usage:

    scripts/recollision_energy.py data/recollisions/unit data/recollisions/heavy data/recollisions/large
    scripts/recollision_energy.py --figure recollisions.png data/recollisions/*
"""
import sys

import numpy as np

from block_jackknife import block_sums, jackknife, time_series

WINDOWS = [(0.0, 62.5), (62.5, 1000.0), (1000.0, 4000.0)]


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


def shares(directory):
    """t, C_re/C_imp and dE_re/(dE_first + dE_re) at every recorded time, each with its block-jackknife error."""
    def ratios(x, count):
        return np.stack([x[:, 0] / x[:, 1], x[:, 2] / (x[:, 2] + x[:, 3])])

    return time_series(directory, ["C_re", "C_imp", "dE_re", "dE_first"], ratios)


def draw(directories, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4), constrained_layout=True)
    for directory in directories:
        t, value, error = shares(directory)
        label = directory.rstrip("/").split("/")[-1]
        for axis, row in ((left, 0), (right, 1)):
            line, = axis.plot(t, value[row], "o-", ms=3, label=label)
            axis.fill_between(t, value[row] - error[row], value[row] + error[row], color=line.get_color(), alpha=0.3)
    left.set(xscale="log", xlabel="t", ylabel="C_re / C_imp", title="recollisions among the impurity's collisions")
    right.set(xscale="log", xlabel="t", ylabel="dE_re / (dE_first + dE_re)",
              title="share of the energy loss in recollisions")
    for axis in (left, right):
        axis.axhline(0, color="k", lw=0.5)
        axis.grid(alpha=0.3)
        axis.legend(title="impurity")
    fig.suptitle("MD of the paper's 2D scene (bands: 1 sigma, block jackknife); Eq. (36) has no recollisions: 0 in both")
    fig.savefig(path, dpi=120)


def main(directories):
    for directory in directories:
        sums, counts = block_sums(directory)
        times = sorted({t for block in sums.values() for (t, _) in block})
        print(directory)
        for t1, t2 in WINDOWS:
            t1 = 0.0 if t1 == 0 else min(times, key=lambda t: abs(t - t1))
            t2 = min(times, key=lambda t: abs(t - t2))
            parts = [window_sums(block, t1, t2) for block in sums.values()]
            value, error = jackknife(parts, list(counts.values()), lambda x, count: per_collision(x))
            print(f"  t in ({t1:g}, {t2:g}]: energy lost per first collision {value[0]:.4g} ± {error[0]:.2g}, "
                  f"per recollision {value[1]:.4g} ± {error[1]:.2g}, ratio {value[2]:.3f} ± {error[2]:.3f}")


if __name__ == "__main__":
    arguments = sys.argv[1:]
    figure = None
    if arguments[:1] == ["--figure"]:
        if len(arguments) < 2:
            sys.exit("--figure needs a file name\n" + __doc__)
        figure, arguments = arguments[1], arguments[2:]
    if not arguments:
        sys.exit(__doc__)
    main(arguments)
    if figure:
        draw(arguments, figure)
