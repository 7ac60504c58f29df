#!/usr/bin/python3
"""The impurity's bow: against t, the ratio of the host densities ahead of and behind the impurity
in its contact shell (g_front/g_back, 1 for Eq. (36)'s undisturbed gas), and the drift of the hosts
ahead along its direction over its rms speed (u_front / (sqrt(2) V_imp)), with block-jackknife
bands, for MD runs that recorded V_imp, g_front, g_back and u_front (docs/verification.md,
"Recollisions switched off"). Draws with matplotlib (Debian's python3-matplotlib). Usage:

    scripts/bow_figure.py bow.png data/recollisions/heavy-shells data/recollisions/unit-shells data/recollisions/large-shells
"""
import sys

import numpy as np

from block_jackknife import time_series

NAMES = ["g_front", "g_back", "u_front", "V_imp"]


def values(x, count):
    """[g_front/g_back, u_front/(sqrt(2) V_imp)] per time from summed inner values x[time, NAMES]
    over `count` realizations (V_imp's inner value is |v|^2/2, Eq. (38))."""
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.stack([x[:, 0] / x[:, 1], (x[:, 2] / count) / np.sqrt(2.0 * x[:, 3] / count)])


def bow(directory):
    """t, values (2 x times) and their block-jackknife errors."""
    return time_series(directory, NAMES, values)


def draw(path, directories):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2), constrained_layout=True)
    for directory in directories:
        t, value, error = bow(directory)
        label = directory.rstrip("/").split("/")[-1].removesuffix("-shells")
        keep = t >= 10.0
        for axis, row in ((left, 0), (right, 1)):
            line, = axis.plot(t[keep], value[row][keep], "o-", ms=3, label=label)
            axis.fill_between(t[keep], (value[row] - error[row])[keep], (value[row] + error[row])[keep],
                              color=line.get_color(), alpha=0.3)
    left.axhline(1.0, color="k", lw=0.8)
    left.set(xscale="log", xlabel="t", ylabel="g_front / g_back",
             title="host density ahead / behind (Eq. (36): 1)")
    right.axhline(0.0, color="k", lw=0.8)
    right.set(xscale="log", xlabel="t", ylabel="u_front / (sqrt(2) V_imp)",
              title="hosts ahead: drift / impurity's rms speed")
    for axis in (left, right):
        axis.grid(alpha=0.3)
        axis.legend(title="impurity")
    fig.suptitle("The impurity's bow, MD of the paper's 2D scene, contact shell (1 sigma bands, block jackknife)")
    fig.savefig(path, dpi=120)


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    draw(sys.argv[1], sys.argv[2:])
    for directory in sys.argv[2:]:
        t, value, error = bow(directory)
        print(directory)
        for k in range(len(t)):
            if t[k] in (62.5, 250.0, 500.0, 1000.0, 4000.0):
                print(f"  t = {t[k]:g}: ahead/behind {value[0][k]:.3f} ± {error[0][k]:.3f}, "
                      f"drift/speed {value[1][k]:.3f} ± {error[1][k]:.3f}")
