"""The paper end to end (``coldblast reproduce``): A_2, A_3, the Navier-Stokes core, an MD ensemble
of the paper's 2D scene, the kinetic tracer of its impurity and the comparisons, with reports."""
import os
import sys

from . import _coldblast
from ._arguments import flag, integer, number, text


def _line_callback(progress):
    """progress: True (lines on stderr, as the CLI prints them), False/None (silent) or a callable(line)."""
    if progress is True:
        return lambda line: print("reproduce: " + line, file=sys.stderr, flush=True)
    if progress is False or progress is None:
        return None
    if not callable(progress):
        raise ValueError(f"progress = {progress!r} is not True, False or a callable(line)")
    return progress


def reproduce(scale="quick", out="coldblast-reproduce", threads=0, seed=1, realizations=None, hydro_until=None,
              md_run=None, tracer_trajectories=None, figures=True, progress=True):
    """Run every step of ``coldblast reproduce`` and return its summary.

    Parameters
    ----------
    scale : str
        "quick" (384 MD realizations, under a minute on 2 cores) or "paper" (the paper's 3e4).
    out : str or os.PathLike
        Output directory: REPORT.md, table1.md, summary.json, tvns.json, hydro/, md/, tracer/ and the
        report folders (report-theory/, report-paper/, report-hydro/, report-tracer/).
    threads : int
        MD and tracer worker threads, [0, 1024]; 0: all hardware threads. The numbers do not depend on it.
    seed : int
        Master seed of the MD ensemble and of the tracer, >= 0.
    realizations : int or None
        MD realizations (at least 2); None: the scale's default.
    hydro_until : float or None
        Navier-Stokes run up to this R/lambda, [20, 1e8]; None: the scale's default (1e4, 1e6).
    md_run : str, os.PathLike or None
        An existing ``md run`` directory of the paper's scene to use instead of the MD step.
    tracer_trajectories : int or None
        Kinetic tracer trajectories (at least 2); None: the scale's default (1e5, 1e6).
    figures : bool
        Draw the gnuplot figures of the reports.
    progress : bool or callable
        True: the CLI's step lines on stderr; False: silent; a callable receives each line (str).

    Returns the summary as a dict: the JSON of ``coldblast reproduce --format json`` (keys in
    docs/cli.md: A_2, A_3, hydro, md, against_theory, against_paper, against_hydro, tracer,
    tracer_against_md, ...). Raises ValueError with the CLI's message for bad input (before any
    step runs), KeyboardInterrupt on Ctrl-C.
    """
    return _coldblast.reproduce(text(scale, "--scale"), os.fspath(out), integer(threads, "--threads"),
                                integer(seed, "--seed"), 0 if realizations is None else integer(realizations,
                                                                                                 "--realizations"),
                                0.0 if hydro_until is None else number(hydro_until, "--hydro-until"),
                                "" if md_run is None else os.fspath(md_run),
                                0 if tracer_trajectories is None else integer(tracer_trajectories,
                                                                              "--tracer-trajectories"),
                                flag(figures, "figures"), _line_callback(progress))
