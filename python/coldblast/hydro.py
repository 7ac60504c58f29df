"""The radial Navier-Stokes blast (``coldblast hydro core|euler``; paper Sec. III, Eqs. (13)-(16))."""
from types import SimpleNamespace

from . import _coldblast
from . import _progress
from ._arguments import flag, integer, number, text
from . import theory as _theory


def _run(euler, d, until, cells, viscosity, kappa_prefactor, progress, eos="ideal", phi=0.0, transport="dilute",
         start="self-similar", r0=0.0):
    label = "hydro euler" if euler else "hydro core"
    raw = _coldblast.hydro_run(euler, integer(d, "--d"), 0.0 if until is None else number(until, "--until"),
                               integer(cells, "--cells"), flag(viscosity, "--viscosity"),
                               None if kappa_prefactor is None else number(kappa_prefactor, "--kappa-prefactor"),
                               text(eos, "--eos"), number(phi, "--phi"), text(transport, "--transport"),
                               text(start, "--start"), number(r0, "--r0"),
                               _progress.callback(progress, label, "R/lambda", "{:.4g}"))
    return _result(raw)


def _result(raw):
    """The namespace of a result from its one schema (hydro/result_files.hpp): ``summary`` (the dict
    ``coldblast hydro --format json`` prints), its keys and its model's keys as attributes, and the
    tables of samples.csv, exponents.csv and the profiles as float64 arrays."""
    summary = raw["summary"]
    flat = {key: value for key, value in summary.items() if key not in ("exponents", "model")}
    result = SimpleNamespace(summary=summary, samples=raw["samples"], exponents=raw["exponents"],
                             profiles=raw["profiles"], **flat, **summary["model"])
    result.r0 = summary["model"]["r0_over_lambda"]  # the name of the argument
    if "exponents" in summary:  # core: the final running exponents (the theory's: ``theory``)
        result.final_exponents = {name: e["measured"] for name, e in summary["exponents"].items()}
    return result


def core(d=2, until=1e4, cells=0, viscosity=False, kappa_prefactor=None, eos="ideal", phi=0.0, transport="dilute",
         start="self-similar", r0=0.0, progress=True):
    """Heat-conducting blast up to R/lambda = until (the same call as ``coldblast hydro core``).

    Parameters
    ----------
    d : int
        1 planar, 2 cylindrical, 3 spherical.
    until : float
        R/lambda at the end, (2, 1e12] (lambda = mean free path, Eq. (5)); seconds for 1e4.
    cells : int
        Finite-volume cells, [16, 100000]; 0 = the mode's default (``_coldblast.default_core_cells`` here,
        ``default_euler_cells`` for :func:`euler`).
    viscosity : bool
        Shear viscosity mu = c_mu n lambda sqrt(T) on or off.
    kappa_prefactor : float or None
        c_kappa in [0, 1e6] of kappa = c_kappa n lambda sqrt(T); None = Chapman-Enskog.
    eos, phi, transport : str, float, str
        Equation of state ("ideal", "henderson" for d = 2, "carnahan-starling" for d = 3), ambient
        packing fraction (0: the library's default for a hard-particle EOS) and transport
        ("dilute" or "enskog"), as ``--eos --phi --transport`` (docs/hydro.md).
    start, r0 : str, float
        How the energy enters, as ``--start --r0``: "self-similar" (a smooth hot region at R/lambda = 2)
        or "hotspot" (E as heat at rest, uniform within the radius r0 at the ambient density: the MD's
        hot spot; r0 > 0 in mean free paths, r0/lambda; the times then count from the deposition;
        docs/hydro.md, "Starts").
    progress : bool, str or callable
        True: R/lambda and ETA as a tqdm bar in a Jupyter notebook (where tqdm is installed), as lines
        on stderr otherwise; "bar" or "lines" to choose; False: silent; callable(done, total).

    Returns
    -------
    types.SimpleNamespace with
        ``samples``: dict of float64 arrays (t, R_over_lambda, R, H, H_density, n0, T0, p0, energy,
        mass, energy_error, H_prefactor, n0_prefactor, T0_prefactor, p0_scaled), one entry per sample;
        ``exponents``: dict of float64 arrays of running exponents d ln X/d ln t (t, R_over_lambda,
        R, H, H_density, n0, T0) and in R/lambda (H_in_R, ...);
        ``profiles``: list of dicts (t, R and float64 arrays r, r_over_R, density, velocity,
        temperature, pressure, heat_flux), the last at R/lambda = until;
        ``summary``: the dict ``coldblast hydro core --format json`` prints (docs/cli.md), whose keys
        are also attributes: ``R_over_lambda``, ``prefactors``, ``p0_scaled``, ``lambda``,
        ``kappa_prefactor``, ``viscosity_prefactor``, ``A_reference``, ``A_measured``,
        ``energy_error``, ``energy_drift_before_projection``, ``cells``, ``wall_seconds``,
        ``rhs_evaluations``, and its model's: ``eos``, ``phi``, ``transport``, ``start``,
        ``r0_over_lambda`` (also ``r0``), ``start_R_over_lambda`` (the grid's R_ref/lambda at the start);
        ``final_exponents`` (H, n0, T0, R: summary["exponents"][X]["measured"]) and ``theory`` (the
        exact Fractions).
    Units: m = k_B = 1 with the CLI's E = 1, n = 1, a = 1/2 (lambda = 1 in 2D).
    Ctrl-C raises KeyboardInterrupt within a fraction of a second.
    """
    result = _run(False, d, until, cells, viscosity, kappa_prefactor, progress, eos, phi, transport, start, r0)
    exact = _theory.exponents(integer(d, "--d"))
    result.theory = {name: exact[name] for name in ("H", "n0", "T0", "R")}
    return result


def euler(d=2, until=500, cells=0, eos="ideal", phi=0.0, progress=True):
    """Euler limit (kappa = mu = 0) against the exact TvNS solution (``coldblast hydro euler``).

    Same arguments and result as :func:`core` (without final exponents), with the summary's TvNS
    check as attributes: ``A_measured``, ``A_exact``, ``A_relative_error``, ``profile_L1_error``
    ({density, velocity, pressure}), ``R_over_initial_width`` (``coldblast hydro euler --format json``).
    """
    return _run(True, d, until, cells, False, None, progress, eos, phi)
