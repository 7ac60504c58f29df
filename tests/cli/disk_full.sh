#!/usr/bin/env bash
# Disk full (issue 16): `md run` with its output folder on a tiny tmpfs. With room for only part of
# the checkpoint, the run must exit 1 naming the file it could not write; the blocks already saved
# must load (the resume below reads them all); no temporary may be left; and after space is freed,
# --resume must finish with outputs equal to an uninterrupted run's (apart from the command line and
# run id and per-process cost fields). A second pass fills the disk during the final output writes
# of a run that replaces an earlier complete run (--overwrite, which removes the old run's files
# first): every output file written must be complete (never cut), no manifest.json may claim the
# incomplete run, the checkpoint must stay intact, and the resume must finish. Needs root and tmpfs:
# skipped (exit 77) otherwise.
# Usage: disk_full.sh BINARY WORK
set -uo pipefail
binary=$1 work=$2
scene=(md run --set t_max=40 --realizations 24 --set block_size=1)
rm -rf "$work" && mkdir -p "$work/mnt"
if [ "$(id -u)" -ne 0 ] || ! mount -t tmpfs -o size=1m coldblast-test "$work/mnt" 2>/dev/null; then
  echo "disk_full: SKIP: cannot mount a tmpfs here (needs root and mount rights)"
  exit 77
fi
trap 'umount "$work/mnt" 2>/dev/null' EXIT
mnt=$work/mnt

test_name=disk_full
. "$(dirname "$0")/resume_lib.sh"
reference_run "$binary" "$work" "${scene[@]}"
same_as_reference() { same_files "$work/reference" "$1"; }
fill_leaving() {  # fills the tmpfs until only $1 KiB are free
  rm -f "$mnt/filler"
  local free_kib=$(($(stat -f -c '%a * %S / 1024' "$mnt")))
  dd if=/dev/zero of="$mnt/filler" bs=1K count=$((free_kib - $1)) status=none 2>/dev/null
}

# 1. The checkpoint fills the disk: room for scene.toml and a few block files (4 KiB pages each).
fill_leaving 40
"$binary" "${scene[@]}" --out "$mnt/run" >/dev/null 2>"$work/full.err"
status=$?
blocks=$(ls "$mnt/run/checkpoint" 2>/dev/null | grep -c '^block_.*\.txt$')
echo "disk_full: checkpoint on a full disk: exit $status, $blocks blocks saved: $(grep -o 'cannot write.*' "$work/full.err" | head -1)"
[ "$status" -eq 1 ] || fail "exit $status, expected 1: $(cat "$work/full.err")"
grep -q "cannot write $mnt/run/.*: No space left on device" "$work/full.err" || fail "no message naming the file: $(cat "$work/full.err")"
[ "$blocks" -gt 0 ] && [ "$blocks" -lt 24 ] || fail "$blocks blocks saved, expected some but not all"
[ -z "$(find "$mnt/run" -name '*.tmp.*')" ] || fail "temporaries left behind: $(find "$mnt/run" -name '*.tmp.*')"
rm -f "$mnt/filler"
"$binary" "${scene[@]}" --resume "$mnt/run" >/dev/null 2>"$work/resume.err" || fail "resume after freeing space: $(cat "$work/resume.err")"
grep -q "md run: $((24 - blocks))/$((24 - blocks)) realizations" "$work/resume.err" || fail "the resume did not load the $blocks saved blocks"
same_as_reference "$mnt/run"
echo "disk_full: resumed after freeing space, outputs identical"

# 2. The final outputs fill the disk, replacing the complete outputs of an earlier run.
rm -rf "$mnt/run"
"$binary" md run --set t_max=5 --realizations 1 --out "$mnt/run" >/dev/null 2>&1 || fail "the earlier run failed"
room_kib=280  # the checkpoint (25 files of one 4 KiB page and their temporaries) and observables.csv, not blocks.csv
fill_leaving $room_kib
"$binary" "${scene[@]}" --set seed=7 --out "$mnt/run" >/dev/null 2>"$work/refused.err"
[ $? -eq 2 ] && grep -q -- "--out = $mnt/run holds the files of run" "$work/refused.err" ||
  fail "a run over another run's files without --overwrite: $(cat "$work/refused.err")"
"$binary" "${scene[@]}" --set seed=7 --out "$mnt/run" --overwrite >/dev/null 2>"$work/full2.err"
status=$?
echo "disk_full: outputs on a full disk: exit $status: $(grep -o 'cannot write.*' "$work/full2.err" | head -1)"
[ "$status" -eq 1 ] || fail "exit $status, expected 1: $(cat "$work/full2.err")"
for f in $(cd "$work/reference" && ls); do
  [ ! -e "$mnt/run/$f" ] || { [ -s "$mnt/run/$f" ] && [ "$(tail -c 1 "$mnt/run/$f" | od -An -c | tr -d ' ')" = '\n' ]; } ||
    fail "$f was cut"
done
[ ! -e "$mnt/run/manifest.json" ] || fail "manifest.json claims an incomplete run"
[ -z "$(find "$mnt/run" -name '*.tmp.*')" ] || fail "temporaries left behind"
saved=$(ls "$mnt/run/checkpoint" 2>/dev/null | grep -c '^block_.*\.txt$')
[ "$saved" -eq 24 ] || fail "the checkpoint itself ran out of space ($saved blocks): raise room_kib"
grep -q "cannot write $mnt/run/[a-z_]*\.csv: No space left" "$work/full2.err" || fail "the failure was not in an output file"
rm -f "$mnt/filler"
"$binary" "${scene[@]}" --set seed=7 --resume "$mnt/run" >/dev/null 2>"$work/resume2.err" || fail "second resume: $(cat "$work/resume2.err")"
echo "disk_full: PASS ($saved of 24 blocks were saved when the outputs failed; every file stayed complete)"
