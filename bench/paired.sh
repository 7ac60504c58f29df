#!/bin/bash
# Paired timing of two md_driver binaries (say, built from two commits) on one workload: runs them
# alternately REPS times on one core and prints each one's loop CPU times and median, and whether
# their checksums agree (they must, for a change that keeps trajectories bit for bit).
#   bench/paired.sh OLD_BINARY NEW_BINARY REPS md_driver-arguments...
#   e.g. bench/paired.sh old/md_driver build-perf/bin/md_driver 5 equilibrium 0.3
set -euo pipefail
if [ $# -lt 4 ]; then
  echo "usage: $0 OLD_BINARY NEW_BINARY REPS md_driver-arguments..." >&2
  exit 2
fi
old=$1 new=$2 reps=$3
shift 3
out=$(mktemp)
trap 'rm -f "$out"' EXIT
for _ in $(seq "$reps"); do
  for which in old new; do
    binary=$old
    [ "$which" = new ] && binary=$new
    line=$(taskset -c 0 "$binary" "$@")
    case "$line" in
      *checksum*loop*) echo "$which $line" >> "$out" ;;
      *) echo "$0: $binary $* printed no checksum and loop time: $line" >&2; exit 1 ;;
    esac
  done
done
for which in old new; do
  grep "^$which " "$out" | sed -E 's/.* loop ([0-9.]+) s.*/\1/' | sort -n | tr '\n' ' ' |
    awk -v w="$which" '{n = NF; m = (n % 2) ? $((n + 1) / 2) : ($(n / 2) + $(n / 2 + 1)) / 2; print w, "median", m, "s:", $0}'
done
if [ "$(grep -o 'checksum [0-9a-f]*' "$out" | sort -u | wc -l)" = 1 ]; then
  echo "checksums: identical"
else
  echo "checksums: DIFFER"
fi
