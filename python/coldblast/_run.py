"""Run directories of ``md run`` (CLI- or Python-made) as pandas DataFrames (docs/md-output.md)."""
import os
import re

import pandas as pd

from . import _coldblast


class Run:
    """An MD run directory.

    Attributes
    ----------
    directory : str
    summary : dict
        summary.json (scene, seed, realizations, collisions_total, d, n, a, E, phi, lambda, A_d, ...).
    observables : DataFrame
        observables.csv: t, observable, mean, stderr, count.
    blocks : DataFrame
        blocks.csv: block, t, observable, sum, count (the jackknife input).
    profiles, p_imp, trajectories : DataFrame or None
        profiles.csv, p_imp.csv, trajectories.csv when the run recorded them.
    snapshots : dict
        {t: DataFrame of snapshot_<t>.csv (id, x, y[, z], moving, impurity)}, realization 0.
    realization_snapshots : dict
        {k: {t: DataFrame}} of every realization that recorded snapshots (scene key
        snapshot_realizations; realization k > 0 writes snapshot_<t>_realization_<k>.csv).
    """

    def __init__(self, directory):
        self.directory = os.fspath(directory)
        # The library's reader checks the directory (ValueError naming the missing file).
        self.summary = _coldblast.read_run_summary(self.directory)
        self.observables = self._csv("observables.csv", required=True)
        self.blocks = self._csv("blocks.csv", required=True)
        self.profiles = self._csv("profiles.csv")
        self.p_imp = self._csv("p_imp.csv")
        self.trajectories = self._csv("trajectories.csv")
        self.realization_snapshots = {}
        for name in sorted(os.listdir(self.directory)):
            match = re.fullmatch(r"snapshot_(.+?)(?:_realization_(\d+))?\.csv", name)
            if match:
                k = int(match.group(2) or 0)
                self.realization_snapshots.setdefault(k, {})[float(match.group(1))] = self._csv(name)
        self.realization_snapshots = {k: dict(sorted(v.items())) for k, v in sorted(self.realization_snapshots.items())}
        self.snapshots = self.realization_snapshots.get(0, {})

    def _csv(self, name, required=False):
        path = os.path.join(self.directory, name)
        if not os.path.exists(path):
            if required:
                raise ValueError(f"RUN_DIR file = {path} cannot be read")  # the library's wording
            return None
        # round_trip: the files hold 17 significant digits; pandas' default parser can be 1 ulp off
        return pd.read_csv(path, comment="#", float_precision="round_trip")

    def estimate(self, observable):
        """Rows of observables.csv for one observable (t, mean, stderr, count), sorted by t."""
        table = self.observables[self.observables["observable"] == observable]
        if table.empty:
            names = ", ".join(sorted(self.observables["observable"].unique()))
            raise ValueError(f"observable = {observable} is not in this run (recorded: {names})")
        return table.drop(columns="observable").sort_values("t").reset_index(drop=True)

    def __repr__(self):
        return (f"Run({self.directory!r}: d = {self.summary.get('d')}, {self.summary.get('realizations')} realizations, "
                f"observables {sorted(self.observables['observable'].unique())})")


def read_run(directory):
    """Read an ``md run`` output directory (CLI- or Python-made) into a :class:`Run` of pandas DataFrames.

    Raises ValueError naming the missing file when the folder is not a run directory.
    """
    return Run(directory)
