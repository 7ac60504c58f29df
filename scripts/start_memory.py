#!/usr/bin/python3
"""The start's memory in the MD: two runs of one scene that differ only in how E enters (a kick
and a hot spot, `[start]`, docs/md-output.md "Starts"), compared at equal R/λ.

Usage: scripts/start_memory.py KICK_DIR HOT_DIR [--out CSV] [--power-json JSON] [--ns NS_SS NS_HOT]

Both runs must have the same scene apart from [start], the same seed and block size, and hold
accumulators.csv (every channel per block, docs/md-output.md). At x = R/λ = 10 · 2^(k/4) up to the
largest x both runs reach, each run's amplitudes are read by linear interpolation in ln X against
ln x between recording times:
  n0/n, T0/Rdot^2 (Rdot = 2R/((d+2)t) from the run's own R and t), T0 (units E/(n λ^d): no time
  origin in it), H/R (compare's rule: the r/R at which the binned density first reaches twice its
  innermost bin, linear between bin centres; docs/compare.md), t (the time at which the blast
  reaches x: the time origin's memory), R_imp, V_imp (Eq. (38)'s square roots), C_imp, and p_imp's
  moment ratio <r^4>/<r^2>^2 (histogram moments with bin centres, as compare/figures.cpp).
The difference is hot/kick - 1 (ratio: hot - kick), with the paired delete-one-block jackknife
(block b left out of both runs at once: the two runs share seeds, so their blocks pair; it is
valid whether or not they are correlated). The decay: for each difference significant (> 2σ) at
three or more x, the least-squares slope of ln|Δ| against ln x over those x, jackknifed the same way.
"""
import argparse
import csv
import io
import json
import math
import sys

import numpy as np

sys.path.insert(0, __import__("os").path.dirname(__file__))
from block_jackknife import jackknife  # noqa: E402

SCALARS = ["R_imp", "V_imp", "C_imp", "n0", "T0", "R"]
NAMES = ["n0/n", "T0/Rdot^2", "T0", "H/R", "t", "R_imp", "V_imp", "C_imp", "p_imp_ratio"]


def header_value(path, key):
    for line in open(path):
        if not line.startswith("#"):
            break
        if line.startswith(f"# {key}:"):
            return line.split(":", 1)[1].strip()
    raise SystemExit(f"{path}: no '# {key}:' header line")


def scene_values(directory):
    summary = json.load(open(f"{directory}/summary.json"))
    scene = summary["scene"]
    return summary, scene


def read_accumulators(directory):
    """(times, {block: array[channel_index]}, {block: count}, channel keys) from accumulators.csv."""
    rows = [r for r in open(f"{directory}/accumulators.csv") if not r.startswith("#")]
    table = list(csv.DictReader(io.StringIO("".join(rows))))
    keys = sorted({(r["channel"], float(r["t"]), int(r["bin"])) for r in table})
    index = {k: i for i, k in enumerate(keys)}
    parts = {}
    for r in table:
        b = int(r["block"])
        parts.setdefault(b, np.zeros(len(keys)))[index[(r["channel"], float(r["t"]), int(r["bin"]))]] = float(r["sum"])
    counts = {}
    for r in open(f"{directory}/block_totals.csv"):
        if r.startswith("#") or r.startswith("block"):
            continue
        block, count = r.split(",")[:2]
        counts[int(block)] = float(count)
    times = sorted({k[1] for k in keys})
    return times, parts, counts, keys


def core_size(density):
    """compare's binned_core_size: r/R where the density first reaches twice its innermost bin."""
    centre = 0.025 + 0.05 * np.arange(len(density))
    if not density[0] > 0:
        return math.nan
    for i in range(1, len(density)):
        if density[i] >= 2.0 * density[0]:
            n_a = density[0] if i == 1 else density[i - 1]
            return centre[i - 1] + (2.0 * density[0] - n_a) / (density[i] - n_a) * (centre[i] - centre[i - 1])
    return math.nan


class Run:
    def __init__(self, directory):
        self.summary, self.scene = scene_values(directory)
        self.d, self.n, self.E = self.scene["d"], self.scene["n"], self.scene["E"]
        self.lam = self.summary["lambda"]  # Eq. (5)
        self.commit = header_value(f"{directory}/observables.csv", "commit")
        self.times, self.parts, self.counts, self.keys = read_accumulators(directory)
        self.index = {k: i for i, k in enumerate(self.keys)}
        self.size = len(self.keys)

    def series(self, total, count):
        """Per recorded time: x = R/λ and every amplitude of NAMES (rows: times)."""
        mean = total / count
        get = lambda name, t, b=0: mean[self.index[(name, t, b)]]  # noqa: E731
        out = []
        for t in self.times:
            R = get("R", t)
            rdot = 2.0 * R / ((self.d + 2) * t)
            density = np.array([get("profile_density", t, b) for b in range(30)])
            p = np.array([get("p_imp_fraction", t, b) for b in range(60)])
            r = np.arange(60) + 0.5  # bin centres in units of the bin width (the ratio is scale free)
            m0, m2, m4 = p.sum(), (p * r**2).sum(), (p * r**4).sum()
            T0 = get("T0", t)
            out.append([R / self.lam, get("n0", t) / self.n, T0 / rdot**2, T0 * self.n * self.lam**self.d / self.E,
                        core_size(density), t, math.sqrt(get("R_imp", t)), math.sqrt(get("V_imp", t)), get("C_imp", t),
                        m4 * m0 / m2**2])
        return np.array(out)

    def at(self, total, count, xs):
        s = self.series(total, count)
        lx = np.log(s[:, 0])
        values = []
        for j in range(1, s.shape[1]):
            y = s[:, j]
            ok = np.isfinite(y) & (y > 0)
            values.append(np.exp(np.interp(np.log(xs), lx[ok], np.log(y[ok]), left=np.nan, right=np.nan)))
        return np.array(values)  # [name, x]


def ns_delta(self_similar, hotspot, xs):
    """{amplitude: {x: hot/self-similar - 1}} of two `hydro core` runs' samples.csv (NS's own n0, T0, H
    and t; T0/Rdot^2 from T0 and t at equal R; p_imp has no NS counterpart)."""
    def read(directory):
        rows = [r for r in open(f"{directory}/samples.csv") if not r.startswith("#")]
        table = list(csv.DictReader(io.StringIO("".join(rows))))
        return {k: np.array([float(r[k]) for r in table]) for k in ("R_over_lambda", "n0", "T0", "H", "t")}

    a, b = read(self_similar), read(hotspot)
    at = lambda s, k: np.exp(np.interp(np.log(xs), np.log(s["R_over_lambda"]), np.log(s[k])))  # noqa: E731
    delta = {k: at(b, k) / at(a, k) - 1.0 for k in ("n0", "T0", "H", "t")}
    delta["T0/Rdot^2"] = (1 + delta["T0"]) * (1 + delta["t"]) ** 2 - 1  # Rdot = 2R/((d+2)t) at equal R
    names = {"n0/n": "n0", "T0": "T0", "H/R": "H", "t": "t", "T0/Rdot^2": "T0/Rdot^2"}
    return {name: {f"{x:.4f}": f"{delta[k][i]:.2g}" for i, x in enumerate(xs)} for name, k in names.items()}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("kick")
    parser.add_argument("hot")
    parser.add_argument("--out", default="start_memory.csv")
    parser.add_argument("--power-json", default="start_memory_power.json")
    parser.add_argument("--x-min", type=float, default=10.0)
    parser.add_argument("--ns", nargs=2, metavar=("NS_SELF_SIMILAR", "NS_HOTSPOT"),
                        help="two `hydro core --out` folders: their hot/self-similar - 1 of n0, T0, H, t at the same x")
    args = parser.parse_args()
    kick, hot = Run(args.kick), Run(args.hot)
    for key in ("d", "n", "a", "E", "seed", "block_size", "realizations", "t_max"):
        if kick.scene[key] != hot.scene[key]:
            raise SystemExit(f"the runs differ in {key}: {kick.scene[key]} and {hot.scene[key]}")
    blocks = sorted(kick.parts)
    if blocks != sorted(hot.parts) or any(kick.counts[b] != hot.counts[b] for b in blocks):
        raise SystemExit("the runs' blocks do not pair")
    # x grid: 10 · 2^(k/4) up to the largest x both reach (full sample).
    last = min(kick.series(sum(kick.parts.values()), sum(kick.counts.values()))[-1, 0],
               hot.series(sum(hot.parts.values()), sum(hot.counts.values()))[-1, 0])
    # The last point sits just inside the largest x (0.995 of it), so that every jackknife sample reaches it.
    xs = np.array([args.x_min * 2 ** (k / 4) for k in range(64) if args.x_min * 2 ** (k / 4) <= 0.995 * last])
    xs = np.append(xs, 0.995 * last) if xs[-1] < 0.97 * last else xs
    parts = [np.concatenate([kick.parts[b], hot.parts[b]]) for b in blocks]
    counts = [kick.counts[b] for b in blocks]
    m = kick.size

    def both(total, count):
        a, b = kick.at(total[:m], count, xs), hot.at(total[m:], count, xs)
        delta = b / a - 1.0
        delta[-1] = b[-1] - a[-1]  # the moment ratio: a difference
        return np.stack([a, b, delta])  # [which, name, x]

    value, error = jackknife(parts, counts, both)
    rows = []
    for j, name in enumerate(NAMES):
        for i, x in enumerate(xs):
            rows.append({"R_over_lambda": f"{x:.4f}", "amplitude": name,
                         "kick": f"{value[0, j, i]:.6g}", "kick_err": f"{error[0, j, i]:.2g}",
                         "hotspot": f"{value[1, j, i]:.6g}", "hotspot_err": f"{error[1, j, i]:.2g}",
                         "delta": f"{value[2, j, i]:.5g}", "delta_err": f"{error[2, j, i]:.2g}",
                         "delta_over_err": f"{value[2, j, i] / error[2, j, i]:.2f}"})
    # Decay: slope of ln|Δ| against ln x where |Δ| > 2σ (at least three x), jackknifed with that set.
    power = {}
    for j, name in enumerate(NAMES):
        significant = [i for i in range(len(xs)) if abs(value[2, j, i]) > 2 * error[2, j, i]]
        entry = {"significant_x": [round(float(xs[i]), 3) for i in significant]}
        if len(significant) >= 3 and len({np.sign(value[2, j, i]) for i in significant}) == 1:
            lx = np.log(xs[significant])

            def slope(total, count, j=j, significant=significant, lx=lx):
                d = both(total, count)[2, j, significant]
                return np.array([np.polyfit(lx, np.log(np.abs(d)), 1)[0]])

            p, p_err = jackknife(parts, counts, slope)
            entry.update({"power": float(p[0]), "power_err": float(p_err[0])})
        power[name] = entry
    provenance = {"kick": args.kick, "hotspot": args.hot, "commit_kick": kick.commit,
                  "commit_hotspot": hot.commit, "seed": kick.scene["seed"],
                  "realizations": kick.scene["realizations"], "blocks": len(blocks),
                  "lambda": kick.lam, "command": " ".join(sys.argv)}
    if args.ns:
        ns = ns_delta(args.ns[0], args.ns[1], xs)
        for r in rows:
            r["ns_delta"] = ns.get(r["amplitude"], {}).get(r["R_over_lambda"], "")
        provenance["ns"] = {"self_similar": args.ns[0], "hotspot": args.ns[1],
                            "command_hotspot": header_value(f"{args.ns[1]}/samples.csv", "command")}
    with open(args.out, "w") as f:
        f.write("# " + json.dumps(provenance) + "\n")
        f.write("# delta = hotspot/kick - 1 (p_imp_ratio: hotspot - kick); errors: paired delete-one-block jackknife\n")
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    json.dump({"provenance": provenance, "decay": power}, open(args.power_json, "w"), indent=1)
    for name in NAMES:
        print(name)
        for r in rows:
            if r["amplitude"] == name:
                print(f"  x {r['R_over_lambda']:>8}  kick {r['kick']:>10} ± {r['kick_err']:<8} hot {r['hotspot']:>10} ± "
                      f"{r['hotspot_err']:<8} Δ {r['delta']:>10} ± {r['delta_err']:<8} ({r['delta_over_err']}σ)"
                      f"  NS Δ {r.get('ns_delta', '')}")
        print("  decay:", power[name])


if __name__ == "__main__":
    main()
