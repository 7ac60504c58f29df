#!/usr/bin/env python3
"""The blast's centre from an MD run's profile bins, against the Navier-Stokes blast.

At large R/lambda the run's n0 and T0 observables are measured in a ball that held 100 particles at
t = 0 (md/observers.cpp): at R/lambda = 307 the core's density is 0.09 n, so the ball holds about 9
particles and the estimate is noise. The innermost profile bins (r < 0.05 R: some 460 particles per
realization there) measure the same centre. This prints, for the first BINS bins at time T, the
MD's n/n_inf and T/Rdot^2 (Rdot = 2R/((d+2)t), Eq. (1)) with delete-one-block jackknife errors
(accumulators.csv: per-block sums), beside the NS's values averaged over the same shells (density:
by volume; temperature: by particle number, as the MD pools its particles' kinetic energy).

usage: central_bin.py RUN_DIR CONTINUUM_DAT [--t T] [--bins B]
  CONTINUUM_DAT: a compare report's figures/profiles_continuum.dat (its last index: the dense NS at
  the MD's R/lambda; columns r/R, n/n_inf, u/Rdot, T/Rdot^2).
"""
import argparse
import json
import pathlib

import numpy as np
import pandas as pd


def block_sums(run, t):
    acc = pd.read_csv(run / "accumulators.csv", comment="#")
    totals = pd.read_csv(run / "block_totals.csv", comment="#").set_index("block")["count"]
    at = acc[np.isclose(acc.t, t, rtol=1e-12)]
    return at, totals


def jackknife(values_fn, blocks):
    full = values_fn(None)
    leave = np.array([values_fn(b) for b in blocks])
    m = len(blocks)
    return full, np.sqrt((m - 1) / m * ((leave - leave.mean(axis=0)) ** 2).sum(axis=0))


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("run", type=pathlib.Path)
    p.add_argument("continuum", type=pathlib.Path)
    p.add_argument("--t", type=float, default=None)
    p.add_argument("--bins", type=int, default=2)
    o = p.parse_args()
    summary = json.loads((o.run / "summary.json").read_text())
    d = summary["scene"]["d"]
    profiles = pd.read_csv(o.run / "profiles.csv", comment="#")
    t = o.t if o.t is not None else profiles.t.max()
    at, totals = block_sums(o.run, t)
    blocks = sorted(totals.index)
    width = profiles.r_over_R_hi.iloc[0] - profiles.r_over_R_lo.iloc[0]

    def channel(name, b):
        rows = at[(at.channel == name) & (at.bin == b)] if name.startswith("profile") else at[at.channel == name]
        return rows.set_index("block")["sum"]

    def estimate(drop):
        keep = [b for b in blocks if b != drop]
        N = totals.loc[keep].sum()
        R = channel("R", 0).loc[keep].sum() / N
        rdot = 2.0 * R / ((d + 2) * t)
        out = []
        for b in range(o.bins):
            count = channel("profile_count", b).loc[keep].sum()
            u = channel("profile_radial_velocity_sum", b).loc[keep].sum() / count
            T = (channel("profile_mv2_sum", b).loc[keep].sum() / count - u * u) / d
            out += [channel("profile_density", b).loc[keep].sum() / N, T / rdot**2]  # density: already n/n_inf
        return np.array(out)

    value, error = jackknife(estimate, blocks)
    text = o.continuum.read_text().strip().split("\n\n\n")
    ns = np.array([[float(x) for x in line.split()] for line in text[-1].splitlines() if line.strip()])
    r, n_ns, T_ns = ns[:, 0], ns[:, 1], ns[:, 3]
    print(f"t = {t:g}, {len(blocks)} blocks; bins of width {width:g} R")
    print("r/R range  | MD n/n_inf        | NS n/n_inf | MD T/Rdot^2     | NS T/Rdot^2 | MD/NS-1 (T)")
    for b in range(o.bins):
        inside = (r >= b * width) & (r < (b + 1) * width)
        shell = r[inside] ** (d - 1)
        n_avg = (n_ns[inside] * shell).sum() / shell.sum()
        T_avg = (T_ns[inside] * n_ns[inside] * shell).sum() / (n_ns[inside] * shell).sum()
        n, dn, T, dT = value[2 * b], error[2 * b], value[2 * b + 1], error[2 * b + 1]
        print(f"{b * width:.2f}-{(b + 1) * width:.2f}  | {n:.4f} ± {dn:.4f}  | {n_avg:.4f}     | "
              f"{T:.3f} ± {dT:.3f}  | {T_avg:.4f}      | {T / T_avg - 1:+.1%} ± {dT / T_avg:.1%}")


if __name__ == "__main__":
    main()
