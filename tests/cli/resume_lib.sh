# Shared by the stop-and-resume tests (kill_resume.sh, sigterm_in_flight.sh, disk_full.sh), sourced
# after each sets test_name: fail(), the uninterrupted reference run, and the check that a stopped
# and resumed run wrote the same files. Two runs of one ensemble differ only in the provenance
# command line, the run id and the cost fields that count one process's work (docs/md-output.md).

fail() {
  echo "${test_name:?set test_name before sourcing resume_lib.sh}: FAIL: $*" >&2
  exit 1
}

# The usual start: WORK made afresh, then reference_run of ARGS, reported with its duration.
begin_resume_test() {
  local binary=$1 work=$2
  rm -rf "$work" && mkdir -p "$work"
  reference_run "$@"
  echo "$test_name: uninterrupted run ${duration_ms} ms"
}

# Runs BINARY ARGS... --out WORK/reference (stderr in WORK/reference.err); sets duration_ms.
reference_run() {
  local binary=$1 work=$2
  shift 2
  local start
  start=$(date +%s%N)
  "$binary" "$@" --out "$work/reference" >/dev/null 2>"$work/reference.err" ||
    fail "reference run: $(cat "$work/reference.err")"
  duration_ms=$((($(date +%s%N) - start) / 1000000))
}

# A run file without the command line, the run id and the per-process cost fields.
normalise() {
  grep -v -E '^# (command|run_id): |"(run_id|wall_seconds|collisions_per_second|seconds_per_realization|resumed_realizations|resumed_collisions)":' "$1"
}

# Fails unless folder OUT holds the files of folder REFERENCE, equal after normalise (with
# `--names`, the same file names too); sets file_count.
same_files() {
  local names=0
  [ "$1" = --names ] && names=1 && shift
  local reference=$1 out=$2 files
  files=$(cd "$reference" && ls)
  [ "$names" -eq 0 ] || [ "$files" = "$(cd "$out" && ls)" ] || fail "different files: $(cd "$out" && ls | tr '\n' ' ')"
  for f in $files; do
    diff <(normalise "$reference/$f") <(normalise "$out/$f") >/dev/null || fail "$f differs from the uninterrupted run's"
  done
  file_count=$(echo $files | wc -w)
}
