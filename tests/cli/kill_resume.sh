#!/usr/bin/env bash
# Random kills (issue 16): `md run` is killed with SIGKILL at 10 random moments (checkpoint writes
# happen after every block of one realization, each fsynced, so kills land in and between them, and
# in the final output writes) and resumed each time with --resume; then stopped by SIGTERM and by
# SIGINT, which must exit 143/130 with a loadable checkpoint. The final files must equal an
# uninterrupted run's byte for byte, apart from the "# command:" line, the run id (two runs: the
# "# run_id:" lines, summary.json's and manifest.json's "run_id") and the cost fields of
# summary.json that count only the last process's work (wall_seconds, collisions_per_second,
# seconds_per_realization, resumed_realizations, resumed_collisions; docs/md-output.md).
# Usage: kill_resume.sh BINARY WORK [SEED]
set -uo pipefail
binary=$1 work=$2 seed=${3:-$RANDOM}
RANDOM=$seed
echo "kill_resume: seed $seed (rerun with this third argument to repeat the kill moments)"
scene=(md run --set t_max=60 --realizations 48 --set block_size=1 --threads 2)
test_name=kill_resume
. "$(dirname "$0")/resume_lib.sh"
begin_resume_test "$binary" "$work" "${scene[@]}"

out=$work/killed
attempt() {  # one start (resuming when a checkpoint exists), killed by $1 after $2 ms; sets status
  local args=("${scene[@]}" --out "$out")
  [ -f "$out/manifest.json" ] && args+=(--overwrite)  # an attempt that finished: start anew over it
  [ -f "$out/checkpoint/scene.toml" ] && args=("${scene[@]}" --resume "$out")
  "$binary" "${args[@]}" >/dev/null 2>>"$work/killed.err" &
  local pid=$!
  sleep "$(awk "BEGIN { print $2 / 1000 }")"
  kill -s "$1" "$pid" 2>/dev/null
  wait "$pid" 2>/dev/null
  status=$?
}
for kill in $(seq 1 10); do
  # A moment within what is left of the run (its blocks, then the output writes), or a little past it.
  done_blocks=$(ls "$out/checkpoint" 2>/dev/null | grep -c '^block_.*\.txt$')
  ms=$((RANDOM % (30 + duration_ms * (48 - done_blocks) / 48 * 11 / 10) + 10))
  attempt KILL "$ms"
  blocks=$(ls "$out/checkpoint" 2>/dev/null | grep -c '^block_.*\.txt$')
  echo "kill_resume: SIGKILL after ${ms} ms: exit $status, ${blocks} blocks checkpointed"
  [ "$status" -eq 137 ] || [ "$status" -eq 0 ] || fail "exit $status after SIGKILL: $(tail -3 "$work/killed.err")"
done

for signal in TERM INT; do
  expected=$([ $signal = TERM ] && echo 143 || echo 130)
  # A fresh run stopped a quarter into its blocks (earlier on retries, should it finish first); the
  # SIGINT run's checkpoint is what the final resume continues.
  for delay in $((duration_ms / 4 + 20)) $((duration_ms / 8 + 10)) 20; do
    rm -rf "$out"
    attempt $signal "$delay"
    [ "$status" -ne 0 ] && break
  done
  [ "$status" -eq "$expected" ] || fail "SIG$signal: exit $status, expected $expected: $(tail -3 "$work/killed.err")"
  grep -q "continue with \`coldblast md run --resume $out\`" "$work/killed.err" || fail "SIG$signal: no resume hint"
  [ -f "$out/checkpoint/scene.toml" ] || fail "SIG$signal left no checkpoint"
  echo "kill_resume: SIG$signal: exit $status, $(ls "$out/checkpoint" | grep -c '^block_') blocks checkpointed"
done

args=("${scene[@]}" --out "$out")
[ -f "$out/checkpoint/scene.toml" ] && args=("${scene[@]}" --resume "$out")
[ -f "$out/manifest.json" ] && args+=(--overwrite)  # the last start finished: run once more over it
"$binary" "${args[@]}" >/dev/null 2>>"$work/killed.err" || fail "final resume: $(tail -3 "$work/killed.err")"
[ -e "$out/checkpoint" ] && fail "the finished run left its checkpoint"

same_files --names "$work/reference" "$out"
leftovers=$(find "$out" -name '*.tmp.*' | wc -l)
[ "$leftovers" -eq 0 ] || echo "kill_resume: note: $leftovers temporary files of killed writes remain"
echo "kill_resume: PASS: $file_count files identical after 10 SIGKILLs, a SIGTERM and a SIGINT"
