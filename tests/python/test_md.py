"""coldblast.md.run and read_run against `coldblast md run` (same scene, seed: identical numbers)."""
import json
import math
import os

import numpy as np
import pandas as pd
import pytest

import coldblast
from conftest import REPO, cli_error, cli_json

TINY = {"t_max": 50, "realizations": 4}


def data_lines(path):
    with open(path) as f:
        return [line for line in f if not line.startswith("#")]


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    base = tmp_path_factory.mktemp("md")
    cli_dir, py_dir = base / "cli", base / "py"
    summary = cli_json("md", "run", "--set", "t_max=50", "--realizations", 4, "--seed", 3, "--threads", 2,
                       "--out", cli_dir)
    result = coldblast.md.run(realizations=4, seed=3, threads=1, out=py_dir, progress=False, t_max=50)
    return cli_dir, py_dir, summary, result


def test_same_numbers_as_cli(runs):
    cli_dir, py_dir, summary, result = runs
    for key in ("collisions_total", "energy_error_max", "particles", "region_radius", "A_d", "A_d_source",
                "recording_times", "realizations", "seed"):
        assert result.summary[key] == summary[key], key
    observables = pd.read_csv(cli_dir / "observables.csv", comment="#", float_precision="round_trip")
    for name, table in observables.groupby("observable", sort=False):
        e = result.estimates[name]
        np.testing.assert_array_equal(e["t"], table["t"].to_numpy())
        np.testing.assert_array_equal(e["mean"], table["mean"].to_numpy())
        np.testing.assert_array_equal(e["stderr"], table["stderr"].to_numpy())
        np.testing.assert_array_equal(e["count"], table["count"].to_numpy())
    assert list(result.estimates) == list(dict.fromkeys(observables["observable"]))
    for name in ("observables.csv", "blocks.csv", "accumulators.csv"):
        assert data_lines(cli_dir / name) == data_lines(py_dir / name), name


def test_dtypes_and_shapes(runs):
    _, _, summary, result = runs
    k = summary["recording_times"]
    for name, e in result.estimates.items():
        assert e["t"].dtype == np.float64 and e["mean"].dtype == np.float64 and e["stderr"].dtype == np.float64
        assert e["count"].dtype == np.int64
        assert all(e[c].shape == (k,) for c in ("t", "mean", "stderr", "count")), name
    assert (result.estimates["C_imp"]["count"] == 4).all()


def test_read_run_cli_and_python_directories(runs):
    cli_dir, py_dir, _, result = runs
    a, b = coldblast.read_run(cli_dir), coldblast.read_run(py_dir)
    pd.testing.assert_frame_equal(a.observables, b.observables)
    pd.testing.assert_frame_equal(a.blocks, b.blocks)
    assert list(a.observables.columns) == ["t", "observable", "mean", "stderr", "count"]
    assert list(a.blocks.columns) == ["block", "t", "observable", "sum", "count"]
    r = a.estimate("R_imp")
    np.testing.assert_array_equal(r["mean"].to_numpy(), result.estimates["R_imp"]["mean"])
    assert a.summary["collisions_total"] == result.summary["collisions_total"]
    assert a.profiles is None and a.snapshots == {}


def test_read_run_not_a_run(tmp_path):
    with pytest.raises(ValueError, match=r"summary\.json"):
        coldblast.read_run(tmp_path)
    (tmp_path / "summary.json").write_text('{"d": 2}')
    with pytest.raises(ValueError, match=r"blocks\.csv"):
        coldblast.read_run(tmp_path)


def test_scene_dict_and_file_agree(tmp_path):
    scene = {"d": 2, "n": 0.15, "a": 0.5, "E": 10.0, "t_max": 40.0, "realizations": 2, "seed": 5,
             "observables": ["R_imp", "T0"], "impurities": {"count": 3}}
    path = tmp_path / "scene.toml"
    path.write_text(coldblast.md.scene_toml(scene))
    a = coldblast.md.run(scene, progress=False)
    b = coldblast.md.run(path, progress=False)
    c = coldblast.md.run(str(path), progress=False, impurities={"count": 2})
    assert list(a.estimates) == ["R_imp", "T0"]
    np.testing.assert_array_equal(a.estimates["T0"]["mean"], b.estimates["T0"]["mean"])
    assert a.summary["scene"]["impurities"]["count"] == 3 and c.summary["scene"]["impurities"]["count"] == 2
    expected = cli_json("md", "run", path, "--set", "impurities.count=2", "--out", tmp_path / "cli")
    assert c.summary["collisions_total"] == expected["collisions_total"]


@pytest.mark.parametrize("kwargs,flags", [
    ({"E": -1}, ["--set", "E=-1"]),
    ({"n": 0.8}, ["--set", "n=0.8"]),
    ({"colour": "red"}, ["--set", "colour=red"]),
    ({"observables": ["magic"]}, ["--set", 'observables=["magic"]']),
    ({"snapshot_times": [300.0]}, ["--set", "snapshot_times=[300.0]"]),
    ({"impurities": {"count": 100000}}, ["--set", "impurities.count=100000"]),
    ({"realizations": 0}, ["--realizations", 0]),  # 0 and -1 are no longer "not given" sentinels
    ({"realizations": -1}, ["--realizations", -1]),
    ({"seed": -1}, ["--seed", -1]),
])
def test_bad_input_is_the_cli_error(kwargs, flags):
    with pytest.raises(ValueError) as error:
        coldblast.md.run(progress=False, **kwargs)
    assert str(error.value) == cli_error("md", "run", *flags)


def test_missing_scene_file_is_the_cli_error():
    with pytest.raises(ValueError) as error:
        coldblast.md.run("/nonexistent.toml")
    assert str(error.value) == cli_error("md", "run", "/nonexistent.toml")


def test_snapshot_beyond_t_max_rejected_at_validation():
    with pytest.raises(ValueError, match=r"snapshot_times = 300 is outside \(0, 200\]"):
        coldblast.md.run(snapshot_times=[50.0, 300.0], progress=False)


def test_progress_callback_counts_realizations():
    seen = []
    coldblast.md.run(progress=lambda done, total: seen.append((done, total)), t_max=30, realizations=3)
    assert seen[-1] == (3, 3) and all(total == 3 for _, total in seen)


def test_help_is_readable():
    doc = coldblast.md.run.__doc__
    for word in ("realizations", "threads", "seed", "out", "Units", "ValueError", "KeyboardInterrupt"):
        assert word in doc


def test_states_equal_the_cli_and_the_ensemble(tmp_path, runs):
    """coldblast.md.states: the CLI's impurity_states.csv row for row, and at a recorded time the
    ensemble's R_imp, V_imp and C_imp (the same realizations)."""
    _, _, _, result = runs
    t = float(result.estimates["V_imp"]["t"][-5])
    states = coldblast.md.states(t, realizations=4, seed=3, threads=2, out=tmp_path / "py", progress=False, t_max=50)
    from conftest import run_cli
    run_cli("md", "states", "--set", "t_max=50", "--realizations", 4, "--seed", 3, "--time", repr(t),
            "--out", tmp_path / "cli")
    assert data_lines(tmp_path / "py" / "impurity_states.csv") == data_lines(tmp_path / "cli" / "impurity_states.csv")
    assert states.t == t and states.r.shape == (16, 2) and states.v.shape == (16, 2)
    assert list(states.realization) == [k // 4 for k in range(16)]
    k = list(result.estimates["V_imp"]["t"]).index(t)
    v_imp = math.sqrt(np.mean(0.5 * (states.v ** 2).sum(axis=1)))
    r_imp = math.sqrt(np.mean(0.5 * ((states.r - states.r0) ** 2).sum(axis=1)))
    assert v_imp == pytest.approx(result.estimates["V_imp"]["mean"][k], rel=1e-12)
    assert r_imp == pytest.approx(result.estimates["R_imp"]["mean"][k], rel=1e-12)
    assert np.mean(states.collisions) == pytest.approx(result.estimates["C_imp"]["mean"][k], rel=1e-12)
    # the tracer continues them: trajectory i from state i, so at t its V_imp is theirs
    tracer = coldblast.tracer.run(background="tvns", start="states", start_states=tmp_path / "py" / "impurity_states.csv",
                                  progress=False, t_max=50)
    assert tracer.summary["trajectories"] == 16 and tracer.summary["start"] == "states"
    j = list(tracer.estimates["V_imp"]["t"]).index(t)
    assert tracer.estimates["V_imp"]["mean"][j] == pytest.approx(v_imp, rel=1e-12)


def test_states_bad_time_is_the_cli_error():
    with pytest.raises(ValueError) as error:
        coldblast.md.states(60, progress=False, t_max=50)
    assert str(error.value) == cli_error("md", "states", "--set", "t_max=50", "--time", 60)
