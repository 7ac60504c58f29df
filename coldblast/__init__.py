"""Development shim: lets Debian's ``/usr/bin/python3 -c "import coldblast"`` work from the repository
root without installing (elsewhere: PYTHONPATH=/path/to/coldblast/build/python).

It loads the package that scripts/bootstrap.sh builds into build/python/coldblast (or
$COLDBLAST_BUILD_DIR/python/coldblast) for /usr/bin/python3. An installed coldblast (``python -m pip
install --no-build-isolation .`` into any Python, or ``cmake --install build``) does not need this
file. Sources: python/coldblast (Python) and python/_coldblast.cpp (the extension).
"""
import importlib.util
import os
import sys

_root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
_package = os.path.join(os.environ.get("COLDBLAST_BUILD_DIR") or os.path.join(_root, "build"), "python", "coldblast")
if not os.path.isfile(os.path.join(_package, "__init__.py")):
    raise ImportError(f"coldblast is not built: {_package} is missing; run `bash scripts/bootstrap.sh` "
                      "(it needs Debian's python3-dev and pybind11-dev)")
_spec = importlib.util.spec_from_file_location(__name__, os.path.join(_package, "__init__.py"),
                                               submodule_search_locations=[_package])
_module = importlib.util.module_from_spec(_spec)
sys.modules[__name__] = _module
try:
    _spec.loader.exec_module(_module)
except ImportError as error:
    del sys.modules[__name__]
    raise ImportError(f"{error}; build/ is made for Debian's /usr/bin/python3 with python3-numpy and "
                      f"python3-pandas, this is {sys.executable}: use /usr/bin/python3, or install coldblast "
                      "into this Python (with numpy and pandas): python -m pip install --no-build-isolation . "
                      "(docs/python.md)") from error
