"""The impurity's kinetic equation, paper Eq. (36), by exact null-collision Monte Carlo in a
Navier-Stokes, TvNS or equilibrium host background (``coldblast tracer``; docs/kinetic.md)."""
import os

from . import _coldblast
from . import _progress
from ._run import Run
from ._signals import sigterm_stops
from ._arguments import integer, number, text
from .md import scene_arguments


def run(scene=None, background="ns", trajectories=None, threads=1, seed=None, out=None, transport="dilute",
        start="kick", start_time=None, T=1.0, phi=None, frames_per_decade=40, cells=_coldblast.default_core_cells,
        progress=True, start_states=None, kernel="auto", overwrite=False, resume=None, md_run=None, r0=None,
        **overrides):
    """Run an ensemble of impurity trajectories (the same call as ``coldblast tracer``).

    Parameters
    ----------
    scene : None, str, os.PathLike or dict
        The MD scene the tracer matches (keys of ``md run``: d, n, a, E, impurities.*, t_min, t_max,
        seed, block_size): None for the embedded default scene, a TOML path, or a dict.
    background : str
        "ns" (the Navier-Stokes core), "tvns" (exact Euler), "equilibrium" (uniform bath) or "md"
        (an MD run's own measured mean fields: ``md_run``).
    md_run : str, os.PathLike or None
        background="md": an ``md run`` folder that recorded the observables profiles and R (``coldblast
        tracer --md-run``); its scene is the tracer's when ``scene`` is None (d, n, a, E and the
        impurities must agree).
    trajectories : int or None
        Impurity trajectories, >= 1; None: the scene's realizations x impurities.count.
    threads : int
        Worker threads, [1, 1024]; the numbers do not depend on it (bit-identical).
    seed : int or None
        Master seed >= 0; None: the scene's. Trajectory i is seeded from (seed, i).
    out : str, os.PathLike or None
        Run directory as ``coldblast tracer --out`` (``coldblast compare`` reads it): one run, every
        finished block kept in out/checkpoint meanwhile (``coldblast tracer --resume out``
        continues a stopped run); a folder holding another run's files is refused unless
        ``overwrite``. None writes nothing.
    overwrite : bool
        Replace the files of another run in ``out`` (exactly those of its manifest.json).
    resume : str, os.PathLike or None
        Continue the stopped run in this output directory (``coldblast tracer --resume``): its
        scene and options come from its checkpoint; an argument given again (other than its
        default) must agree with them, else ValueError naming it and both values.
    transport : str
        "dilute" (chi = 1; the ideal-gas Navier-Stokes) or "enskog" (chi(n) at contact; with "ns" the dense
        Navier-Stokes at the scene's packing fraction, the prediction for its MD; not with "tvns").
    start : str
        "kick" (the MD's kick, E shared by the impurities), "hotspot" (the MD's hot spot of radius
        ``r0``: the impurity among the particles nearest the centre, E a Maxwellian of every particle
        within r0, in the Navier-Stokes hot spot), "single" (the MD's single kicked host: the impurity
        at rest near the centre, as the MD places it), "thermal" (local Maxwellian) or "states" (the MD's own impurities:
        ``start_states``).
    r0 : float or None
        start="hotspot": the hot spot's radius, a length as the scene's start.r0 (not
        ``coldblast.hydro.core``'s r0/lambda); None: the scene's start.r0. Only with start="hotspot".
    start_states : str, os.PathLike or None
        start="states": an impurity_states.csv of ``coldblast md states`` (or ``coldblast.md.states``
        with ``out``) of the same scene; trajectory i starts from state i at the file's time.
    start_time : float or None
        Start time >= 0; None: the scene's t_min (ns, tvns; t_min/1024 for start="hotspot"), 0 for
        equilibrium.
    T, phi : float, float or None
        Equilibrium background only: bath temperature (> 0) and packing fraction (None: the scene's).
    frames_per_decade, cells : int
        ns background: stored frames per decade of R/lambda [4, 400] and Navier-Stokes cells [64, 4096].
    kernel : str
        "auto" (the widest vector kernel the CPU runs, for ns and tvns; else the scalar loop), "avx512",
        "avx2", "sse4", "neon" or "scalar": the same process with other deviates, so other sample paths;
        the summary's "kernel" says which ran.
    progress : bool, str or callable
        True: blocks done and ETA as a tqdm bar in a Jupyter notebook (where tqdm is installed), as lines
        on stderr otherwise; "bar" or "lines" to choose; False: silent; callable(done, total).
    **overrides
        Scene keys to override, as ``--set key=value`` (``t_max=500``, ``impurities={"count": 2}``).

    Returns
    -------
    coldblast.Run, the object ``coldblast.read_run(out)`` gives for the folder (equal DataFrames):
        ``observables`` (R_imp, V_imp, C_imp, u_imp, ...; ``estimate(name)``, ``estimates``),
        ``blocks``, ``p_imp``, ``moments`` (DataFrame of moments.csv: t, r2, r4_over_r2_squared,
        v2, v4_over_v2_squared and their _stderr), ``prefactors`` (prefactors.csv), ``summary``
        (summary.json: collision_rate, collision_rate_error, chi, temperature_final,
        rejection_rate, ...; docs/kinetic.md), ``directory`` (``out`` or None).

    Raises ValueError with the CLI's exit-2 message for bad input (e.g. ``--background = plasma is
    not one of ...``), KeyboardInterrupt on Ctrl-C (with ``out`` every finished block stays in
    out/checkpoint, and ``run(resume=out)`` continues it).
    """
    if resume is not None:
        if out is not None and os.path.normpath(os.fspath(out)) != os.path.normpath(os.fspath(resume)):
            raise ValueError(f"resume = {os.fspath(resume)} must be the output directory (out = {os.fspath(out)})")
        out = resume
    # The arguments given other than their defaults: with resume, each must agree with the checkpoint.
    given = [flag for flag, value, default in (
        ("SCENE", scene, None), ("--set", overrides or None, None), ("--seed", seed, None),
        ("--background", background, "ns"), ("--transport", transport, "dilute"), ("--start", start, "kick"),
        ("--trajectories", trajectories, None), ("--T", T, 1.0), ("--phi", phi, None),
        ("--start-time", start_time, None), ("--frames-per-decade", frames_per_decade, 40),
        ("--cells", cells, _coldblast.default_core_cells),
        ("--start-states", start_states, None), ("--kernel", kernel, "auto"), ("--md-run", md_run, None),
        ("--r0", r0, None))
        if value != default]
    scene_file, scene_text, sets = scene_arguments(scene, overrides)
    with sigterm_stops():
        raw = _coldblast.tracer_run(scene_file, scene_text, sets, None if seed is None else integer(seed, "--seed"),
                                    text(background, "--background"), text(transport, "--transport"),
                                    text(start, "--start"),
                                    0 if trajectories is None else integer(trajectories, "--trajectories"),
                                    integer(threads, "--threads"), number(T, "--T"),
                                    None if phi is None else number(phi, "--phi"),
                                    0.0 if start_time is None else number(start_time, "--start-time"),
                                    integer(frames_per_decade, "--frames-per-decade"), integer(cells, "--cells"),
                                    "" if start_states is None else os.fspath(start_states),
                                    text(kernel, "--kernel"), "" if md_run is None else os.fspath(md_run),
                                    0.0 if r0 is None else number(r0, "--r0"),
                                    "" if out is None else os.fspath(out), resume is not None,
                                    bool(overwrite), given, _progress.callback(progress, "tracer", "blocks"))
    return Run(raw, out, "tracer")
