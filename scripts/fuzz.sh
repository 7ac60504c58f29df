#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, ASan + UBSan) in build-fuzz/ and fuzzes each for SECONDS
# (default 60), two targets at a time under nice, starting from the regression corpus
# fuzz/corpus/<target>/. New coverage goes to build-fuzz/corpus/<target>/; a crash, hang, leak or
# sanitizer report is saved as build-fuzz/findings/<target>/crash-* (replay: the printed command;
# after the fix, copy it into fuzz/corpus/<target>/ so the ordinary tests replay it).
# Usage: scripts/fuzz.sh [SECONDS] [TARGET ...]     targets: scene options checkpoint run_directory
# COLDBLAST_FUZZ_SEED=S fixes libFuzzer's seed; COLDBLAST_FUZZ_RUNS_<target>=N (or COLDBLAST_FUZZ_RUNS
# for every target) stops a target after N inputs. CI's bounded pass (.ci/run) sets both, so a clean
# clone fuzzes the same inputs on every machine that is fast enough (SECONDS stays the upper bound;
# a slower machine runs a prefix of them).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${COLDBLAST_FUZZ_BUILD_DIR:-$here/build-fuzz}
seconds=${1:-60}
shift || true
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(scene options checkpoint run_directory)

fixed=()
[ -n "${COLDBLAST_FUZZ_SEED:-}" ] && fixed+=(-seed="$COLDBLAST_FUZZ_SEED")

launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
      -DCOLDBLAST_FUZZ=ON -DCOLDBLAST_BUILD_TESTS=OFF "${launcher[@]}" >/dev/null
nice -n 15 cmake --build "$build" -j2 --target "${targets[@]/#/coldblast_fuzz_}" >&2

run_one() {
  local target=$1
  mkdir -p "$build/corpus/$target" "$build/findings/$target"
  local runs_var="COLDBLAST_FUZZ_RUNS_$target" runs=()
  local limit=${!runs_var:-${COLDBLAST_FUZZ_RUNS:-}}
  [ -n "$limit" ] && runs=(-runs="$limit")
  echo "fuzz: $target for $seconds s" >&2
  # -rss_limit_mb and -timeout turn runaway memory and hangs into findings too.
  nice -n 15 "$build/bin/coldblast_fuzz_$target" "$build/corpus/$target" "$here/fuzz/corpus/$target" \
      -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=8192 -print_final_stats=1 \
      -artifact_prefix="$build/findings/$target/" "${fixed[@]}" "${runs[@]}" >"$build/findings/$target/log.txt" 2>&1
  local status=$?
  tail -n 12 "$build/findings/$target/log.txt" | grep -E "stat::number_of_executed_units|Done|ERROR|SUMMARY|finding" >&2 || true
  return $status
}

failed=0
for ((i = 0; i < ${#targets[@]}; i += 2)); do
  pids=()
  for target in "${targets[@]:i:2}"; do
    run_one "$target" & pids+=($!)
  done
  for pid in "${pids[@]}"; do wait "$pid" || failed=1; done
done
if [ $failed -ne 0 ]; then
  echo "fuzz: findings in $build/findings/ (see log.txt beside them)" >&2
  exit 1
fi
echo "fuzz: no findings" >&2
