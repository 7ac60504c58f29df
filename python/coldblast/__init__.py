"""coldblast: a blast in a zero-temperature hard-sphere gas, from Python.

The same C++ library as the ``coldblast`` command line (pybind11 extension ``_coldblast``); numbers
are identical to the CLI's for the same inputs. Units everywhere: m = 1, k_B = 1, ``a`` is the
particle radius (diameter 2a), T means k_B T.

- ``coldblast.theory.exponents(d)``: the paper's exact exponents (fractions.Fraction).
- ``coldblast.tvns(d=2, gamma=None, eos="ideal", phi=0)``: exact Taylor-von Neumann-Sedov blast,
  amplitude A_d of Eq. (1) with its error, and the self-similar profile over numpy arrays.
- ``coldblast.hydro.core(d=2, until=1e4, ...)``: the radial Navier-Stokes blast (numpy arrays).
- ``coldblast.md.run(scene, realizations=..., threads=..., seed=..., out=None, **overrides)``:
  an MD ensemble; estimates per observable (t, mean, stderr) and the summary.
- ``coldblast.tracer.run(scene, background="ns", trajectories=..., ...)``: the impurity's kinetic
  equation (Eq. 36) by Monte Carlo (``coldblast tracer``); estimates, moments and the summary.
- ``coldblast.read_run(dir)``: a run directory (CLI- or Python-made) as pandas DataFrames.
- ``coldblast.compare(run_dir, against="theory", md_run=None)``: the verdict of ``coldblast compare`` as a dict.
- ``coldblast.write_gsd(run_dir, path=None, realization=0)``: a run's snapshots as a GSD file (hoomd schema,
  for OVITO and freud); also ``python3 -m coldblast gsd RUN_DIR [-o FILE]``.
- ``coldblast.reproduce(scale="quick", out="coldblast-reproduce")``: the paper end to end
  (``coldblast reproduce``); its summary as a dict.

``coldblast.__version__`` is the version of the top CMakeLists.txt's project() with the git commit
of the build as a PEP 440 local label (``0.1.0+a21aaf8c1234``; ``coldblast --version`` prints
``coldblast 0.1.0 (a21aaf8c1234)``); ``coldblast.__commit__`` is the commit alone.

Bad input raises ValueError with the CLI's exit-2 message; Ctrl-C raises KeyboardInterrupt within
a fraction of a second and leaves no half-written file. Tour: docs/python.md.
"""
from ._version import __commit__, __version__
from . import _coldblast
from . import hydro, md, theory, tracer
from ._run import Run, read_run
from ._tvns import Tvns, tvns
from ._compare import compare
from ._reproduce import reproduce
from ._gsd import write_gsd

__all__ = ["theory", "tvns", "Tvns", "hydro", "md", "tracer", "read_run", "Run", "compare", "reproduce", "write_gsd"]
