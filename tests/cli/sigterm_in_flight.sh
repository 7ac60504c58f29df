#!/usr/bin/env bash
# A long realization stopped by SIGTERM saves where it stands (OUT/checkpoint/in_flight) and the
# run exits 143 within seconds; `--resume OUT` goes on from there and ends with the files of an
# uninterrupted run, byte for byte apart from the provenance command line, the run id and the cost
# fields of the last process (as kill_resume.sh). --save-every outside (0, 1e9] is refused.
# Usage: sigterm_in_flight.sh BINARY WORK
set -uo pipefail
binary=$1 work=$2
scene=(md run --set t_max=12000 --realizations 1)
test_name=sigterm_in_flight
. "$(dirname "$0")/resume_lib.sh"
begin_resume_test "$binary" "$work" "${scene[@]}"

out=$work/stopped
"$binary" "${scene[@]}" --out "$out" >/dev/null 2>"$work/stopped.err" &
pid=$!
sleep "$(awk "BEGIN { print $duration_ms / 2000 }")"  # half-way through the realization
kill -TERM "$pid"
signalled=$(date +%s%N)
wait "$pid"
status=$?
stop_ms=$((($(date +%s%N) - signalled) / 1000000))
[ "$status" -eq 143 ] || fail "exit $status after SIGTERM, expected 143: $(tail -3 "$work/stopped.err")"
state=$out/checkpoint/in_flight/realization_0.bin
[ -s "$state" ] || fail "no saved state $state"
grep -q "where each long one in flight stood" "$work/stopped.err" || fail "no note of the saved state"
echo "sigterm_in_flight: stopped ${stop_ms} ms after SIGTERM, state $(stat -c %s "$state") bytes"
[ "$stop_ms" -le 5000 ] || fail "took ${stop_ms} ms to stop"

"$binary" md run --resume "$out" >/dev/null 2>"$work/resumed.err" || fail "resume: $(tail -3 "$work/resumed.err")"
[ -e "$out/checkpoint" ] && fail "the finished run left its checkpoint"
same_files --names "$work/reference" "$out"

"$binary" md run --save-every 0 --out "$work/bad" >/dev/null 2>"$work/bad.err"
status=$?
[ "$status" -eq 2 ] && grep -q -- "--save-every" "$work/bad.err" || fail "--save-every 0: exit $status, $(cat "$work/bad.err")"
echo "sigterm_in_flight: PASS: resumed from the saved state to the uninterrupted run's $file_count files"
