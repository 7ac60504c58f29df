"""Builds the Python module coldblast with CMake for the interpreter that runs pip (pyproject.toml):

    python -m pip install --no-build-isolation .

CMake configures the project in build/pip/ with -DPython3_EXECUTABLE=<this interpreter> and builds
the target _coldblast (the static libraries and the pybind11 extension); the extension and the
generated _version.py join the pure-Python package python/coldblast/ in the wheel. The environment
variable CMAKE_ARGS adds CMake options (as in pybind11's cmake_example), e.g.
-DCOLDBLAST_LIBRARIES_FROM=$PWD/build to link the libraries of an up-to-date build instead of
compiling them again, or -DCMAKE_CXX_COMPILER_LAUNCHER=ccache. CMAKE_BUILD_PARALLEL_LEVEL sets the
parallel jobs (default: every core). `pip install -v` shows CMake's progress.
"""
import hashlib
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent
BUILD_BASE = Path("build") / "pip"  # beside the CMake build of scripts/bootstrap.sh, ignored by git


def cmake(*args):
    try:
        subprocess.run(["cmake", *map(str, args)], check=True)
    except FileNotFoundError:
        sys.exit("coldblast: building the module needs cmake and the Debian packages scripts/bootstrap.sh installs")


def version():
    """project(VERSION) of CMakeLists.txt with the git commit, as cmake/build_info.cmake writes
    coldblast.__version__ (one home for both)."""
    project = re.search(r"project\(coldblast VERSION ([0-9.]+)", (ROOT / "CMakeLists.txt").read_text())[1]
    with tempfile.TemporaryDirectory() as folder:
        output = Path(folder) / "_version.py"
        cmake(f"-DSOURCE_DIR={ROOT}", f"-DVERSION={project}", f"-DPYTHON_OUTPUT={output}",
              "-P", ROOT / "cmake" / "build_info.cmake")
        return re.search(r'__version__ = "(.*)"', output.read_text())[1]


class CMakeBuild(build_ext):
    """Builds the extension with the project's CMake, not with setuptools' compiler calls."""

    def build_extension(self, ext):
        target = Path(self.get_ext_fullpath(ext.name)).resolve()
        extra = shlex.split(os.environ.get("CMAKE_ARGS", ""))
        # One CMake tree per interpreter and CMAKE_ARGS, so that no cached option of another build leaks in.
        key = hashlib.sha256("\n".join([sys.executable, *extra]).encode()).hexdigest()[:12]
        build = Path(self.build_temp).resolve() / f"cmake-{key}"
        print(f"coldblast: building the module for {sys.executable} in {build}", file=sys.stderr)
        cmake("-S", ROOT, "-B", build, "-DCMAKE_BUILD_TYPE=Release", f"-DPython3_EXECUTABLE={sys.executable}",
              "-DCOLDBLAST_PYTHON=ON", "-DCOLDBLAST_PYTHON_REQUIRED=ON", "-DCOLDBLAST_BUILD_TESTS=OFF", *extra)
        jobs = [] if "CMAKE_BUILD_PARALLEL_LEVEL" in os.environ else ["-j", os.cpu_count() or 1]
        cmake("--build", build, "--target", "_coldblast", *jobs)
        package = build / "python" / "coldblast"
        target.parent.mkdir(parents=True, exist_ok=True)
        self.built_package = target.parent
        for name in (target.name, "_version.py"):
            if not (package / name).is_file():
                sys.exit(f"coldblast: CMake built no {package / name}; the module is built for "
                         f"{sys.executable}, whose extension suffix CMake must agree with")
            shutil.copyfile(package / name, target.parent / name)

    def copy_extensions_to_source(self):
        """An editable install (pip install -e) imports python/coldblast/ itself: the extension and
        the generated _version.py go there (both ignored by git)."""
        super().copy_extensions_to_source()
        self.copy_file(str(self.built_package / "_version.py"), str(ROOT / "python" / "coldblast" / "_version.py"),
                       level=self.verbose)


(ROOT / BUILD_BASE).mkdir(parents=True, exist_ok=True)
setup(
    version=version(),
    packages=["coldblast"],
    package_dir={"coldblast": "python/coldblast"},
    ext_modules=[Extension("coldblast._coldblast", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": str(BUILD_BASE)}, "egg_info": {"egg_base": str(BUILD_BASE)}},
    zip_safe=False,
)
