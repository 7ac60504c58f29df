"""One result shape for every run: ``md.run``, ``tracer.run`` and ``read_run`` all return a :class:`Run`.

The library renders a run's files once (run::blast_files, run::tracer_files: the files of a run
directory, docs/md-output.md and docs/kinetic.md); a run returned by ``md.run``/``tracer.run`` is
parsed from those texts, a run read from a folder from the same files on disk, by the same code
below. So the DataFrames of a run made in Python and of its folder read back are equal, column for
column and bit for bit.
"""
import io
import json
import os
import re

import numpy as np
import pandas as pd

from . import _coldblast

# The run files that become DataFrames (attribute name: file name); None when the run has no such file.
_TABLES = {"observables": "observables.csv", "blocks": "blocks.csv", "profiles": "profiles.csv",
           "p_imp": "p_imp.csv", "trajectories": "trajectories.csv", "moments": "moments.csv",
           "prefactors": "prefactors.csv"}
_SNAPSHOT = re.compile(r"snapshot_(.+?)(?:_realization_(\d+))?\.csv")
_TRAJECTORIES = re.compile(r"trajectories_realization_(\d+)\.csv")


def _table(text):
    # comment="#": the provenance header; round_trip: the files hold shortest round-trip decimals,
    # which pandas' default parser can read 1 ulp off.
    return pd.read_csv(io.BytesIO(text), comment="#", float_precision="round_trip")


class Snapshot:
    """One snapshot of one realization as numpy arrays (snapshot_<t>.csv: the particles the scene's
    snapshot_particles selects, ids ascending).

    Attributes: ``t`` (float), ``realization`` (int), ``id`` (int64, shape (N,)), ``position``
    (float64, (N, d), from the blast centre), ``moving`` and ``impurity`` (bool, (N,)).
    """

    def __init__(self, t, realization, table):
        self.t, self.realization = float(t), int(realization)
        self.id = table["id"].to_numpy(dtype=np.int64)
        axes = [c for c in ("x", "y", "z") if c in table.columns]
        self.position = table[axes].to_numpy(dtype=np.float64)
        self.moving = table["moving"].to_numpy() != 0
        self.impurity = table["impurity"].to_numpy() != 0

    def __len__(self):
        return len(self.id)

    def to_frame(self):
        """The snapshot as the DataFrame of its file (id, x, y[, z], moving, impurity)."""
        frame = pd.DataFrame({"id": self.id})
        for k, axis in enumerate("xyz"[:self.position.shape[1]]):
            frame[axis] = self.position[:, k]
        frame["moving"], frame["impurity"] = self.moving.astype(int), self.impurity.astype(int)
        return frame

    def __repr__(self):
        return (f"Snapshot(t = {self.t:g}, realization {self.realization}: {len(self)} particles, "
                f"{int(self.moving.sum())} moving, {int(self.impurity.sum())} impurities)")


class Run:
    """A run, made in Python or read from its folder (``md run``, ``md merge`` or ``tracer``).

    Attributes
    ----------
    directory : str or None
        The run folder; None for a run made with ``out=None`` (nothing written).
    kind : str
        "md run", "md merge" or "tracer" (manifest.json's kind).
    summary : dict
        summary.json (scene, seed, realizations, collisions_total, d, n, a, E, phi, lambda, A_d, ...;
        the tracer's adds collision_rate, chi, ..., docs/kinetic.md).
    observables : DataFrame
        observables.csv: t, observable, mean, stderr, count (``estimate(name)``: one observable).
    blocks : DataFrame
        blocks.csv: block, t, observable, sum, count (the jackknife input).
    profiles, p_imp, trajectories : DataFrame or None
        profiles.csv, p_imp.csv, trajectories.csv (realization 0) when the run recorded them.
    moments, prefactors : DataFrame or None
        The tracer's moments.csv (r2, r4_over_r2_squared, v2, v4_over_v2_squared with their
        stderr) and prefactors.csv; None for an MD run.
    snapshots : dict
        {t: Snapshot} of realization 0 (numpy arrays; ``Snapshot.to_frame()`` gives a DataFrame).
    realization_snapshots : dict
        {k: {t: Snapshot}} of every realization that recorded snapshots (scene key snapshot_realizations).
    realization_trajectories : dict
        {k: DataFrame} of trajectories_realization_<k>.csv (realization 0's is ``trajectories``).
    files : list of str
        The names of the run's files (manifest.json's list).
    """

    def __init__(self, files, directory=None, kind=None):
        """`files`: [(name, bytes)] as the run directory holds them (run::blast_files)."""
        self.directory = None if directory is None else os.fspath(directory)
        contents = dict(files)
        self.files = [name for name, _ in files]
        if "summary.json" not in contents:
            raise ValueError(f"RUN_DIR file = {os.path.join(self.directory or '', 'summary.json')} cannot be read")
        self.summary = json.loads(contents["summary.json"])
        self.kind = kind or ("tracer" if str(self.summary.get("engine", "")).startswith("tracer") else "md run")
        for attribute, name in _TABLES.items():
            setattr(self, attribute, _table(contents[name]) if name in contents else None)
        self.realization_snapshots, self.realization_trajectories = {}, {}
        for name in sorted(contents):
            match = _SNAPSHOT.fullmatch(name)
            if match:
                k, t = int(match.group(2) or 0), float(match.group(1))
                self.realization_snapshots.setdefault(k, {})[t] = Snapshot(t, k, _table(contents[name]))
            match = _TRAJECTORIES.fullmatch(name)
            if match:
                self.realization_trajectories[int(match.group(1))] = _table(contents[name])
        self.realization_snapshots = {k: dict(sorted(v.items())) for k, v in sorted(self.realization_snapshots.items())}
        self.snapshots = self.realization_snapshots.get(0, {})

    @property
    def out(self):
        """The run folder (as ``directory``; the name of the ``out`` argument that made it)."""
        return self.directory

    def estimate(self, observable):
        """Rows of observables.csv for one observable (t, mean, stderr, count), sorted by t."""
        table = self.observables[self.observables["observable"] == observable]
        if table.empty:
            names = ", ".join(sorted(self.observables["observable"].unique()))
            raise ValueError(f"observable = {observable} is not in this run (recorded: {names})")
        return table.drop(columns="observable").sort_values("t").reset_index(drop=True)

    @property
    def estimates(self):
        """observables.csv per observable, in file order, as numpy arrays:
        {name: {"t", "mean", "stderr": float64, "count": int64}} (the same numbers as ``observables``)."""
        result = {}
        for name, rows in self.observables.groupby("observable", sort=False):
            result[name] = {"t": rows["t"].to_numpy(dtype=np.float64), "mean": rows["mean"].to_numpy(dtype=np.float64),
                            "stderr": rows["stderr"].to_numpy(dtype=np.float64),
                            "count": rows["count"].to_numpy(dtype=np.int64)}
        return result

    def __repr__(self):
        where = self.directory if self.directory is not None else "not written"
        unit = "trajectories" if self.kind == "tracer" else "realizations"
        return (f"Run({where!r}: {self.kind}, d = {self.summary.get('d')}, {self.summary.get('realizations')} {unit}, "
                f"observables {sorted(self.observables['observable'].unique())})")


def _directory_files(directory):
    """[(name, bytes)] of a run folder: manifest.json's list, or for a folder written before
    manifests, the files the run layer writes."""
    manifest_path = os.path.join(directory, "manifest.json")
    kind = None
    if os.path.exists(manifest_path):
        with open(manifest_path, "rb") as handle:
            manifest = json.load(handle)
        names, kind = manifest["files"], manifest.get("kind")
    else:
        names = sorted(name for name in os.listdir(directory)
                       if name in _TABLES.values() or name == "summary.json" or _SNAPSHOT.fullmatch(name)
                       or _TRAJECTORIES.fullmatch(name))
    files = []
    for name in names:
        if name in _TABLES.values() or name == "summary.json" or _SNAPSHOT.fullmatch(name) \
                or _TRAJECTORIES.fullmatch(name):
            with open(os.path.join(directory, name), "rb") as handle:
                files.append((name, handle.read()))
        else:
            files.append((name, b""))  # listed, not parsed (exact sums, extxyz)
    return files, kind


def read_run(directory):
    """Read a run folder (``md run``, ``md merge`` or ``tracer``; CLI- or Python-made) into a
    :class:`Run`, the object ``md.run`` and ``tracer.run`` return.

    Raises ValueError naming the missing file when the folder is not a run directory, or naming the
    file of another run in a mixed folder.
    """
    directory = os.fspath(directory)
    _coldblast.read_run_summary(directory)  # the library's checks: one run per folder, required files
    files, kind = _directory_files(directory)
    names = {name for name, _ in files}
    for required in ("observables.csv", "blocks.csv"):
        if required not in names:
            raise ValueError(f"RUN_DIR file = {os.path.join(directory, required)} cannot be read")
    return Run(files, directory, kind)
