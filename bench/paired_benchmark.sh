#!/bin/bash
# Paired rates of one Google Benchmark case in two binaries (say, built from two commits, or two
# cases of one binary): runs them alternately REPS times on one core (CORE, default 0) and prints
# each side's items_per_second (collisions per CPU second for bench_tracer) and median, and the
# ratio of the medians. Alternation spreads the shared machine's drift over both sides. A run that
# fails (say, an exception) is reported on stderr and repeated, up to three times. Where a filter
# matches several cases, they run in one process and the last one is timed.
#   bench/paired_benchmark.sh OLD_BINARY OLD_FILTER NEW_BINARY NEW_FILTER REPS
#   e.g. bench/paired_benchmark.sh old/bench_tracer 'late_core_batch<2>$' \
#          build/bin/bench_tracer 'late_core_batch<2>/avx512' 9
set -euo pipefail
if [ $# -ne 5 ]; then
  echo "usage: $0 OLD_BINARY OLD_FILTER NEW_BINARY NEW_FILTER REPS" >&2
  exit 2
fi
old=$1 old_filter=$2 new=$3 new_filter=$4 reps=$5
out=$(mktemp)
trap 'rm -f "$out"' EXIT
for _ in $(seq "$reps"); do
  for which in old new; do
    binary=$old filter=$old_filter
    [ "$which" = new ] && binary=$new filter=$new_filter
    for attempt in 1 2 3; do
      json=$(taskset -c "${CORE:-0}" "$binary" --benchmark_filter="$filter" --benchmark_format=json 2>/dev/null) && break
      echo "$0: $binary --benchmark_filter='$filter' failed (attempt $attempt)" >&2
      [ "$attempt" = 3 ] && exit 1
    done
    rate=$(echo "$json" | /usr/bin/python3 -c 'import json, sys; b = json.load(sys.stdin)["benchmarks"]; print(b[-1]["items_per_second"])')
    echo "$which $rate" >> "$out"
  done
done
for which in old new; do
  grep "^$which " "$out" | cut -d' ' -f2 | sort -g | tr '\n' ' ' |
    awk -v w="$which" '{n = NF; m = (n % 2) ? $((n + 1) / 2) : ($(n / 2) + $(n / 2 + 1)) / 2; printf "%s median %.4g /s: %s\n", w, m, $0}'
done | awk '{print; m[NR] = $3} END {printf "new / old = %.3f\n", m[2] / m[1]}'
