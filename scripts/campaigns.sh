#!/bin/bash
# The issue-6 campaigns exactly as recorded in docs/verification.md ("Campaign 1" … "Campaign 4"),
# one per argument: bash scripts/campaigns.sh 2 3 4   (outputs in ./campaigns/, reports beside them).
# Issue 32's deep campaigns: 5 (2D, R/λ = 307, 128 realizations in 64 shards, about 20 hours of both cores) and
# 6 (3D, R/λ = 37, 32 realizations in 16 shards, about 13 hours of both cores); each resumes its runs
# from their checkpoints when started again and skips a shard already finished. `finish5 DIR...` and
# `finish6 DIR...` do only the analysis, of shards made elsewhere, into campaigns/c5 or c6; `interim5`
# looks at campaign 5 midway (data/campaign5-2d-deep/interim, from the shards kept there).
# `--keep DIR` (first): each finished shard of 5 and 6 is copied whole into DIR/shards and logged in
# DIR/provenance.log (scripts/keep_shard.sh), e.g. on a disk that outlives the machine; a shard found
# there finished and missing here is copied back instead of run again (a new machine resumes from DIR).
# Wall times on the 2-core development machine: 1: ~1.5 h, 2: 42 min, 3: 61 min, 4: 5 + 12 + 15 min.
# data/campaign* were made by commit 8ad2c6a's engine; since 8fda9ee trajectories differ by round-off
# (bookkeeping events no longer re-round positions), so a rerun agrees statistically, not bit for bit.
# compare exits 3 on a failed verdict; that is a result here, not an error (hence "|| true").
set -euo pipefail
cd "$(dirname "$0")/.."
cb=./build/bin/coldblast
[ -x "$cb" ] || { echo "campaigns.sh: $cb missing: run scripts/bootstrap.sh first" >&2; exit 2; }
mkdir -p campaigns
keep=""
if [ "${1:-}" = --keep ]; then
  [ $# -ge 3 ] || { echo "campaigns.sh: --keep needs a folder and then the campaigns (5 or 6)" >&2; exit 2; }
  keep=$2; shift 2
fi
obs='observables=["R_imp","V_imp","C_imp","u_imp","u_flow","n0","T0","R","profiles","p_imp"]'
# A long run: started with --out, or resumed from its checkpoint when one is there.
# With --keep, a finished shard is kept (once: keep_shard.sh leaves a kept copy alone), and one kept
# but absent here is copied back.
run_or_resume() {
  local out=$1 kept
  shift
  kept=${keep:+$keep/shards/$(basename "$out")}
  if [ -n "$kept" ] && [ ! -e "$out" ] && [ -f "$kept/manifest.json" ] && [ ! -e "$kept/checkpoint" ]; then
    cp -rp "$kept" "$out"
  fi
  if [ -f "$out/manifest.json" ] && [ ! -d "$out/checkpoint" ]; then
    :  # finished earlier
  elif [ -d "$out/checkpoint" ]; then
    $cb md run --resume "$out" --threads 2
  else
    $cb "$@" --out "$out"
  fi
  if [ -n "$kept" ]; then
    bash scripts/keep_shard.sh "$out" "$keep/shards" "$keep/provenance.log" "$(uname -n), $(nproc) CPUs, load $(cut -d' ' -f1-3 /proc/loadavg)"
  fi
}
# The merged run, the comparisons and the kinetic tracer (NS background and the MD's own fields)
# against it: $1 = output folder, $2 = scene, $3 = tracer seed, $4 = t_min, $5 = t_max, the rest: run folders.
analyse_deep() {
  local out=$1 scene=$2 seed=$3 tmin=$4 tmax=$5; shift 5
  mkdir -p "$out"
  $cb md merge "$@" --out "$out/md" 2> "$out/merge.stderr.txt"
  for ref in hydro theory paper; do
    [ $ref = paper ] && [[ $scene == *3d* ]] && continue  # the paper's Table 1 is 2D
    $cb compare "$out/md" --against $ref --out "$out/vs-$ref" > "$out/vs-$ref.txt" || true
  done
  # the full NS (viscous) beside the paper's conduction-only core (docs/verification.md, "Viscosity in the comparison")
  $cb compare "$out/md" --against hydro --hydro-viscosity on --out "$out/vs-hydro-viscous" > "$out/vs-hydro-viscous.txt" || true
  local tobs='observables=["R_imp","V_imp","C_imp","p_imp"]'
  $cb tracer "$scene" --transport enskog --trajectories 131072 --threads 2 --seed "$seed" --set t_min="$tmin" \
    --set t_max="$tmax" --set "$tobs" --out "$out/tracer"
  $cb tracer --background md --md-run "$out/md" --transport enskog --trajectories 131072 --threads 2 --seed "$seed" \
    --set "$tobs" --out "$out/tracer-mdfields"
  $cb compare "$out/tracer" --md-run "$out/md" --out "$out/tracer-vs-md" > "$out/tracer-vs-md.txt" || true
  $cb compare "$out/tracer-mdfields" --md-run "$out/md" --out "$out/tracer-mdfields-vs-md" \
    > "$out/tracer-mdfields-vs-md.txt" || true
  # the tables of docs/verification.md's campaign section, from these files (R/λ and t: the defaults)
  /usr/bin/python3 "$(dirname "$0")/campaign_tables.py" "$out" > "$out/tables.md" || true
}
finish5() { analyse_deep campaigns/c5 scenes/paper-2d.toml 5 0.6103515625 320000 "$@"; }
# Campaign 5 midway: the kept shards k/64 with k not a multiple of 8 (they share no realization with
# shard 0/8's 16, so the two are independent ensembles) merged, compared with the dense NS (without and
# with viscosity) and theory, and set against shard 0: replaces data/campaign5-2d-deep/interim whole.
interim5() {
  local d=data/campaign5-2d-deep out=campaigns/c5-interim dirs=() k n
  for k in $(seq 1 63); do
    if [ $((k % 8)) -ne 0 ] && [ -f "$d/shards/c5-2d-deep-shard$k-of-64/manifest.json" ]; then
      dirs+=("$d/shards/c5-2d-deep-shard$k-of-64")
    fi
  done
  n=${#dirs[@]}
  [ "$n" -ge 2 ] || { echo "campaigns.sh: interim5 needs at least 2 kept shards in $d/shards (found $n)" >&2; exit 2; }
  rm -rf "$out"; mkdir -p "$out/interim"
  $cb md merge "${dirs[@]}" --out "$out/md" 2>&1 | head -3 > "$out/interim/merge.txt"
  $cb compare "$out/md" --against hydro --out "$out/vs-hydro" > "$out/interim/vs-hydro.txt" 2>/dev/null || true
  $cb compare "$out/md" --against hydro --hydro-viscosity on --out "$out/vs-hydro-viscous" \
    > "$out/interim/vs-hydro-viscous.txt" 2>/dev/null || true
  $cb compare "$out/md" --against theory --out "$out/vs-theory" > "$out/interim/vs-theory.txt" 2>/dev/null || true
  cp "$out/vs-hydro/amplitudes.csv" "$out/interim/amplitudes.csv"
  cp "$out/vs-hydro-viscous/amplitudes.csv" "$out/interim/amplitudes-viscous.csv"
  /usr/bin/python3 scripts/replication.py "$out/interim/amplitudes.csv" "$d/shard0-of-8/vs-hydro/amplitudes.csv" \
    --labels "shards k/64 ($((2 * n)))" "shard 0 of 8 (16)" > "$out/interim/replication.md"
  /usr/bin/python3 scripts/amplitude_history_figure.py "$out/interim/amplitudes.csv" "$d/shard0-of-8/vs-hydro/amplitudes.csv" \
    --labels "shards k/64 ($((2 * n)) new realizations)" "shard 0 of 8 (16 realizations)" --from 25 \
    --out "$out/interim/replication.png" \
    --title "Campaign 5 (2D, paper scene, kick start): two independent ensembles against the dense NS" >&2
  rm -rf "$d/interim"; cp -r "$out/interim" "$d/interim"
  echo "campaigns.sh interim5: $n shards ($((2 * n)) realizations) into $d/interim"
}
finish6() { analyse_deep campaigns/c6 scenes/paper-3d.toml 6 0.7505950927734375 58498.28719409885 "$@"; }
case "${1:-}" in
  finish5) shift; [ $# -ge 1 ] || { echo "campaigns.sh: finish5 needs the shards' folders" >&2; exit 2; }; finish5 "$@"; exit ;;
  finish6) shift; [ $# -ge 1 ] || { echo "campaigns.sh: finish6 needs the shards' folders" >&2; exit 2; }; finish6 "$@"; exit ;;
  interim5) [ $# -eq 1 ] || { echo "campaigns.sh: interim5 takes no argument" >&2; exit 2; }; interim5; exit ;;
esac
for c in "$@"; do
  case "$c" in
    1) # = reproduce --scale paper, in two steps so that a killed run can --resume (same seed 1,
       # block size 30000/64, A_2(phi) from hydro::solve_tvns_for_md; tests/cli/run_reproduce_md.cmake)
       $cb md run scenes/paper-2d.toml --realizations 30000 --set block_size=468 --threads 2 --seed 1 --out campaigns/c1-md
       $cb reproduce --scale paper --md-run campaigns/c1-md --out campaigns/c1-paper || true ;;
    2) for s in 0 1; do
         $cb md run scenes/paper-2d.toml --realizations 192 --set block_size=4 --threads 2 --seed 31 \
           --set t_min=0.6103515625 --set t_max=40000 --set "$obs" --shard $s/2 --out campaigns/c2-long-shard$s
       done
       $cb md merge campaigns/c2-long-shard0 campaigns/c2-long-shard1 --out campaigns/c2-long
       for T in 4204.482076 11892.07115 40000; do
         $cb compare campaigns/c2-long --against hydro --allowance 0 --until $T --out campaigns/c2-long-hydro-until-$T || true
       done
       $cb compare campaigns/c2-long --against theory --allowance 0 --window-decades 1 --out campaigns/c2-long-theory || true ;;
    3) $cb md run scenes/paper-3d.toml --realizations 48 --set block_size=2 --threads 2 --seed 33 \
         --set t_min=0.7505950927734375 --set t_max=12297.75 --set "$obs" --out campaigns/c3-3d
       for ref in theory hydro; do $cb compare campaigns/c3-3d --against $ref --allowance 0 --out campaigns/c3-3d-$ref || true; done ;;
    4) $cb md run scenes/paper-2d.toml --realizations 1024 --set block_size=16 --threads 2 --seed 41 \
         --set impurities.mass=10 --set "$obs" --out campaigns/c4-heavy
       $cb md run scenes/paper-2d.toml --realizations 1024 --set block_size=16 --threads 2 --seed 42 \
         --set impurities.radius=2.5 --set "$obs" --out campaigns/c4-large
       $cb md run scenes/paper-2d.toml --realizations 64 --set block_size=2 --threads 2 --seed 43 \
         --set impurities.mass=10 --set t_min=0.6103515625 --set t_max=40000 --set "$obs" --out campaigns/c4-heavy-long
       for r in c4-heavy c4-large c4-heavy-long; do
         $cb compare campaigns/$r --against theory --allowance 0 --out campaigns/$r-theory || true
       done ;;
    5) # 64 shards k/64 (blocks k and k + 64), 2 realizations each, so that a finished one is a small
       # folder kept in data/ (with its accumulators.csv, which md merge needs) while the rest runs. The
       # shards k = 0, 8, ..., 56 hold the realization numbers of data/campaign5-2d-deep/shard0-of-8 (whose
       # accumulators.csv was not kept, so it cannot be merged; its build placed the gas differently, so
       # these are new microstates, not copies): they run last.
       c5() { run_or_resume campaigns/c5-2d-deep-shard$1-of-64 md run scenes/paper-2d.toml --realizations 128 \
                --set block_size=1 --threads 2 --seed 51 --set t_min=0.6103515625 --set t_max=320000 --set "$obs" \
                --shard $1/64; }
       for k in $(seq 1 63); do if [ $((k % 8)) -ne 0 ]; then c5 $k; fi; done
       for k in $(seq 0 8 56); do c5 $k; done
       finish5 campaigns/c5-2d-deep-shard{0..63}-of-64 ;;
    6) # 16 shards of 2 realizations (the same seeds as one run of 32): a finished shard is a small folder
       # that can be kept (data/campaign6-3d-deep/shards) while the rest runs; an unfinished one resumes.
       for s in $(seq 0 15); do
         run_or_resume campaigns/c6-3d-deep-shard$s md run scenes/paper-3d.toml --realizations 32 --set block_size=1 \
           --threads 2 --seed 61 --set t_min=0.7505950927734375 --set t_max=58498.28719409885 --set "$obs" --shard $s/16
       done
       finish6 campaigns/c6-3d-deep-shard{0..15} ;;
    *) echo "campaigns.sh: campaign '$c' is not one of 1, 2, 3, 4, 5, 6 (or, first and alone: finish5 DIR..., finish6 DIR..., interim5)" >&2; exit 2 ;;
  esac
done
