#!/usr/bin/python3
"""The impurity's braking split into how often it collides and what each collision takes: in each
time window (t1, t2], per impurity, the first collisions (with a partner not hit before), the
recollisions, the kinetic energy lost, and the energy lost per first collision, with block-jackknife
errors. MD runs that recorded C_imp, C_re, dE_first and dE_re give all of them; tracer runs (Eq. (36):
every partner fresh) and MD runs without C_re count every collision as a first one and take the
energy lost from V_imp: M (V_imp(t1)² − V_imp(t2)²), V_imp² being the mean of |v|²/2 (Eq. (38)).
Usage (docs/verification.md, "Recollisions switched off"):

    scripts/energy_budget.py [--windows 250,500,1000,2000,4000] RUN_DIR...
"""
import json
import sys

import numpy as np

from block_jackknife import block_sums, jackknife

DEFAULT_WINDOWS = [250.0, 500.0, 1000.0, 2000.0, 4000.0]


def impurity_mass(directory):
    with open(f"{directory}/summary.json") as f:
        return float(json.load(f)["scene"]["impurities"]["mass"])


def window_sums(block, t1, t2, mass):
    """[first collisions, recollisions, energy lost] summed over a block's impurities in (t1, t2]."""
    def change(name):
        return block[(t2, name)] - block[(t1, name)]
    collisions = change("C_imp")
    if (t2, "dE_first") in block:
        recollisions = change("C_re")
        lost = change("dE_first") + change("dE_re")
        return np.array([collisions - recollisions, recollisions, lost, change("dE_first")])
    lost = mass * (block[(t1, "V_imp")] - block[(t2, "V_imp")])
    return np.array([collisions, 0.0, lost, lost])


def per_impurity(x, count):
    """first collisions, recollisions, energy lost (per impurity), energy lost per first collision."""
    return np.array([x[0] / count, x[1] / count, x[2] / count, x[3] / x[0]])


def budget(directory, windows):
    """[(t1, t2, value, error)] with value, error = per_impurity arrays (block jackknife)."""
    sums, counts = block_sums(directory)
    mass = impurity_mass(directory)
    times = sorted({t for block in sums.values() for (t, _) in block})
    edges = [min(times, key=lambda t: abs(t - w)) for w in windows]
    result = []
    for t1, t2 in zip(edges, edges[1:]):
        if t1 >= t2:
            continue
        parts = [window_sums(block, t1, t2, mass) for block in sums.values()]
        value, error = jackknife(parts, [counts[b] for b in sums], per_impurity)
        result.append((t1, t2, value, error))
    return result


def main(arguments):
    windows = DEFAULT_WINDOWS
    if arguments[:1] == ["--windows"]:
        if len(arguments) < 2:
            sys.exit("--windows needs a comma-separated list of times\n" + __doc__)
        windows = [float(w) for w in arguments[1].split(",")]
        arguments = arguments[2:]
    if not arguments:
        sys.exit(__doc__)
    for directory in arguments:
        print(directory)
        for t1, t2, v, e in budget(directory, windows):
            print(f"  t in ({t1:g}, {t2:g}]: first collisions {v[0]:.3f} ± {e[0]:.3f}, recollisions {v[1]:.3f} ± "
                  f"{e[1]:.3f}, energy lost {v[2]:.4g} ± {e[2]:.2g}, per first collision {v[3]:.4g} ± {e[3]:.2g}")


if __name__ == "__main__":
    main(sys.argv[1:])
