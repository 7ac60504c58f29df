"""coldblast.theory.exponents against `coldblast theory --format json`."""
from fractions import Fraction

import pytest

import coldblast
from conftest import cli_error, cli_json


@pytest.mark.parametrize("d", [1, 2, 3, 7])
def test_exponents_equal_cli(d):
    expected = cli_json("theory", "--d", d)
    e = coldblast.theory.exponents(d)
    assert list(e) == list(expected["exponents"])
    for name, entry in expected["exponents"].items():
        assert isinstance(e[name], Fraction)
        assert str(e[name]) == entry["rational"]
        assert float(e[name]) == entry["value"]
        assert str(e.in_R_over_lambda[name]) == entry["R_over_lambda"]["rational"]
    assert str(e.h_d) == expected["h_d"]["rational"] and str(e.omega_d) == expected["omega_d"]["rational"]
    assert e.pathological == expected["pathological"]
    for name, entry in expected["convection_diffusion"].items():
        assert str(e.convection_diffusion[name]) == entry["rational"]


def test_paper_table2():
    """The paper's Table 2 [table:scaling], typed in from the paper."""
    table2 = {2: ("2/5", "2/5", "-2/5", "-3/5", "-1/5", "-4/5"),
              3: ("52/175", "62/175", "-87/175", "-113/175", "-36/175", "-174/175")}
    for d, row in table2.items():
        e = coldblast.theory.exponents(d)
        assert tuple(e[n] for n in ("C_imp", "R_imp", "V_imp", "u_imp", "n0", "T0")) == tuple(map(Fraction, row))


@pytest.mark.parametrize("d", [0, 10001])
def test_bad_dimension_is_the_cli_error(d):
    with pytest.raises(ValueError) as error:
        coldblast.theory.exponents(d)
    assert str(error.value) == cli_error("theory", "--d", d)


@pytest.mark.parametrize("d", [2, 3])
def test_computed_prefactors_equal_cli(d):
    """`coldblast theory` prints the table of theory/computed_prefactors.cpp, value for value."""
    printed = cli_json("theory", "--d", d)["computed_prefactors"]
    table = coldblast.theory.computed_prefactors(d)
    assert len(table) > 0 and len(printed["entries"]) == len(table)
    for row, entry in zip(table, printed["entries"]):
        for key in ("observable", "t", "R_over_lambda", "value", "error", "source"):
            assert entry[key] == row[key]
        assert row["error"] > 0 and row["value"] > 0
        source = printed["sources"][str(row["source"])]
        assert source["command"] == row["command"] and source["trajectories"] == row["trajectories"]
        assert source["command"].startswith("coldblast tracer ")
    assert {row["observable"] for row in table} == {"R_imp", "V_imp", "C_imp"}
    assert coldblast.theory.computed_prefactors(7) == []
