"""coldblast.tvns against `coldblast tvns --format json` (same inputs, identical numbers)."""
import math

import numpy as np
import pytest

import coldblast
from conftest import cli_error, cli_json


@pytest.mark.parametrize("kwargs,flags", [
    ({"d": 2}, ["--d", 2]),
    ({"d": 3}, ["--d", 3]),
    ({"d": 3, "gamma": 1.4}, ["--d", 3, "--gamma", 1.4]),
    ({"d": 2, "eos": "henderson", "phi": 0.118}, ["--d", 2, "--eos", "henderson", "--phi", 0.118]),
])
def test_amplitude_and_profile_equal_cli(kwargs, flags):
    at = [0.0, 0.1, 0.5, 0.9, 1.0]
    expected = cli_json("tvns", *flags, "--at", ",".join(map(str, at)))
    s = coldblast.tvns(**kwargs)
    for key in ("A", "A_error", "method_agreement", "A_ode", "gamma", "shock_compression", "cavity_radius",
                "density_exponent", "temperature_exponent", "case", "eos"):
        assert getattr(s, key) == expected[key], key
    p = s.profile(np.array(at))
    for i, point in enumerate(expected["profile"]):
        for field in ("density", "velocity", "pressure"):
            assert p[field][i] == point[field]
        temperature = point["temperature"]
        assert (math.isinf(p["temperature"][i]) if temperature is None else p["temperature"][i] == temperature)


def test_paper_amplitude():
    s = coldblast.tvns(d=2)
    assert abs(s.A - 0.351935906848599) < 1e-13 and 0 < s.A_error < 1e-12


def test_profile_is_vectorised_over_any_shape():
    s = coldblast.tvns(d=2)
    x = np.linspace(0.0, 1.0, 12).reshape(3, 4)
    p = s.profile(x)
    for field in ("density", "velocity", "pressure", "temperature", "r_over_R"):
        assert p[field].shape == (3, 4) and p[field].dtype == np.float64
    np.testing.assert_array_equal(p["r_over_R"], x)
    # Rankine-Hugoniot at the shock, ideal gas gamma = 2: rho1/rho0 = (gamma+1)/(gamma-1) = 3
    assert p["density"][2, 3] == pytest.approx(3.0, rel=1e-12)
    assert coldblast.tvns().profile(0.5)["density"].shape == ()


@pytest.mark.parametrize("kwargs,flags", [
    ({"d": 4}, ["--d", 4]),
    ({"gamma": 0.5}, ["--gamma", 0.5]),
    ({"eos": "vdw"}, ["--eos", "vdw"]),
    ({"eos": "henderson", "phi": 0.95}, ["--eos", "henderson", "--phi", 0.95]),
    ({"d": 3, "eos": "henderson", "phi": 0.1}, ["--d", 3, "--eos", "henderson", "--phi", 0.1]),
    ({"phi": 0.1}, ["--phi", 0.1]),
])
def test_bad_input_is_the_cli_error(kwargs, flags):
    with pytest.raises(ValueError) as error:
        coldblast.tvns(**kwargs)
    assert str(error.value) == cli_error("tvns", *flags)


def test_profile_outside_unit_interval():
    with pytest.raises(ValueError, match="1.5"):
        coldblast.tvns().profile(np.array([0.5, 1.5]))
