#!/usr/bin/python3
"""An MD run folder with coarser profiles: every `--bins` adjacent bins of r/R merged and every
`--times`-th recorded time kept, exactly as `md run` would have binned them (md/observers.cpp):
the density as the volume average, the radial flow as the particle average Σ v_r / Σ 1, and the
temperature from the merged Σ m v² / Σ 1 = d T + u² of each bin. The `tracer --background md`
run in the coarse profiles against the one in the original measures the interpolation's effect
on the tracer (second order: the error at the original spacing is about a third of the
difference; docs/verification.md, "The tracer in the MD's own fields").

Usage: scripts/coarsen_profiles.py MD_DIR OUT_DIR [--bins 2] [--times 2]
OUT_DIR gets the coarse profiles.csv and copies of summary.json and observables.csv (R).
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


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("md")
    parser.add_argument("out")
    parser.add_argument("--bins", type=int, default=2, help="adjacent bins merged (default 2)")
    parser.add_argument("--times", type=int, default=2, help="keep every n-th recorded time (default 2)")
    args = parser.parse_args()
    if args.bins < 1 or args.times < 1:
        parser.error("--bins and --times must be >= 1")
    import json
    with open(os.path.join(args.md, "summary.json")) as f:
        d = int(json.load(f)["d"])
    header, rows = read(os.path.join(args.md, "profiles.csv"))
    merged = coarsen(rows, d, args.bins, args.times)
    os.makedirs(args.out, exist_ok=True)
    for name in ("summary.json", "observables.csv"):
        shutil.copy(os.path.join(args.md, name), os.path.join(args.out, name))
    with open(os.path.join(args.out, "profiles.csv"), "w") as f:
        f.writelines(header)
        f.write(f"# coarsened by scripts/coarsen_profiles.py --bins {args.bins} --times {args.times} from {args.md}\n")
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()), lineterminator="\n")
        writer.writeheader()
        writer.writerows(merged)
    print(f"{args.out}/profiles.csv: {len(merged)} rows ({len(rows)} in {args.md})")


if __name__ == "__main__":
    main()
