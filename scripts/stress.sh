#!/usr/bin/env bash
# Regenerates the stress grid of docs/stress.md (nice'd: it runs for a while on 2 cores):
#   scripts/stress.sh [BINARY] [tvns hydro md md_phi md_radius md_memory tvns_tolerance tracer]  > table.md
#   (md_phi, md_radius: only the MD φ sweeps, only the MD impurity radius sweeps;
#   tvns_tolerance: only the TvNS tolerance sweep, which tvns includes)
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
exec nice -n 15 /usr/bin/python3 "$here/scripts/stress.py" "${1:-$here/build/bin/coldblast}" "${@:2}"
