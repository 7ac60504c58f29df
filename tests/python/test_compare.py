"""coldblast.compare against `coldblast compare --format json` on the CLI tests' fixture run."""
import os

import pytest

import coldblast
from conftest import REPO, cli_error, cli_json

FIXTURE = os.path.join(REPO, "tests", "cli", "data", "run_T0_wrong")


@pytest.mark.parametrize("against", ["theory", "paper"])
def test_verdict_equals_cli(against):
    expected = cli_json("compare", "--no-report", FIXTURE, "--against", against, expect=3)
    verdict = coldblast.compare(FIXTURE, against=against)
    assert verdict == expected
    assert verdict["pass"] is False
    assert {v["name"]: v["pass"] for v in verdict["observables"]}["T0"] is False


def test_subset_and_report(tmp_path):
    expected = cli_json("compare", "--no-report", FIXTURE, "--observables", "R_imp,n0", "--until", 200)
    verdict = coldblast.compare(FIXTURE, observables=["R_imp", "n0"], until=200, out=tmp_path / "report",
                                figures=False)
    assert verdict == expected and verdict["pass"] is True
    assert (tmp_path / "report" / "verdict.json").exists()


@pytest.mark.parametrize("kwargs,flags", [
    ({"against": "md"}, ["--against", "md"]),
    ({"sigma": -1}, ["--sigma", -1]),
    ({"until": 0.5}, ["--until", 0.5]),
    ({"observables": ["speed"]}, ["--observables", "speed"]),
    ({"against": "hydro"}, ["--against", "hydro"]),  # the fixture has no lambda in summary.json
    ({"hydro_eos": "vdw"}, ["--hydro-eos", "vdw"]),
    ({"hydro_viscosity": True}, ["--hydro-viscosity", "on"]),  # a model option without --against hydro
    ({"allowance": -1}, ["--allowance", -1]),  # not the "default" sentinel it once was
])
def test_bad_input_is_the_cli_error(kwargs, flags):
    with pytest.raises(ValueError) as error:
        coldblast.compare(FIXTURE, **kwargs)
    assert str(error.value) == cli_error("compare", "--no-report", FIXTURE, *flags)


def test_not_a_run(tmp_path):
    with pytest.raises(ValueError) as error:
        coldblast.compare(tmp_path)
    assert str(error.value) == cli_error("compare", "--no-report", tmp_path)


@pytest.mark.parametrize("what", ["file", "fifo", "folder of other files"])
def test_out_that_is_not_a_report_folder_is_the_cli_error_and_stays(tmp_path, what):
    path = tmp_path / "out"
    if what == "file":
        path.write_text("precious\n")
    elif what == "fifo":
        os.mkfifo(path)
    else:
        path.mkdir()
        (path / "mine.txt").write_text("precious\n")
    with pytest.raises(ValueError) as error:
        coldblast.compare(FIXTURE, out=path, figures=False)
    assert str(error.value) == cli_error("compare", FIXTURE, "--no-figures", "--out", path)
    assert "--out = " in str(error.value)
    if what == "file":
        assert path.read_text() == "precious\n"
    elif what == "fifo":
        assert path.is_fifo()
    else:
        assert [p.name for p in path.iterdir()] == ["mine.txt"]


@pytest.mark.parametrize("kwargs,message", [
    ({"sigma": "2"}, "--sigma = '2' is not a number"),
    ({"until": True}, "--until = True is not a number"),
    ({"against": None}, "--against = None is not a string"),
    ({"figures": "no"}, "figures = 'no' is not True or False"),
    ({"observables": 5}, "--observables = 5 is not a name or a list of names"),
    ({"observables": ["R_imp", 3]}, "--observables = ['R_imp', 3] is not a name or a list of names"),
])
def test_argument_types_are_checked_by_name(kwargs, message):
    # Before: bool("no") is True, str(None) the name "None", list("R_imp") five one-letter names,
    # and float("2") passed; a bad type now fails before the run directory is read.
    with pytest.raises(ValueError) as error:
        coldblast.compare("no-such-run", **kwargs)
    assert str(error.value) == message


def test_observables_as_one_string_are_the_command_line_list():
    as_list = coldblast.compare(FIXTURE, observables=["R_imp", "n0"], until=200, figures=False)
    as_text = coldblast.compare(FIXTURE, observables="R_imp,n0", until=200, figures=False)
    assert [v["name"] for v in as_text["observables"]] == ["R_imp", "n0"]
    assert as_text == as_list


def test_viscous_hydro_verdict_equals_cli():
    """hydro_viscosity=True is --hydro-viscosity on: the same verdict, its model named viscous."""
    run = os.path.join(REPO, "data", "paper-2d")
    expected = cli_json("compare", "--no-report", run, "--against", "hydro", "--hydro-viscosity", "on", expect=3)
    verdict = coldblast.compare(run, against="hydro", hydro_viscosity=True, figures=False)
    assert verdict == expected
    assert verdict["hydro_model"]["viscosity"] is True
    assert verdict["hydro_model"]["description"].endswith("Enskog transport, viscous)")
