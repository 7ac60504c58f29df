#!/usr/bin/python3
"""An MD run folder with coarser or perturbed profiles, to measure what the `tracer --background md`
run owes to the profiles' interpolation and noise (docs/verification.md, "The tracer in the MD's
own fields").

--bins k --times m: every k adjacent bins of r/R merged and every m-th recorded time kept, exactly
as `md run` would have binned them (md/observers.cpp): the density as the volume average, the
radial flow as the particle average Σ v_r / Σ 1, and the temperature from the merged
Σ m v² / Σ 1 = d T + u² of each bin. The interpolation is second order, so the tracer's error at the
original spacing is about a third of its change from the original to the coarse profiles.

--noise SEED: to every bin a Gaussian deviate of its statistical error: density_stderr for the
density, and independent-particle estimates for the others, sqrt(T/N) for u and sqrt(2/(d N)) T for
T, N = particles × realizations (a dense gas fluctuates less than independent particles, so these
overstate the noise). The tracer's change is one draw of what the profiles' noise does to it.

Usage: scripts/profile_variants.py MD_DIR OUT_DIR [--bins K] [--times M] [--noise SEED]
OUT_DIR gets the new profiles.csv and copies of summary.json and observables.csv (R).
"""
import argparse
import csv
import io
import math
import os
import shutil


def read(path):
    with open(path) as f:
        lines = f.readlines()
    header = [l for l in lines if l.startswith("#")]
    rows = list(csv.DictReader(io.StringIO("".join(l for l in lines if not l.startswith("#")))))
    return header, rows


def coarsen(rows, d, bins, times):
    """The merged rows (dicts with profiles.csv's columns)."""
    by_time = {}
    for r in rows:
        by_time.setdefault(float(r["t"]), []).append(r)
    kept = sorted(by_time)[::times]
    out = []
    for t in kept:
        group = sorted(by_time[t], key=lambda r: int(r["bin"]))
        if len(group) % bins:
            raise SystemExit(f"--bins {bins} does not divide the {len(group)} bins")
        for b in range(len(group) // bins):
            part = group[b * bins:(b + 1) * bins]
            lo, hi = float(part[0]["r_over_R_lo"]), float(part[-1]["r_over_R_hi"])
            volume = [float(r["r_over_R_hi"]) ** d - float(r["r_over_R_lo"]) ** d for r in part]
            density = sum(v * float(r["density_over_n"]) for v, r in zip(volume, part)) / sum(volume)
            # (the bins' errors as if independent: the error column is informative only)
            error = math.sqrt(sum((v * float(r["density_stderr"])) ** 2 for v, r in zip(volume, part))) / sum(volume)
            particles = sum(float(r["particles"]) for r in part)
            if particles > 0:
                u = sum(float(r["particles"]) * float(r["radial_velocity"]) for r in part) / particles
                v2 = sum(float(r["particles"]) * (d * float(r["temperature"]) + float(r["radial_velocity"]) ** 2)
                         for r in part) / particles
                T = max(0.0, (v2 - u * u) / d)
            else:
                u = T = 0.0
            out.append({"t": part[0]["t"], "bin": b, "r_over_R_lo": repr(lo), "r_over_R_hi": repr(hi),
                        "density_over_n": repr(density), "density_stderr": repr(error),
                        "radial_velocity": repr(u), "temperature": repr(T), "particles": repr(particles)})
    return out


def perturb(rows, d, realizations, seed):
    """The rows with every bin's n, u, T moved by a Gaussian deviate of its statistical error."""
    import random
    rng = random.Random(seed)
    out = []
    for r in rows:
        r = dict(r)
        count = float(r["particles"]) * realizations
        n, error, T = float(r["density_over_n"]), float(r["density_stderr"]), float(r["temperature"])
        if math.isfinite(error):
            r["density_over_n"] = repr(max(0.0, n + error * rng.gauss(0.0, 1.0)))
        if count > 0:
            r["radial_velocity"] = repr(float(r["radial_velocity"]) + math.sqrt(T / count) * rng.gauss(0.0, 1.0))
            r["temperature"] = repr(max(0.0, T * (1.0 + math.sqrt(2.0 / (d * count)) * rng.gauss(0.0, 1.0))))
        out.append(r)
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("md")
    parser.add_argument("out")
    parser.add_argument("--bins", type=int, default=1, help="adjacent bins merged (default 1: none)")
    parser.add_argument("--times", type=int, default=1, help="keep every n-th recorded time (default 1: all)")
    parser.add_argument("--noise", type=int, help="perturb every bin by its statistical error, with this seed")
    args = parser.parse_args()
    if args.bins < 1 or args.times < 1:
        parser.error("--bins and --times must be >= 1")
    import json
    with open(os.path.join(args.md, "summary.json")) as f:
        summary = json.load(f)
    d = int(summary["d"])
    header, rows = read(os.path.join(args.md, "profiles.csv"))
    merged = coarsen(rows, d, args.bins, args.times)
    if args.noise is not None:
        merged = perturb(merged, d, int(summary["realizations"]), args.noise)
    os.makedirs(args.out, exist_ok=True)
    for name in ("summary.json", "observables.csv"):
        shutil.copy(os.path.join(args.md, name), os.path.join(args.out, name))
    with open(os.path.join(args.out, "profiles.csv"), "w") as f:
        f.writelines(header)
        noise = "" if args.noise is None else f" --noise {args.noise}"
        f.write(f"# made by scripts/profile_variants.py --bins {args.bins} --times {args.times}{noise} from {args.md}\n")
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()), lineterminator="\n")
        writer.writeheader()
        writer.writerows(merged)
    print(f"{args.out}/profiles.csv: {len(merged)} rows ({len(rows)} in {args.md})")


if __name__ == "__main__":
    main()
