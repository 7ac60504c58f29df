#!/bin/bash
# scripts/keep_shard.sh (docs/cluster.md, "Keep finished shards"): a finished shard is copied whole
# and logged once; the kept copies merge to what the originals merge to; a repeat changes nothing;
# an unfinished run, another run of the same name, and a symlink or a file as DEST or LOG are
# refused with exit 2 and nothing written.
# Usage: keep_shard.sh BINARY KEEP_SCRIPT WORK
set -uo pipefail
binary=$1 keep=$2 work=$3
test_name="keep_shard"
fail() {
  echo "$test_name: FAIL: $*" >&2
  exit 1
}
rm -rf "$work" && mkdir -p "$work" && cd "$work" || fail "cannot make $work"
run() { "$binary" md run --realizations 4 --set block_size=1 --set t_max=200 "$@" >/dev/null 2>&1; }
run --seed 3 --shard 0/2 --out s0 || fail "md run shard 0/2"
run --seed 3 --shard 1/2 --out s1 || fail "md run shard 1/2"
collisions() { /usr/bin/python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["collisions_total"])' "$1"; }

# Kept whole, logged once with the run's own numbers.
bash "$keep" s0 kept/shards kept/provenance.log "test machine" 2>err || fail "keep s0: $(cat err)"
bash "$keep" s1 kept/shards kept/provenance.log 2>err || fail "keep s1: $(cat err)"
diff -r s0 kept/shards/s0 >/dev/null || fail "kept/shards/s0 differs from s0"
[ "$(wc -l < kept/provenance.log)" = 2 ] || fail "provenance.log has $(wc -l < kept/provenance.log) lines, not 2"
line=$(head -1 kept/provenance.log)
for want in "s0 kept" "shard 0/2" "2 realizations" "$(collisions s0/summary.json) collisions" "; test machine"; do
  [[ $line == *"$want"* ]] || fail "log line lacks '$want': $line"
done
ls -a kept/shards | grep -q partial && fail "a temporary copy was left in kept/shards"
# A resumed run (here s0's folder with a resumed run's summary fields) says what came before the
# last start, whose time covers only the rest.
cp -r s0 s2
/usr/bin/python3 - s2/summary.json <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
s.update(run_id="resumed-run", resumed_realizations=1, resumed_collisions=1234, collisions_per_second=5678.0)
json.dump(s, open(sys.argv[1], "w"))
PY
sed -i 's/"run_id": *"[^"]*"/"run_id": "resumed-run"/' s2/manifest.json
bash "$keep" s2 kept/shards kept/provenance.log 2>err || fail "keep s2: $(cat err)"
line=$(tail -1 kept/provenance.log)
want="; resumed (1 finished realization and 1234 collisions done before), 5.68e+03 collisions/s since"
[[ $line == *"$want"* ]] || fail "the resumed run's line lacks '$want': $line"
[[ $(head -1 kept/provenance.log) == *resumed* ]] && fail "s0's line says resumed"
rm -r kept/shards/s2 s2 && sed -i '$d' kept/provenance.log

# The kept copies merge to exactly what the originals merge to (accumulators.csv came along).
"$binary" md merge s0 s1 --out merged >/dev/null 2>&1 || fail "md merge of the originals"
"$binary" md merge kept/shards/s0 kept/shards/s1 --out merged-kept >/dev/null 2>&1 || fail "md merge of the kept copies"
for f in observables.csv blocks.csv accumulators.csv; do
  cmp <(grep -v '^#' "merged/$f") <(grep -v '^#' "merged-kept/$f") >/dev/null || fail "merged $f differs (beyond its header)"
done

# A repeat: exit 0, nothing added.
before=$(find kept -type f -exec md5sum {} + | sort)
bash "$keep" s0 kept/shards kept/provenance.log 2>err || fail "repeat exited $?"
grep -q "already kept" err || fail "repeat: no 'already kept' message"
[ "$(find kept -type f -exec md5sum {} + | sort)" = "$before" ] || fail "a repeat changed kept/"

# Refusals: exit 2, the parameter named, nothing written.
expect_refusal() {
  local what=$1 pattern=$2
  shift 2
  bash "$keep" "$@" 2>err
  local code=$?
  [ $code = 2 ] || fail "$what: exit $code, not 2"
  grep -q -- "$pattern" err || fail "$what: message '$(cat err)' lacks '$pattern'"
  [ "$(find kept -type f -exec md5sum {} + | sort)" = "$before" ] || fail "$what changed kept/"
}
mkdir -p unfinished/checkpoint && cp s0/manifest.json s0/summary.json unfinished/
expect_refusal "an unfinished run" "RUN 'unfinished' is not finished" unfinished kept/shards kept/provenance.log
mkdir -p other && run --shard 0/2 --seed 4 --out other/s0 || fail "md run other/s0"
expect_refusal "another run of the same name" "another 's0'" other/s0 kept/shards kept/provenance.log
ln -s kept/shards link
expect_refusal "a symlink as DEST" "DEST 'link'" s0 link kept/provenance.log
touch afile
expect_refusal "a file as DEST" "DEST 'afile'" s0 afile kept/provenance.log
ln -s kept/provenance.log loglink
expect_refusal "a symlink as LOG" "LOG 'loglink'" s1 kept/shards2 loglink
[ ! -e kept/shards2 ] || fail "a refused call made its DEST"
expect_refusal "no arguments" "usage" s0
echo "$test_name: passed"
