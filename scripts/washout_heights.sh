#!/usr/bin/env bash
# The wash-out experiment at the paper's three water heights (250, 300, 350 mm) in one command,
# and one figure with the three runs side by side (scripts/plot_washout.py):
#
#   bash scripts/washout_heights.sh                          # 3D scene, default resolution
#   bash scripts/washout_heights.sh --2d                     # the 2D section
#   bash scripts/washout_heights.sh --out runs/paper --set d0=0.005   # extra --set go to every run
#
# Runs go to OUT/h250, OUT/h300, OUT/h350 (default OUT: runs/washout_heights, or
# runs/washout_heights_2d with --2d); the figure is OUT/washout_heights.png. The program is
# build/engine/cli/washout unless WASHOUT is set. A run that stops as unstable (exit 2) keeps
# its file and is still drawn; the script then exits with the worst status of the three.
set -uo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
washout="${WASHOUT:-$here/build/engine/cli/washout}"
scene="$here/scenes/girder_washout.lua"
out=""
extra=()
while [ $# -gt 0 ]; do
  case "$1" in
    --2d) scene="$here/scenes/girder_washout_2d.lua"; shift ;;
    --out) out="${2:?--out needs a folder}"; shift 2 ;;
    --set) extra+=(--set "${2:?--set needs NAME=VALUE}"); shift 2 ;;
    --threads|--quiet) extra+=("$1"); [ "$1" = --threads ] && { extra+=("${2:?}"); shift; }; shift ;;
    -h|--help) sed -n '2,12p' "${BASH_SOURCE[0]}"; exit 0 ;;
    *) echo "washout_heights: unknown argument '$1' (see --help)" >&2; exit 1 ;;
  esac
done
if [ -z "$out" ]; then
  out="runs/washout_heights"
  [[ "$scene" == *_2d.lua ]] && out="runs/washout_heights_2d"
fi
if [ ! -x "$washout" ]; then
  echo "washout_heights: no washout program at $washout (build first, or set WASHOUT=...)" >&2
  exit 1
fi

worst=0
dirs=()
for h in 0.25 0.30 0.35; do
  dir="$out/h${h#0.}0"  # millimetres: 0.25 -> h250
  echo "== water height $h m: $dir"
  "$washout" run "$scene" --out "$dir" --quiet --set water_height="$h" "${extra[@]}"
  status=$?
  if [ $status -ne 0 ]; then
    echo "washout_heights: the run at water height $h m ended with status $status" >&2
    [ $status -gt $worst ] && worst=$status
    [ $status -ne 2 ] && continue  # nothing to draw unless it ran (2: unstable, file kept)
  fi
  dirs+=("$dir")
done
if [ ${#dirs[@]} -gt 0 ]; then
  /usr/bin/python3 "$here/scripts/plot_washout.py" "${dirs[@]}" --out "$out/washout_heights.png" ||
    worst=$(( worst > 3 ? worst : 3 ))
fi
exit $worst
