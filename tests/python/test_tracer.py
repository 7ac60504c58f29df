"""coldblast.tracer.run against `coldblast tracer` (same files, same numbers; the md background
too), the exact equilibrium collision rate, and coldblast.compare(..., md_run=...) against
`coldblast compare --md-run`."""
import json
import math
import os

import pytest

import coldblast
from conftest import REPO, cli_error, cli_json, run_cli

TINY = dict(t_max=50)  # the embedded 2D scene, cut at t = 50


def lines(path):
    return [l for l in path.read_text().splitlines() if not l.startswith(("# command: ", "# run_id: "))]


@pytest.mark.parametrize("background", ["tvns", "ns"])
def test_run_equals_cli(tmp_path, background):
    expected = cli_json("tracer", "--background", background, "--set", "t_max=50", "--trajectories", 64,
                        "--seed", 3, "--out", tmp_path / "cli")
    result = coldblast.tracer.run(background=background, trajectories=64, seed=3, threads=2,
                                  out=tmp_path / "py", progress=False, **TINY)
    for key in ("collision_rate", "collision_rate_error", "chi", "temperature_final", "rejection_rate"):
        assert result.summary[key] == expected[key], key
    for name in ("observables.csv", "blocks.csv", "p_imp.csv", "moments.csv", "prefactors.csv"):
        assert lines(tmp_path / "py" / name) == lines(tmp_path / "cli" / name), name
    # The returned tables are the files' numbers.
    r_imp = result.estimates["R_imp"]
    assert list(r_imp["t"]) == list(result.moments["t"]) and r_imp["t"][-1] <= 50.0
    assert result.moments["r2"].iloc[-1] == float(lines(tmp_path / "py" / "moments.csv")[-1].split(",")[1])


def test_kernel_is_passed_on_and_recorded():
    scalar = coldblast.tracer.run(background="tvns", kernel="scalar", trajectories=16, seed=3, progress=False, **TINY)
    assert scalar.summary["kernel"] == "scalar"
    auto = coldblast.tracer.run(background="tvns", trajectories=16, seed=3, progress=False, **TINY)
    assert auto.summary["kernel"] in ("avx512", "avx2", "sse4", "neon", "scalar")
    if auto.summary["kernel"] != "scalar":  # other deviates: other trajectories of the same law
        assert auto.summary["collision_rate"] != scalar.summary["collision_rate"]


def test_equilibrium_rate_is_the_exact_one():
    # Equal discs in a dilute bath (chi = 1): rate = n (2 * 2a) <|g|>, <|g|> = sqrt(pi T / (2 mu)), mu = 1/2.
    result = coldblast.tracer.run(background="equilibrium", start="thermal", T=1.5, trajectories=400, seed=5,
                                  progress=False, **TINY)
    s = result.summary
    n, a = s["scene"]["n"], s["scene"]["a"]
    exact = n * 2 * (2 * a) * math.sqrt(math.pi * 1.5)
    assert s["chi"] == 1.0
    assert s["collision_rate_exact"] == pytest.approx(exact, rel=1e-14)
    assert abs(s["collision_rate"] - exact) < 4 * s["collision_rate_error"]
    assert abs(s["temperature_final"] - 1.5) < 4 * s["temperature_final_error"]


def test_compare_md_run_equals_cli(tmp_path):
    coldblast.tracer.run(background="tvns", trajectories=64, seed=3, out=tmp_path / "tracer", progress=False, **TINY)
    coldblast.md.run(realizations=4, seed=3, out=tmp_path / "md", progress=False, block_size=1, **TINY)
    expected = cli_json("compare", "--no-report", tmp_path / "tracer", "--md-run", tmp_path / "md", "--sigma", 10, "--allowance", 1,
                        "--no-figures")
    verdict = coldblast.compare(tmp_path / "tracer", md_run=tmp_path / "md", sigma=10, allowance=1, figures=False)
    assert verdict == expected
    names = [o["name"] for o in verdict["tracer_vs_md"]["observables"]]
    assert {"R_imp", "V_imp", "C_imp"} <= set(names)


@pytest.mark.parametrize("kwargs,flags", [
    ({"background": "plasma"}, ["--background", "plasma"]),
    ({"background": "equilibrium", "T": -1.0}, ["--background", "equilibrium", "--T", -1]),
    ({"trajectories": 0.5}, None),
    ({"kernel": "simd"}, ["--kernel", "simd"]),
])
def test_bad_input_is_the_cli_error(kwargs, flags):
    with pytest.raises(ValueError) as error:
        coldblast.tracer.run(progress=False, **kwargs)
    if flags is not None:
        assert str(error.value) == cli_error("tracer", *flags)
    else:
        assert "--trajectories = 0.5 is not an integer" in str(error.value)


def test_compare_md_run_missing(tmp_path):
    coldblast.tracer.run(background="tvns", trajectories=16, seed=3, out=tmp_path / "tracer", progress=False, **TINY)
    with pytest.raises(ValueError) as error:
        coldblast.compare(tmp_path / "tracer", md_run="/nonexistent", figures=False)
    assert str(error.value) == cli_error("compare", "--no-report", tmp_path / "tracer", "--md-run", "/nonexistent", "--no-figures")


def test_out_that_is_a_file_is_the_cli_error(tmp_path):
    path = tmp_path / "file"
    path.write_text("precious\n")
    with pytest.raises(ValueError) as error:
        coldblast.tracer.run(background="tvns", trajectories=4, out=path, progress=False, **TINY)
    assert str(error.value) == cli_error("tracer", "--background", "tvns", "--trajectories", 4, "--out", path)
    assert str(error.value).startswith(f"--out = {path} is a regular file")
    with pytest.raises(ValueError) as error:
        coldblast.md.run(realizations=1, out=path, progress=False, **TINY)
    assert str(error.value) == cli_error("md", "run", "--set", "t_max=50", "--out", path)
    assert path.read_text() == "precious\n"


def test_scene_snapshot_times_do_not_refuse_a_shorter_t_max():
    # scenes/paper-2d.toml lists md snapshot times up to 2000; the tracer records none.
    scene = os.path.join(REPO, "scenes", "paper-2d.toml")
    result = coldblast.tracer.run(scene, background="tvns", trajectories=8, progress=False, t_max=1000)
    assert result.estimates["R_imp"]["t"][-1] <= 1000.0
    assert "snapshot_times = []" in result.summary["scene_toml"]


def test_md_background_equals_cli(tmp_path):
    # tracer.run(background="md", md_run=DIR) is `coldblast tracer --background md --md-run DIR`:
    # the MD run's scene by default, the same files, the MD run's id and path in summary.json.
    md = tmp_path / "md"
    coldblast.md.run(realizations=4, seed=3, out=md, progress=False, block_size=1,
                     observables=["R_imp", "V_imp", "C_imp", "R", "profiles", "p_imp"], **TINY)
    run_cli("tracer", "--background", "md", "--md-run", md, "--trajectories", 64, "--out", tmp_path / "cli")
    coldblast.tracer.run(background="md", md_run=md, trajectories=64, out=tmp_path / "py", progress=False)
    for name in ("observables.csv", "blocks.csv", "p_imp.csv", "moments.csv", "prefactors.csv"):
        assert lines(tmp_path / "py" / name) == lines(tmp_path / "cli" / name), name
    summary = json.loads((tmp_path / "py" / "summary.json").read_text())
    assert summary["background"] == "md"
    assert summary["md_run"] == str(md)
    assert summary["md_run_id"] == json.loads((md / "summary.json").read_text())["run_id"]
    assert summary["scene"]["t_max"] == 50  # the MD run's scene
    for kwargs, flags in (({}, []), ({"md_run": tmp_path / "none"}, ["--md-run", tmp_path / "none"]),
                          ({"md_run": md, "E": 20}, ["--md-run", md, "--set", "E=20"])):
        with pytest.raises(ValueError) as error:
            coldblast.tracer.run(background="md", progress=False, **kwargs)
        assert str(error.value) == cli_error("tracer", "--background", "md", *flags)


def test_hotspot_start_takes_r0_and_names_its_errors_as_the_cli():
    """start="hotspot", r0=R0 is `tracer --start hotspot --r0 R0`: the NS hot spot, r0 recorded; r0 without
    the hot spot, or outside the MD's range, is the CLI's exit-2 message."""
    r = coldblast.tracer.run(start="hotspot", r0=5, cells=64, trajectories=32, progress=False)
    assert r.summary["start"] == "hotspot" and r.summary["r0"] == 5.0
    assert "hot-spot start r0 = 0.75 lambda" in r.summary["background_description"]
    with pytest.raises(ValueError, match="--r0 = 5 is the radius of a hot spot: it needs --start hotspot"):
        coldblast.tracer.run(r0=5, progress=False)
    with pytest.raises(ValueError, match=r"--r0 = 1 is outside \[2\.9"):
        coldblast.tracer.run(start="hotspot", r0=1, progress=False)
