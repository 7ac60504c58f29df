#!/bin/bash
# Keeps a finished run folder (a campaign's shard) somewhere that outlives the machine, whole (with
# its accumulators.csv, which md merge needs), and logs it: docs/cluster.md, "Keep finished shards".
#   scripts/keep_shard.sh RUN DEST LOG [NOTE]
# RUN must be finished (RUN/manifest.json and no RUN/checkpoint). It is copied to DEST/<name of RUN>
# through a temporary folder renamed at the end, so DEST never holds half a copy; a copy of the same
# run (same run_id) already there is left alone; another run of the same name is refused. One line
# is appended to LOG: the time the run finished, its shard, realizations, collisions, wall time,
# threads and energy error, and NOTE (say, the machine and its load). Exit 0 kept or already kept,
# 2 bad input.
set -euo pipefail
die() { echo "keep_shard.sh: $*" >&2; exit 2; }
[ $# -ge 3 ] && [ $# -le 4 ] || die "usage: keep_shard.sh RUN DEST LOG [NOTE]"
run=${1%/}; dest=${2%/}; log=$3; note=${4:-}
[ -d "$run" ] && [ ! -L "$run" ] || die "RUN '$run' is not a run folder"
[ -f "$run/manifest.json" ] && [ ! -e "$run/checkpoint" ] ||
  die "RUN '$run' is not finished (it needs manifest.json and no checkpoint/; resume it with md run --resume)"
[ -f "$run/summary.json" ] || die "RUN '$run' has no summary.json"
[ ! -e "$dest" ] || { [ -d "$dest" ] && [ ! -L "$dest" ]; } || die "DEST '$dest' exists and is not a folder (or is a symlink)"
[ ! -e "$log" ] || { [ -f "$log" ] && [ ! -L "$log" ]; } || die "LOG '$log' exists and is not a regular file"
mkdir -p "$dest"
name=$(basename "$run")
run_id() { /usr/bin/python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["run_id"])' "$1/manifest.json"; }
if [ -e "$dest/$name" ]; then
  [ -f "$dest/$name/manifest.json" ] && [ "$(run_id "$dest/$name")" = "$(run_id "$run")" ] ||
    die "DEST already holds another '$name' (a different run_id): not replaced"
  echo "keep_shard.sh: $dest/$name is already kept" >&2
  exit 0
fi
tmp="$dest/.$name.partial-$$"
trap 'rm -rf "$tmp"' EXIT
cp -rp "$run" "$tmp"
sync "$tmp" 2>/dev/null || true
mv -T "$tmp" "$dest/$name"
trap - EXIT
when=$(date -u -r "$run/manifest.json" +%FT%TZ)
/usr/bin/python3 - "$run/summary.json" "$name" "$when" "$note" >> "$log" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
line = (f"{sys.argv[3]} {sys.argv[2]} kept (run {s['run_id']}, shard {s.get('shard', '-')}): "
        f"{s['realizations']} realizations, {s['collisions_total']} collisions, {s['wall_seconds']:.1f} s "
        f"since the last start with {s['threads']} threads; energy error <= {s['energy_error_max']:.1e}")
if s.get("resumed_collisions", 0) > 0:  # a resumed run: its time covers only the collisions after the states
    r = s["resumed_realizations"]
    line += (f"; resumed ({r} finished realization{'' if r == 1 else 's'} and {s['resumed_collisions']} "
             f"collisions done before), {s['collisions_per_second']:.3g} collisions/s since")
print(line + (f"; {sys.argv[4]}" if sys.argv[4] else ""))
PY
echo "keep_shard.sh: kept $run in $dest/$name" >&2
