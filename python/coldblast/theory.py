"""The paper's scaling laws as exact fractions (``coldblast theory``; paper Table 2, Eqs. (4)-(12), Sec. IV)
and the impurity prefactors computed by ``coldblast tracer`` (theory/computed_prefactors.hpp)."""
from fractions import Fraction

from . import _coldblast
from ._arguments import integer as _integer


class Exponents(dict):
    """Time exponents t^alpha by name (R, H, R_imp, C_imp, V_imp, u_imp, n0, T0, D0) as Fractions.

    Attributes: ``d``; ``pathological`` (d = 1: no hydrodynamics); ``h_d`` (Eq. (4)) and ``omega_d``
    (Eq. (7)); ``in_R_over_lambda`` (the same exponents in R/lambda, a dict of Fractions);
    ``convection_diffusion`` (Sec. IV: drift, diffusion, spread, density, gaussian_coefficient).
    """

    def __repr__(self):
        items = ", ".join(f"{k}={v}" for k, v in self.items())
        return f"Exponents(d={self.d}: {items})"


def exponents(d=2):
    """Exact exponents of the paper for dimension d.

    Parameters
    ----------
    d : int
        Spatial dimension, 1 <= d <= 10000 (1 is pathological: the impurity is caged).

    Returns
    -------
    Exponents
        A dict of ``fractions.Fraction`` time exponents, e.g. ``exponents(2)["R_imp"] == Fraction(2, 5)``,
        with attributes ``in_R_over_lambda``, ``h_d``, ``omega_d``, ``convection_diffusion``.

    Raises ValueError (the CLI's message, e.g. ``--d = 0 is outside [1, 10000]``) for d out of range.
    """
    d = _integer(d, "--d")
    raw = _coldblast.theory_exponents(d)
    frac = lambda pair: Fraction(*pair)
    result = Exponents({name: frac(value) for name, value in raw["in_time"].items()})
    result.d = raw["d"]
    result.pathological = raw["pathological"]
    result.h_d = frac(raw["h_d"])
    result.omega_d = frac(raw["omega_d"])
    result.in_R_over_lambda = {name: frac(value) for name, value in raw["in_R_over_lambda"].items()}
    result.convection_diffusion = {name: frac(value) for name, value in raw["convection_diffusion"].items()}
    return result


def computed_prefactors(d=2):
    """The impurity prefactors of dimension d computed by ``coldblast tracer`` (not from the paper).

    Returns a list of dicts with ``observable`` (R_imp, V_imp, C_imp), ``t``, ``R_over_lambda``,
    ``value``, ``error`` (standard error), ``source``, ``command`` and ``trajectories`` of the run:
    X divided by the paper's estimate of X with its O(1) factor set to 1 (Eqs. (6), (8), (10)), the
    numbers ``coldblast theory --d D`` prints. Empty when none are known for d.

    Raises ValueError (the CLI's message) for d out of [1, 10000].
    """
    d = _integer(d, "--d")
    return _coldblast.theory_computed_prefactors(d)
