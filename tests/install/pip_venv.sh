#!/bin/sh
# `python -m pip install --no-build-isolation .` (README) into a venv of Debian's python3 with its
# numpy and pandas (--system-site-packages), offline (--no-index): pip's CMake build is for the
# venv's interpreter, and the package imports from another folder with its version and commit.
# To keep CI short, only the extension is compiled: the libraries come from this build
# (-DCOLDBLAST_LIBRARIES_FROM, docs/python.md); the full route is the same CMake code as BUILD_DIR's.
# With a 6th argument `borrow`, PYTHON is another interpreter of the same minor version (a pyenv
# Python): offline it has no numpy, so its venv borrows Debian's numpy and pandas through a .pth
# file, as a user would point a pyenv or conda Python at their own numpy; the build is for PYTHON.
# Usage: pip_venv.sh PYTHON SOURCE_DIR BUILD_DIR WORK_DIR VERSION [borrow]
set -eu
python=$1 source=$2 build=$3 work=$4 version=$5 numpy=${6:-system}
rm -rf "$work"
mkdir -p "$work"
if [ "$numpy" = borrow ]; then
  "$python" -m venv "$work/venv" || { echo "no venv from $python"; exit 1; }
  "$work/venv/bin/python" -c 'import sysconfig; print(sysconfig.get_path("purelib"))' >"$work/site"
  echo /usr/lib/python3/dist-packages >"$(cat "$work/site")/debian-dist-packages.pth"
else
  "$python" -m venv --system-site-packages "$work/venv" || { echo "no venv: Debian's python3-venv is missing (scripts/bootstrap.sh)"; exit 1; }
fi
venv=$work/venv/bin/python

cd "$source"
if ! CMAKE_ARGS="-DCOLDBLAST_LIBRARIES_FROM=$build" "$venv" -m pip install --no-build-isolation --no-index \
     --no-cache-dir --disable-pip-version-check -v . >"$work/pip.log" 2>&1; then
  tail -40 "$work/pip.log"
  exit 1
fi
grep -F -- "-- coldblast: Python module for $venv (" "$work/pip.log" || { echo "CMake did not build for $venv"; exit 1; }
grep "Successfully installed coldblast-" "$work/pip.log"

cd "$work"
"$venv" "$source/tests/install/check_import.py" "$("$venv" -c 'import sysconfig; print(sysconfig.get_path("platlib"))')" \
  "$version" --pip
