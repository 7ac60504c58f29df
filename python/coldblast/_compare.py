"""The verdict of an MD run against theory, the paper's Table 1 or hydro (``coldblast compare``)."""
import os

from . import _coldblast
from ._arguments import flag, integer, names, number, text
from . import _progress


def compare(run_dir, against="theory", sigma=2.0, allowance=None, window_decades=0.5, until=None,
            observables=None, hydro_cells=_coldblast.default_core_cells, hydro_eos=None, hydro_phi=None,
            hydro_transport=None, hydro_viscosity=None, md_run=None, out=None, figures=True):
    """Compare a run directory's running exponents with a reference (the same call as ``coldblast compare``).

    Parameters
    ----------
    run_dir : str or os.PathLike
        An ``md run`` output directory (CLI- or Python-made).
    against : str
        "theory" (exact rationals), "paper" (Table 1, d = 2 only) or "hydro" (Navier-Stokes at the MD's R/lambda).
    sigma : float
        Pass when |alpha_S - alpha_ref| <= sigma * error (+ allowance); (0, 10].
    allowance : float or None
        Finite-time allowance in [0, 1]; None: the reference's default (theory 0.10, hydro 0.05, paper 0).
    window_decades : float
        Window fit over the last w decades of recorded time, (0, 6].
    until : float or None
        Measure as of this time (in [second, last] recorded time); None: all times.
    observables : list of str, str or None
        Subset of R_imp, C_imp, V_imp, u_imp, T0, n0 (a list, or one string "R_imp,C_imp" as on the
        command line); None: all recorded.
    hydro_cells : int
        Navier-Stokes cells for against="hydro", [16, 100000].
    hydro_eos, hydro_phi, hydro_transport : str, float, str or None
        The Navier-Stokes model for against="hydro" (``--hydro-eos --hydro-phi --hydro-transport``);
        None: the default (the hard-particle EOS at the run's phi, Enskog transport; docs/compare.md).
    hydro_viscosity : bool or None
        Shear (and Enskog bulk) viscosity in that model (``--hydro-viscosity on|off``); None: off, the
        paper's conduction-only core (docs/verification.md, "Viscosity in the comparison").
    md_run : str, os.PathLike or None
        For a tracer run_dir (``coldblast tracer --out``): an MD run of the same scene, compared at
        every common time (``--md-run``: the verdict's "tracer_md" key; figures tracer_vs_md.png and
        tracer_p_imp.png and tracer_vs_md.csv in out).
    out : str, os.PathLike or None
        Report directory (report.md, verdict.json, exponents.csv, figures/), or None.
    figures : bool
        Draw the gnuplot figures into out/figures.

    Returns the verdict as a dict: the JSON of ``coldblast compare --format json`` (keys in
    docs/cli.md), with ``pass`` True or False (no exception for a failed verdict).
    Raises ValueError with the CLI's message for bad input or a directory that is not a run.
    """
    return _coldblast.compare(os.fspath(run_dir), text(against, "--against"), number(sigma, "--sigma"),
                              None if allowance is None else number(allowance, "--allowance"),
                              number(window_decades, "--window-decades"),
                              0.0 if until is None else number(until, "--until"),
                              names(observables, "--observables"), integer(hydro_cells, "--hydro-cells"),
                              "" if hydro_eos is None else text(hydro_eos, "--hydro-eos"),
                              None if hydro_phi is None else number(hydro_phi, "--hydro-phi"),
                              "" if hydro_transport is None else text(hydro_transport, "--hydro-transport"),
                              None if hydro_viscosity is None else flag(hydro_viscosity, "--hydro-viscosity"),
                              "" if md_run is None else os.fspath(md_run), "" if out is None else os.fspath(out),
                              flag(figures, "figures"), None)
