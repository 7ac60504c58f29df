"""Event-driven MD ensembles of the blast (``coldblast md run``; paper Sec. V, docs/md-output.md)."""
import math
import os
from types import SimpleNamespace

import numpy as np

from . import _coldblast
from . import _progress
from ._run import Run
from ._signals import sigterm_stops
from ._arguments import integer as _integer
from ._arguments import number as _number


def _toml_value(value, key):
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, np.integer)):
        return str(int(value))
    if isinstance(value, (float, np.floating)):
        value = float(value)
        if math.isnan(value):
            return "nan"
        if math.isinf(value):
            return "inf" if value > 0 else "-inf"
        return repr(value)
    if isinstance(value, str):
        return '"' + value.replace("\\", "\\\\").replace('"', '\\"') + '"'
    if isinstance(value, (list, tuple, np.ndarray)):
        return "[" + ", ".join(_toml_value(v, key) for v in value) + "]"
    raise ValueError(f"scene key {key} = {value!r}: not a number, string, bool or list")


def _flatten(mapping, prefix=""):
    """{"impurities": {"count": 2}} -> [("impurities.count", 2)]."""
    items = []
    for key, value in mapping.items():
        name = prefix + str(key)
        if isinstance(value, dict):
            items.extend(_flatten(value, name + "."))
        else:
            items.append((name, value))
    return items


def scene_toml(scene):
    """A scene dict (keys of docs/md-output.md; ``impurities`` a nested dict) as TOML text."""
    lines = [f"{key} = {_toml_value(value, key)}" for key, value in _flatten(scene)]
    return "\n".join(lines) + "\n"


def scene_arguments(scene, overrides):
    """(scene_file, scene_text, ["key=value", ...]) of a scene (None, a TOML path or a dict) and
    its overrides, as the library's scene reader takes them (shared with coldblast.tracer)."""
    scene_file, scene_text = "", ""
    if scene is None:
        pass
    elif isinstance(scene, dict):
        scene_text = scene_toml(scene)
    elif isinstance(scene, (str, os.PathLike)):
        scene_file = os.fspath(scene)
        if not scene_file:
            raise ValueError("SCENE = '' is empty (a TOML file, a dict, or None for the default scene)")
    else:
        raise ValueError(f"SCENE = {scene!r} is not a TOML path, a dict or None")
    return scene_file, scene_text, [f"{key}={_toml_value(value, key)}" for key, value in _flatten(overrides)]


def default_scene():
    """The embedded default scene (d = 2, E = 10, t_max = 200, 32 realizations) as TOML text."""
    return _coldblast.default_scene_toml()


def run(scene=None, realizations=None, threads=1, seed=None, out=None, progress=True, resume=None, overwrite=False,
        save_every=600.0, **overrides):
    """Run an MD ensemble of blast realizations (the same call as ``coldblast md run``).

    Parameters
    ----------
    scene : None, str, os.PathLike or dict
        None: the embedded default scene (2D, E = 10, t_max = 200, seconds). A path: a TOML scene
        file (scenes/paper-2d.toml, keys in docs/md-output.md). A dict: a scene with those keys
        (``impurities`` a nested dict); keys left out take the library defaults.
    realizations : int or None
        Number of realizations, [1, 1e9]; None: the scene's.
    threads : int
        Worker threads, [1, 1024]; the numbers do not depend on it (bit-identical).
    seed : int or None
        Master seed >= 0; None: the scene's. Realization i is seeded from (seed, i).
    out : str, os.PathLike or None
        Output directory (observables.csv, blocks.csv, summary.json, ..., manifest.json as ``md run
        --out``): one run, with its run id in every file; written atomically at the end, every
        finished realization kept in out/checkpoint meanwhile. A folder holding another run's files
        (or an unfinished run's checkpoint) is refused (ValueError) unless ``overwrite``. None
        writes nothing.
    progress : bool, str or callable
        True: realizations done and ETA as a tqdm bar in a Jupyter notebook (where tqdm is installed), as lines
        on stderr otherwise; "bar" or "lines" to choose; False: silent; callable(done, total).
    resume : str, os.PathLike or None
        Continue the stopped run in this output directory (``md run --resume``): its scene, shard
        and run id come from its checkpoint; an argument given again must agree with them.
    overwrite : bool
        Replace the files of another run in ``out`` (exactly those of its manifest.json).
    save_every : float
        Seconds, in (0, 1e9] (``md run --save-every``): with ``out``, a realization running longer saves
        where it stands in out/checkpoint this often, and at Ctrl-C or SIGTERM at once, so a long
        realization is not lost; ``run(resume=out)`` goes on from there, bit for bit.
    **overrides
        Scene keys to override, as ``--set key=value``: ``E=20``, ``t_max=500``,
        ``observables=["R_imp", "T0"]``, ``impurities={"count": 2}``.

    Units: m = 1 (host mass), k_B = 1, lengths and times in the scene's units (a = particle radius).

    Returns
    -------
    coldblast.Run, the object ``coldblast.read_run(out)`` gives for the folder (equal DataFrames):
        ``observables`` (DataFrame t, observable, mean, stderr, count: R_imp, V_imp, C_imp, u_imp, n0,
        T0, R, ...; definitions in docs/md-output.md; ``estimate(name)`` one of them, ``estimates``
        all as numpy arrays), ``blocks``, ``profiles``, ``p_imp``, ``trajectories`` (DataFrames or
        None), ``snapshots`` ({t: Snapshot of numpy arrays}), ``summary`` (summary.json, dict),
        ``directory`` (``out``, or None when nothing was written).

    Raises ValueError with the CLI's exit-2 message for a bad scene or argument (e.g.
    ``E = -1 is outside (0, inf)``), RuntimeError for a failed run, KeyboardInterrupt on Ctrl-C
    (with ``out`` every finished realization stays in out/checkpoint and a long one in flight saves
    where it stands, within about a second; without ``out`` at the current realization's end;
    ``run(resume=out)`` continues it).
    """
    if resume is not None:
        if out is not None and os.path.normpath(os.fspath(out)) != os.path.normpath(os.fspath(resume)):
            raise ValueError(f"resume = {os.fspath(resume)} must be the output directory (out = {os.fspath(out)})")
        out = resume
    scene_file, scene_text, sets = scene_arguments(scene, overrides)
    with sigterm_stops():
        raw = _coldblast.md_run(scene_file, scene_text, sets,
                                None if realizations is None else _integer(realizations, "--realizations"),
                                None if seed is None else _integer(seed, "--seed"), _integer(threads, "--threads"),
                                "" if out is None else os.fspath(out), resume is not None, bool(overwrite),
                                float(save_every), _progress.callback(progress, "md run", "realizations"))
    return Run(raw, out, "md run")


def states(time, scene=None, realizations=None, threads=1, seed=None, out=None, progress=True, overwrite=False,
           **overrides):
    """The impurities' positions, velocities and collision counts at ``time`` in every realization of
    an MD ensemble (the same call as ``coldblast md states``; realization i is ``run``'s realization
    i of the same scene and seed, so these reproduce its R_imp, V_imp, C_imp at a recorded time).

    Parameters as ``run``; ``time`` in (0, t_max] of the scene. With ``out``, also writes
    out/impurity_states.csv, which ``coldblast.tracer.run(start="states", start_states=...)``
    starts the kinetic tracer from.

    Returns
    -------
    types.SimpleNamespace with ``t``; ``realization``, ``impurity``, ``collisions`` (arrays, one entry
    per impurity); ``r``, ``v``, ``r0`` (arrays of shape (impurities, d): position from the blast
    centre, velocity, start position); ``out``.

    Raises ValueError naming the argument for bad input (``--time = ... is outside (0, t_max]``),
    KeyboardInterrupt on Ctrl-C (nothing is written).
    """
    scene_file, scene_text, sets = scene_arguments(scene, overrides)
    with sigterm_stops():
        raw = _coldblast.md_states(scene_file, scene_text, sets,
                                   None if realizations is None else _integer(realizations, "--realizations"),
                                   None if seed is None else _integer(seed, "--seed"), _integer(threads, "--threads"),
                                   _number(time, "--time"), "" if out is None else os.fspath(out), bool(overwrite),
                                   _progress.callback(progress, "md states", "realizations"))
    return SimpleNamespace(out=None if out is None else os.fspath(out), **raw)
