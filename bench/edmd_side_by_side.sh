#!/bin/bash
# Side-by-side timing of our MD engine (bench/md_driver.cpp) against Smallenburg's EDMD
# (https://github.com/FSmallenburg/EDMD), 3D hard spheres in equilibrium, σ = 1, T = 1.
# It fetches nothing and keeps no peer code: you extract the peer's snapshot yourself, outside
# this repository, and give its paths.
#
#   bench/edmd_side_by_side.sh patch EDMD_DIR
#       edits the extracted snapshot in EDMD_DIR (Single/, Multi/, Cell/) and builds each variant
#       with its own Makefile (gcc -Wall -Ofast -funroll-loops -march=native). The edits, all in
#       main() and two settings: the thermostat off (Single ships with usethermostat = 1), an FCC
#       start, and a driver `md PHI N MELT COLLISIONS` that runs MELT collisions, then times
#       COLLISIONS more by process CPU time, and prints "collisions ... loop S s rate R/s". The
#       engine (events, neighbour lists or cells, calendar) is untouched.
#   bench/edmd_side_by_side.sh pairs MD_DRIVER EDMD_BINARY PHI PAIRS [N] [MELT] [COLLISIONS]
#       alternates `MD_DRIVER equilibrium PHI 1 N MELT COLLISIONS` and `EDMD_BINARY PHI N MELT
#       COLLISIONS` on core 0, the order swapped every pair (defaults N = 32000, MELT = 1e5,
#       COLLISIONS = 1e6); prints each pair's loop CPU seconds and the median of the per-pair
#       ratios ours/EDMD in collisions per CPU second of the loop.
set -euo pipefail

usage() {
  sed -n '7,18p' "$0" >&2
  exit 2
}

patch_edmd() {
  local dir=$1
  for v in Single Multi Cell; do
    local src="$dir/$v/md$v.c"
    [ -f "$src" ] || { echo "$0: no $src (EDMD_DIR must hold the snapshot's Single/, Multi/, Cell/)" >&2; exit 2; }
    grep -q 'int main(int argc' "$src" && { echo "$0: $src is already patched" >&2; exit 2; }
    sed -i \
      -e 's/^const int usethermostat = 1;/const int usethermostat = 0;/' \
      -e 's/^int initialconfig = 0;/int initialconfig = 1;/' \
      -e 's/^#include <stdio.h>/#include <stdio.h>\n#include <time.h>/' \
      -e '/^int main()/,/^}/{
s/^int main()/int main(int argc, char** argv)/
s/^    init();/    if (argc != 5) { fprintf(stderr, "usage: md PHI N MELT COLLISIONS\\n"); return 2; }\n    packfrac = atof(argv[1]); N = atoi(argv[2]);\n    unsigned int melt = strtoul(argv[3], 0, 10), timed = strtoul(argv[4], 0, 10);\n    init();/
s/^    while (simtime <= maxtime)/    while (colcounter < melt) step();\n    struct timespec t0, t1;\n    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, \&t0);\n    while (colcounter < melt + timed)/
s/^    simtime = maxtime;/    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, \&t1);\n    double loop = (t1.tv_sec - t0.tv_sec) + 1e-9 * (t1.tv_nsec - t0.tv_nsec);\n    printf("edmd phi %g N %d: collisions %u loop %.3f s rate %.3g\/s\\n", packfrac, N, timed, loop, timed \/ loop);/
}' "$src"
    if ! grep -q 'usethermostat = 0;' "$src" || ! grep -q 'CLOCK_PROCESS_CPUTIME_ID, &t1' "$src"; then
      echo "$0: patching $src failed (a different snapshot?)" >&2
      exit 1
    fi
    make -C "$dir/$v" -B >/dev/null
  done
  echo "built $dir/Single/md $dir/Multi/md $dir/Cell/md"
}

loop_seconds() { sed -nE 's/.* loop ([0-9.]+) s.*/\1/p' | tail -1; }

pairs() {
  local ours=$1 edmd=$2 phi=$3 reps=$4 n=${5:-32000} melt=${6:-100000} coll=${7:-1000000}
  run_dir=$(mktemp -d)
  trap 'rm -rf "$run_dir"' EXIT
  local ratios=() a b
  for k in $(seq "$reps"); do
    if [ $((k % 2)) = 1 ]; then
      a=$(taskset -c 0 "$ours" equilibrium "$phi" 1 "$n" "$melt" "$coll" | loop_seconds)
      b=$(cd "$run_dir" && taskset -c 0 "$edmd" "$phi" "$n" "$melt" "$coll" | loop_seconds)
    else
      b=$(cd "$run_dir" && taskset -c 0 "$edmd" "$phi" "$n" "$melt" "$coll" | loop_seconds)
      a=$(taskset -c 0 "$ours" equilibrium "$phi" 1 "$n" "$melt" "$coll" | loop_seconds)
    fi
    if [ -z "$a" ] || [ -z "$b" ]; then
      echo "$0: a run printed no loop time" >&2
      exit 1
    fi
    local r
    r=$(awk -v a="$a" -v b="$b" 'BEGIN { printf "%.3f", b / a }')
    ratios+=("$r")
    echo "pair $k phi $phi: ours $a s ($(awk -v c="$coll" -v t="$a" 'BEGIN { printf "%.3g", c / t }')/s)" \
      "edmd $b s ($(awk -v c="$coll" -v t="$b" 'BEGIN { printf "%.3g", c / t }')/s) ratio $r"
  done
  printf '%s\n' "${ratios[@]}" | sort -n | tr '\n' ' ' |
    awk -v p="$phi" '{ n = NF; m = (n % 2) ? $((n + 1) / 2) : ($(n / 2) + $(n / 2 + 1)) / 2; print "phi", p, "median ratio ours/edmd", m, "of:", $0 }'
}

[ $# -ge 1 ] || usage
case $1 in
  patch) [ $# = 2 ] || usage; patch_edmd "$2" ;;
  pairs) [ $# -ge 5 ] || usage; shift; pairs "$@" ;;
  *) usage ;;
esac
