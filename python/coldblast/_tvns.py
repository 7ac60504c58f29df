"""The exact Taylor-von Neumann-Sedov blast (``coldblast tvns``; paper Eq. (1), Eqs. (18a,b))."""
import numpy as np

from . import _coldblast
from ._arguments import integer, number, text


class Tvns:
    """A solved TvNS blast.

    Attributes
    ----------
    A, A_error : float
        Amplitude of Eq. (1), R = (E t^2 / (A n))^(1/(d+2)), and its absolute error estimate
        (two independent methods; ~1e-14 for the ideal gas).
    d, gamma, eos, phi, tolerance, case, method_agreement, A_closed_form, A_ode,
    shock_compression, shock_packing_fraction, cavity_radius, density_exponent, temperature_exponent
        As in ``coldblast tvns --format json``.
    """

    def __init__(self, solution):
        self._solution = solution
        for name in ("d", "gamma", "eos", "phi", "tolerance", "A", "A_error", "method_agreement", "A_closed_form",
                     "A_ode", "case", "shock_compression", "shock_packing_fraction", "cavity_radius",
                     "density_exponent", "temperature_exponent"):
            setattr(self, name, getattr(solution, name))

    def profile(self, xi):
        """Self-similar profile at r/R = xi (scalar or numpy array of any shape, values in [0, 1]).

        Returns a dict of float64 arrays shaped like xi: ``density`` rho/rho0, ``velocity`` u/Rdot,
        ``pressure`` p/(rho0 Rdot^2), ``temperature`` T/Rdot^2 (+inf where the density vanishes),
        and ``r_over_R``. Raises ValueError for xi outside [0, 1].
        """
        x = np.asarray(xi, dtype=np.float64)
        return self._solution.profile(x)

    def __repr__(self):
        return f"Tvns(d={self.d}, eos={self.eos!r}, gamma={self.gamma:.15g}, phi={self.phi}, A={self.A!r} ± {self.A_error:.2g})"


def tvns(d=2, gamma=None, eos="ideal", phi=0.0, tolerance=1e-13):
    """Solve the exact TvNS blast (the same call as ``coldblast tvns``).

    Parameters
    ----------
    d : int
        1 planar, 2 cylindrical, 3 spherical.
    gamma : float or None
        Adiabatic index in [1.001, 1000], ideal EOS only; None means 1 + 2/d.
    eos : str
        "ideal", "henderson" (hard discs, d = 2) or "carnahan-starling" (hard spheres, d = 3).
    phi : float
        Ambient packing fraction for a hard-particle EOS: henderson (0, 0.89286),
        carnahan-starling (0, 0.686) (the ODE stalls above; docs/stress.md); 0 for the ideal gas.
    tolerance : float
        Requested relative accuracy of A, [1e-14, 1e-3].

    Returns a :class:`Tvns`. Raises ValueError with the CLI's message for bad input.
    """
    return Tvns(_coldblast.tvns_solve(integer(d, "--d"), 0.0 if gamma is None else number(gamma, "--gamma"),
                                      text(eos, "--eos"), number(phi, "--phi"), number(tolerance, "--tolerance")))
