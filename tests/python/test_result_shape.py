"""One result shape (issue 30): md.run, tracer.run and read_run return the same coldblast.Run, with
DataFrames equal bit for bit whether the run was kept in memory, written, or read back, snapshots as
numpy arrays; and the progress of a long call as a tqdm bar in a notebook, lines elsewhere."""
import sys
import types

import numpy as np
import pandas as pd
import pytest

import coldblast
from coldblast import _progress

SCENE = {"t_max": 40, "realizations": 4, "seed": 7,
         "observables": ["R_imp", "V_imp", "C_imp", "T0", "profiles", "p_imp", "trajectories", "snapshots"],
         "snapshot_times": [20.0, 40.0], "snapshot_realizations": [0, 2]}
TABLES = ("observables", "blocks", "profiles", "p_imp", "trajectories", "moments", "prefactors")
# summary.json keys that describe the process that ran, not the run's numbers
PROCESS_KEYS = {"run_id", "wall_seconds", "collisions_per_second", "seconds_per_realization",
                "trajectories_per_second", "command", "date", "threads"}


def numbers(summary):
    return {k: v for k, v in summary.items() if k not in PROCESS_KEYS}


def assert_same_run(a, b):
    for name in TABLES:
        x, y = getattr(a, name), getattr(b, name)
        assert (x is None) == (y is None), name
        if x is not None:
            pd.testing.assert_frame_equal(x, y, check_exact=True)
    assert numbers(a.summary) == numbers(b.summary)
    assert a.realization_snapshots.keys() == b.realization_snapshots.keys()
    for k, frames in a.realization_snapshots.items():
        assert frames.keys() == b.realization_snapshots[k].keys()
        for t, s in frames.items():
            np.testing.assert_array_equal(s.position, b.realization_snapshots[k][t].position)
            np.testing.assert_array_equal(s.id, b.realization_snapshots[k][t].id)
    assert a.realization_trajectories.keys() == b.realization_trajectories.keys()


@pytest.fixture(scope="module")
def md_runs(tmp_path_factory):
    out = tmp_path_factory.mktemp("shape") / "md"
    memory = coldblast.md.run(progress=False, **SCENE)
    written = coldblast.md.run(out=out, progress=False, **SCENE)
    return memory, written, coldblast.read_run(out)


def test_md_run_in_memory_written_and_read_back_are_one_object(md_runs):
    memory, written, read = md_runs
    assert type(memory) is type(written) is type(read) is coldblast.Run
    assert memory.directory is None and written.directory == read.directory
    assert memory.kind == written.kind == read.kind == "md run"
    assert_same_run(memory, written)
    assert_same_run(written, read)
    assert read.summary["run_id"] == written.summary["run_id"]
    assert memory.moments is None and memory.prefactors is None  # the tracer's tables


def test_snapshots_are_arrays(md_runs):
    run, written = md_runs[0], md_runs[1]
    assert sorted(run.realization_snapshots) == [0, 2] and run.snapshots is run.realization_snapshots[0]
    assert list(run.snapshots) == [20.0, 40.0] and sorted(run.realization_trajectories) == [2]
    for t, s in run.snapshots.items():
        assert s.t == t and s.realization == 0
        assert s.position.dtype == np.float64 and s.position.shape == (len(s), 2)
        assert s.id.dtype == np.int64 and (np.diff(s.id) > 0).all()  # ids ascending, each once
        assert s.moving.dtype == bool and s.impurity.dtype == bool
        assert s.impurity.sum() == run.summary["scene"]["impurities"]["count"]
        assert (s.moving[s.impurity]).all()  # a kicked impurity has moved
        assert np.hypot(*s.position.T).max() <= run.summary["region_radius"]
        # The arrays are the file's columns: to_frame() gives back the DataFrame of snapshot_<t>.csv.
        path = f"{written.directory}/snapshot_{t:g}.csv"
        pd.testing.assert_frame_equal(s.to_frame(), pd.read_csv(path, comment="#", float_precision="round_trip"))


def test_estimates_are_the_observables_rows(md_runs):
    run = md_runs[0]
    for name, e in run.estimates.items():
        rows = run.estimate(name)
        np.testing.assert_array_equal(e["mean"], rows["mean"].to_numpy())
        assert e["count"].dtype == np.int64 and (e["count"] == 4).all()
    with pytest.raises(ValueError, match=r"observable = n0 is not in this run \(recorded: C_imp, R_imp, T0, V_imp\)"):
        run.estimate("n0")


def test_tracer_run_in_memory_written_and_read_back_are_one_object(tmp_path):
    args = dict(background="tvns", trajectories=32, seed=3, progress=False, t_max=40)
    memory = coldblast.tracer.run(**args)
    written = coldblast.tracer.run(out=tmp_path / "t", **args)
    read = coldblast.read_run(tmp_path / "t")
    assert memory.kind == written.kind == read.kind == "tracer"
    assert_same_run(memory, written)
    assert_same_run(written, read)
    assert list(read.moments.columns[:5]) == ["t", "r2", "r2_stderr", "r4_over_r2_squared",
                                              "r4_over_r2_squared_stderr"]
    assert read.snapshots == {} and read.trajectories is None and read.p_imp is not None
    # <r^4> >= <r^2>^2 (Cauchy-Schwarz) wherever the impurities have moved.
    moved = read.moments[read.moments["r2"] > 0]
    assert len(moved) == len(read.moments) - 1 and (moved["r4_over_r2_squared"] >= 1).all()


class _Shell:
    """Stands for IPython's kernel shell; only its class name matters to in_notebook()."""


def _fake_ipython(monkeypatch, shell_name):
    shell = type(shell_name, (_Shell,), {})()
    monkeypatch.setitem(sys.modules, "IPython", types.SimpleNamespace(get_ipython=lambda: shell))


def test_progress_is_a_bar_in_a_notebook_and_lines_elsewhere(monkeypatch):
    pytest.importorskip("tqdm")
    monkeypatch.delitem(sys.modules, "IPython", raising=False)
    assert isinstance(_progress.callback(True, "md run", "realizations"), _progress.StderrProgress)
    _fake_ipython(monkeypatch, "TerminalInteractiveShell")  # IPython in a terminal: lines
    assert isinstance(_progress.callback(True, "md run", "realizations"), _progress.StderrProgress)
    _fake_ipython(monkeypatch, "ZMQInteractiveShell")  # a Jupyter kernel: a bar
    assert isinstance(_progress.callback(True, "md run", "realizations"), _progress.BarProgress)
    assert isinstance(_progress.callback("lines", "md run", "realizations"), _progress.StderrProgress)
    assert _progress.callback(False, "md run", "realizations") is None


def test_bar_counts_to_the_total(capsys):
    pytest.importorskip("tqdm")
    coldblast.md.run(progress="bar", realizations=3, t_max=20, observables=["R"])
    err = capsys.readouterr().err
    assert "md run: 100%" in err and "| 3/3 [" in err and "realizations/s" in err


def test_bad_progress_names_the_argument():
    with pytest.raises(ValueError, match=r'progress = \'tqdm\' is not True, False, "bar", "lines" or a callable'):
        coldblast.md.run(progress="tqdm", realizations=1, t_max=10)
