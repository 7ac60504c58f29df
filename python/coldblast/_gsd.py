"""GSD files of a run's snapshots (hoomd's schema, read by OVITO, freud and hoomd): ``write_gsd`` and
``python3 -m coldblast gsd RUN_DIR [-o FILE]``.

One frame per snapshot time, holding the particles the snapshot holds (by default the moving ones
and the gas just ahead of the front: docs/md-output.md), read from the run's extended-XYZ file:

- ``particles/types`` = ["host", "impurity"], ``particles/typeid``, ``particles/mass``,
  ``particles/diameter`` (2 × radius), ``particles/position`` and ``particles/velocity`` (float32,
  as the schema has them), ``configuration/box`` (the simulated cube of side 2 R_region, centred on
  the start; Lz = 0 in 2D) and ``configuration/dimensions``;
- the log: ``particles/id`` (the particle's index in the run), ``particles/velocity_float64`` (the
  velocities to the last digit: total energy = E to 1e-12), ``coldblast/time`` (t) and
  ``coldblast/run_id`` (the run's id as UTF-8 bytes: ``bytes(frame.log["coldblast/run_id"]).decode()``).
"""
import argparse
import os
import re
import sys
import tempfile
from pathlib import Path

import numpy as np

TYPES = ["host", "impurity"]


def _frames(path):
    """The frames of one of our snapshots.extxyz files: (comment keys, {column: array})."""
    with open(path) as f:
        lines = f.read().splitlines()
    i = 0
    while i < len(lines):
        n = int(lines[i])
        comment = lines[i + 1]
        keys = {k: q or b for k, q, b in re.findall(r'(\w+)=(?:"([^"]*)"|(\S+))', comment)}
        spec = keys["Properties"].split(":")
        rows = [line.split() for line in lines[i + 2:i + 2 + n]]
        columns, k = {}, 0
        for name, kind, width in zip(spec[0::3], spec[1::3], spec[2::3]):
            width = int(width)
            cells = [r[k:k + width] for r in rows]
            dtype = {"R": np.float64, "I": np.int64, "S": object}[kind]
            array = np.array(cells, dtype=dtype).reshape(n, width)
            columns[name] = array[:, 0] if width == 1 else array
            k += width
        yield keys, columns
        i += 2 + n


def _snapshot_file(run_dir, realization):
    name = "snapshots.extxyz" if realization == 0 else f"snapshots_realization_{realization}.extxyz"
    path = Path(run_dir) / name
    if not Path(run_dir).is_dir():
        raise ValueError(f"RUN_DIR = {run_dir} is not a directory")
    if not path.is_file():
        raise ValueError(f"RUN_DIR = {run_dir} holds no {name}: the run recorded no snapshots of realization "
                         f"{realization} (observables \"snapshots\"; scene key snapshot_realizations)")
    return path


def _frame(gsd_hoomd, index, keys, columns):
    d = int(keys["dimensions"])
    lattice = np.array(keys["Lattice"].split(), dtype=float).reshape(3, 3)
    frame = (getattr(gsd_hoomd, "Frame", None) or gsd_hoomd.Snapshot)()
    frame.configuration.step = index
    frame.configuration.dimensions = d
    frame.configuration.box = [lattice[0, 0], lattice[1, 1], lattice[2, 2] if d == 3 else 0.0, 0, 0, 0]
    n = len(columns["id"])
    frame.particles.N = n
    frame.particles.types = TYPES
    frame.particles.typeid = columns["typeid"].astype(np.uint32)
    frame.particles.mass = columns["masses"].astype(np.float32)
    frame.particles.diameter = (2 * columns["radius"]).astype(np.float32)
    frame.particles.position = columns["pos"].astype(np.float32)
    frame.particles.velocity = columns["velo"].astype(np.float32)
    frame.log["particles/id"] = columns["id"].astype(np.int64)
    frame.log["particles/velocity_float64"] = columns["velo"].astype(np.float64)
    frame.log["coldblast/time"] = np.array([float(keys["Time"])])
    frame.log["coldblast/run_id"] = np.frombuffer(keys.get("run_id", "").encode(), dtype=np.uint8)
    return frame


def _output_path(path):
    """Where to write: a new path or a regular file (a symlink to one is followed and stays a link);
    a device, a FIFO or a folder is never replaced."""
    path = Path(path)
    target = Path(os.path.realpath(path))
    if target.exists() and not target.is_file():
        raise ValueError(f"-o = {path} is not a regular file (a device, FIFO or folder is never replaced)")
    if not target.parent.is_dir():
        raise ValueError(f"-o = {path}: its folder {target.parent} does not exist")
    return target


def write_gsd(run_dir, path=None, realization=0):
    """Write the snapshots of `realization` of the MD run in `run_dir` as a GSD file (hoomd schema);
    `path` defaults to RUN_DIR/snapshots.gsd (snapshots_realization_K.gsd). Returns the path written.
    The file appears whole or not at all. Bad input raises ValueError naming the argument."""
    import gsd.hoomd  # Debian's python3-gsd (scripts/bootstrap.sh)

    if int(realization) < 0:
        raise ValueError(f"--realization = {realization} is outside [0, realizations)")
    source = _snapshot_file(run_dir, int(realization))
    if path is None:
        path = Path(run_dir) / ("snapshots.gsd" if realization == 0 else f"snapshots_realization_{realization}.gsd")
    target = _output_path(path)
    fd, temporary = tempfile.mkstemp(prefix=target.name + ".", suffix=".tmp", dir=target.parent)
    os.close(fd)
    try:
        with gsd.hoomd.open(temporary, mode="wb") as trajectory:
            for index, (keys, columns) in enumerate(_frames(source)):
                trajectory.append(_frame(gsd.hoomd, index, keys, columns))
        os.replace(temporary, target)
    except BaseException:
        os.unlink(temporary)
        raise
    return Path(path)


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python3 -m coldblast gsd",
                                     description="Write an MD run's snapshots as a GSD file (hoomd schema; OVITO, "
                                                 "freud and hoomd read it).")
    parser.add_argument("run_dir", metavar="RUN_DIR", help="an md run folder that recorded snapshots")
    parser.add_argument("-o", "--output", help="the GSD file (default: RUN_DIR/snapshots.gsd)")
    parser.add_argument("--realization", type=int, default=0,
                        help="which realization's snapshots (scene key snapshot_realizations; default 0)")
    args = parser.parse_args(argv)
    try:
        written = write_gsd(args.run_dir, args.output, args.realization)
    except ValueError as error:
        print(f"coldblast gsd: error: {error}", file=sys.stderr)
        return 2
    print(f"wrote {written}")
    return 0
