"""coldblast.reproduce against `coldblast reproduce --format json`: the same summary, number for number
(only wall times, the output paths and the run ids differ), the CLI's step lines as progress, the CLI's errors."""
import os

import pytest

import coldblast
from conftest import REPO, cli_error, cli_json

TINY = dict(realizations=4, hydro_until=50, tracer_trajectories=600, threads=2, figures=False)
TINY_FLAGS = ["--realizations", 4, "--hydro-until", 50, "--tracer-trajectories", 600, "--threads", 2, "--no-figures"]


def without_timings_and_paths(value):
    """The summary without wall times, rates, output paths and run ids (the only keys two runs may differ in)."""
    if isinstance(value, dict):
        return {k: without_timings_and_paths(v) for k, v in value.items()
                if "second" not in k and k not in ("out", "run_dir", "md_run", "run_id")}
    if isinstance(value, list):
        return [without_timings_and_paths(v) for v in value]
    return value


def test_summary_equals_cli(tmp_path):
    expected = cli_json("reproduce", *TINY_FLAGS, "--out", tmp_path / "cli")
    lines = []
    summary = coldblast.reproduce(out=tmp_path / "py", progress=lines.append, **TINY)
    assert summary["out"] == str(tmp_path / "py")
    assert without_timings_and_paths(summary) == without_timings_and_paths(expected)
    # the tracer step ran and was compared with the MD at t = 4000
    assert summary["tracer"]["trajectories"] == 600 and summary["tracer"]["transport"] == "enskog"
    assert [o["name"] for o in summary["tracer_against_md"]["observables"]] == ["R_imp", "V_imp", "C_imp"]
    assert all(o["t"] == 4000 for o in summary["tracer_against_md"]["observables"])
    # progress: the CLI's lines, every step once and in order
    steps = [line for line in lines if line.startswith("step ")]
    assert [s.split(":")[0] for s in steps] == [f"step {k}/6" for k in range(1, 7)]
    for name in ("REPORT.md", "summary.json", "tracer/summary.json", "report-tracer/tracer_vs_md.csv"):
        assert (tmp_path / "py" / name).exists(), name


@pytest.mark.parametrize("kwargs,flags", [
    ({"scale": "huge"}, ["--scale", "huge"]),
    ({"seed": -1}, ["--seed", -1]),
    ({"tracer_trajectories": 1}, ["--tracer-trajectories", 1]),
    ({"hydro_until": 5}, ["--hydro-until", 5]),
    ({"md_run": os.path.join(REPO, "data", "campaign3-3d")}, ["--md-run", os.path.join(REPO, "data", "campaign3-3d")]),
])
def test_bad_input_is_the_cli_error(tmp_path, kwargs, flags):
    with pytest.raises(ValueError) as error:
        coldblast.reproduce(out=tmp_path / "out", progress=False, **kwargs)
    assert str(error.value) == cli_error("reproduce", "--out", tmp_path / "out", *flags)
    assert not (tmp_path / "out").exists()  # refused before any step ran


@pytest.mark.parametrize("kwargs,message", [
    ({"realizations": 2.5}, "--realizations = 2.5 is not an integer"),
    ({"figures": "no"}, "figures = 'no' is not True or False"),
    ({"progress": 3}, "progress = 3 is not True, False or a callable(line)"),
])
def test_wrong_types_are_named(tmp_path, kwargs, message):
    with pytest.raises(ValueError, match=message.replace("(", r"\(").replace(")", r"\)")):
        coldblast.reproduce(out=tmp_path / "out", **kwargs)
