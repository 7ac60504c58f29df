#!/bin/sh
# `cmake --install BUILD --prefix P` (README): P/bin/coldblast prints the version and the commit and
# runs a subcommand on an installed scene, P/share/coldblast/scenes holds the source's scenes, and
# the Python package in P/SITE imports from another folder with the program's version and commit.
# Usage: cmake_install.sh CMAKE BUILD_DIR WORK_DIR SITE PYTHON VERSION SOURCE_DIR
set -eu
cmake=$1 build=$2 work=$3 site=$4 python=$5 version=$6 source=$7
prefix=$work/prefix
rm -rf "$work"
mkdir -p "$work"
"$cmake" --install "$build" --prefix "$prefix" >"$work/install.log"
cd "$work"  # nothing of the source or build tree is reachable from here

program=$("$prefix/bin/coldblast" --version)
echo "$program"
commit=${program#"coldblast $version ("}
commit=${commit%")"}
[ "$program" = "coldblast $version ($commit)" ] || { echo "--version: expected 'coldblast $version (COMMIT)'"; exit 1; }
if [ "$commit" != unknown ]; then
  git -C "$source" cat-file -e "${commit%-dirty}^{commit}" || { echo "--version: $commit is no commit of $source"; exit 1; }
fi

count=0
for scene in "$source"/scenes/*.toml; do
  cmp "$scene" "$prefix/share/coldblast/scenes/$(basename "$scene")"
  count=$((count + 1))
done
[ "$count" -gt 0 ] && [ "$(ls "$prefix/share/coldblast/scenes" | wc -l)" -eq "$count" ]
echo "$count scenes in $prefix/share/coldblast/scenes"

"$prefix/bin/coldblast" tracer "$prefix/share/coldblast/scenes/paper-2d.toml" --background tvns --set t_max=50 \
  --trajectories 64 --out "$work/tracer" 2>/dev/null >"$work/tracer.txt"
grep -q "^tracer (tvns background), scene paper-2d (d = 2): 64 trajectories" "$work/tracer.txt"
[ -s "$work/tracer/observables.csv" ]
head -1 "$work/tracer.txt"

PYTHONPATH=$prefix/$site "$python" "$(dirname "$0")/check_import.py" "$prefix/$site" "$version" "$commit"
