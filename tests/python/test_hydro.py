"""coldblast.hydro.core against `coldblast hydro core --format json`."""
from fractions import Fraction

import numpy as np
import pytest

import coldblast
from conftest import cli_error, cli_json


def test_core_equals_cli_and_arrays():
    expected = cli_json("hydro", "core", "--until", 200, "--cells", 128)
    r = coldblast.hydro.core(until=200, cells=128, progress=False)
    for name in ("H", "n0", "T0", "R"):
        assert r.final_exponents[name] == expected["exponents"][name]["measured"]
        assert float(r.theory[name]) == expected["exponents"][name]["theory"]
    assert r.theory["T0"] == Fraction(-4, 5)
    assert r.R_over_lambda == expected["R_over_lambda"]
    assert r.prefactors == expected["prefactors"]
    assert r.energy_error == expected["energy_error"] and r.cells == 128
    n = len(r.samples["t"])
    assert n > 10
    for key, values in r.samples.items():
        assert values.dtype == np.float64 and values.shape == (n,), key
    assert np.all(np.diff(r.samples["R_over_lambda"]) > 0)
    m = len(r.exponents["t"])
    assert all(v.shape == (m,) for v in r.exponents.values())
    final = r.profiles[-1]
    assert final["r"].dtype == np.float64 and final["density"].shape == final["r"].shape
    # Energy conservation: total energy = E + what entered through the outer edge (projection on).
    assert np.max(np.abs(r.samples["energy_error"])) < 1e-10


def test_dense_core_equals_cli():
    expected = cli_json("hydro", "core", "--until", 50, "--cells", 64, "--eos", "henderson", "--phi", 0.118,
                        "--transport", "enskog")
    r = coldblast.hydro.core(until=50, cells=64, eos="henderson", phi=0.118, transport="enskog", progress=False)
    assert (r.eos, r.phi, r.transport) == ("henderson", 0.118, "enskog")
    for name in ("H", "n0", "T0", "R"):
        assert r.final_exponents[name] == expected["exponents"][name]["measured"]


def test_hotspot_core_equals_cli():
    expected = cli_json("hydro", "core", "--until", 20, "--cells", 64, "--start", "hotspot", "--r0", 0.25)
    r = coldblast.hydro.core(until=20, cells=64, start="hotspot", r0=0.25, progress=False)
    assert (r.start, r.r0, r.start_R_over_lambda) == ("hotspot", 0.25, 2.0)
    assert expected["model"]["start"] == "hotspot" and expected["model"]["r0_over_lambda"] == 0.25
    for name in ("H", "n0", "T0", "R"):
        assert r.final_exponents[name] == expected["exponents"][name]["measured"]
    assert r.samples["t"][0] > 0  # times count from the deposition at t = 0


def test_progress_callback_sees_R_over_lambda():
    seen = []
    coldblast.hydro.core(until=50, cells=64, progress=lambda x, until: seen.append((x, until)))
    assert seen and seen[-1][1] == 50 and seen[-1][0] >= 0.9 * 50


@pytest.mark.parametrize("kwargs,flags", [
    ({"d": 0}, ["--d", 0]),
    ({"cells": 8}, ["--cells", 8]),
    ({"until": 1.0}, ["--until", 1.0]),
    ({"kappa_prefactor": -1}, ["--kappa-prefactor", -1]),
    ({"eos": "vdw"}, ["--eos", "vdw"]),
    ({"transport": "magic"}, ["--transport", "magic"]),
    ({"eos": "henderson", "phi": 0.95}, ["--eos", "henderson", "--phi", 0.95]),
    ({"start": "kick"}, ["--start", "kick"]),
    ({"start": "hotspot"}, ["--start", "hotspot"]),
    ({"start": "hotspot", "r0": -0.5}, ["--start", "hotspot", "--r0", -0.5]),
    ({"r0": 0.3}, ["--r0", 0.3]),
])
def test_bad_input_is_the_cli_error(kwargs, flags):
    with pytest.raises(ValueError) as error:
        coldblast.hydro.core(progress=False, **kwargs)
    assert str(error.value) == cli_error("hydro", "core", *flags)


@pytest.mark.parametrize("call,name", [
    (lambda v: coldblast.hydro.core(d=v, until=50, cells=64, progress=False), "--d"),
    (lambda v: coldblast.hydro.core(until=50, cells=v, progress=False), "--cells"),
    (lambda v: coldblast.hydro.euler(d=v, until=50, progress=False), "--d"),
    (lambda v: coldblast.tvns(d=v), "--d"),
    (lambda v: coldblast.theory.exponents(v), "--d"),
    (lambda v: coldblast.compare("no-such-run", hydro_cells=v), "--hydro-cells"),
])
@pytest.mark.parametrize("value", [2.5, 64.0, True, "2"])
def test_integer_arguments_are_not_truncated(call, name, value):
    # int(2.5) is 2: before, tvns(d=2.5) solved d = 2 and hydro.core(cells=100.7) ran 100 cells.
    with pytest.raises(ValueError) as error:
        call(value)
    assert str(error.value) == f"{name} = {value!r} is not an integer"


def test_numpy_integers_are_integers():
    assert coldblast.tvns(d=np.int64(2)).A == coldblast.tvns(d=2).A
    assert coldblast.theory.exponents(np.int32(3))["R_imp"] == coldblast.theory.exponents(3)["R_imp"]


@pytest.mark.parametrize("call,message", [
    (lambda: coldblast.hydro.core(until="1e4", progress=False), "--until = '1e4' is not a number"),
    (lambda: coldblast.hydro.core(viscosity="no", progress=False), "--viscosity = 'no' is not True or False"),
    (lambda: coldblast.hydro.core(eos=None, progress=False), "--eos = None is not a string"),
    (lambda: coldblast.tvns(gamma="5/3"), "--gamma = '5/3' is not a number"),
    (lambda: coldblast.tracer.run(T=None, background="equilibrium"), "--T = None is not a number"),
    (lambda: coldblast.tracer.run(background=None), "--background = None is not a string"),
])
def test_argument_types_are_checked_by_name(call, message):
    # bool("no") is True: hydro.core(viscosity="no") used to switch the viscosity on.
    with pytest.raises(ValueError) as error:
        call()
    assert str(error.value) == message
