#!/usr/bin/env bash
# The stability suite (issue: stability on stiff and extreme cases): sweeps of stiff and extreme
# cases, each a `washout study`, then a report with the table and the stability map:
#   bash scripts/stability.sh            the full sweep (about an hour on two cores)
#   bash scripts/stability.sh --quick    the envelope's corners only (about a minute), what CI runs
#   options: --out DIR (default runs/stability), --threads N (each run; default 1),
#            --only NAME,NAME (only these sweeps; their names are the report's sections),
#            --report FILE (default docs/stability.md; the map is FILE's name with _map.png)
# Uses the build in build/, the folder in WASHOUT_BUILD, or the program in WASHOUT.
# Exit status: 0 when every run of the quick envelope completed (the full sweep exits 0 whatever
# the runs did: its result is the report), 1 on a usage error or when a quick-envelope run was
# not stable.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"
mode=full out=runs/stability threads=1 report="" only=""
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) mode=quick ;;
    --out) out="$2"; shift ;;
    --threads) threads="$2"; shift ;;
    --report) report="$2"; shift ;;
    --only) only=",$2,"; shift ;;
    *) echo "stability.sh: unknown option '$1' (see the top of scripts/stability.sh)" >&2; exit 1 ;;
  esac
  shift
done
[ -n "$report" ] || report=$([ $mode = quick ] && echo "$out/stability.md" || echo docs/stability.md)
build="${WASHOUT_BUILD:-build}"
washout="${WASHOUT:-$build/engine/cli/washout}"
[ -x "$washout" ] || { echo "stability.sh: no washout in $build (build first)" >&2; exit 1; }
mkdir -p "$out"
rm -f "$out"/sweeps.txt

# The time-step sweeps lift dt_max (1 ms) so that the CFL number alone sets the step.
# sweep NAME "what it checks" SCENE --vary ... --set ...: one study, its folder out/NAME.
sweep() {
  local name="$1" what="$2" scene="$3"
  shift 3
  if [ -n "$only" ] && [[ "$only" != *",$name,"* ]]; then return 0; fi
  echo "== $name: $what"
  "$washout" study "$scene" --out "$out/$name" --threads "$threads" "$@" > "$out/$name.log" 2>&1 ||
    { echo "stability.sh: the study '$name' could not run:"; tail -5 "$out/$name.log"; exit 1; }
  tail -n +2 "$out/$name.log" | grep -E '^  ' || true
  printf '%s\t%s\t%s\n' "$name" "$scene" "$what" >> "$out"/sweeps.txt
}

db=scenes/dambreak_2d.lua gw=scenes/girder_washout_2d.lua
if [ $mode = quick ]; then
  # The corners of the documented envelope (docs/stability.md), cheap resolutions.
  sweep dt_alpha "time step (cfl / 0.3 = dt / dt_default) and alpha, dam break a/10" $db \
    --set d0=0.0146 --set end_time=0.27 --set dt_max=0.01 --vary cfl=0.1,0.6 --vary alpha=0,0.2
  sweep viscosity "viscosity from inviscid to 1 m^2/s, dam break a/10" $db \
    --set d0=0.0146 --set end_time=0.27 --vary viscosity=0,1
  sweep rest_2d "water at rest for 10 s, 2D, H/d0 = 10" scenes/hydrostatic_2d.lua \
    --set d0=0.01 --set end_time=10 --set output_interval=0.5 --vary alpha=0.05
  sweep box_drop "a heavy box dropped from 0.5 m into water" scenes/stability/box_drop_2d.lua \
    --set d0=0.02 --vary drop_height=0.5
else
  sweep dt_alpha "time step (cfl / 0.3 = dt / dt_default) and alpha, dam break a/20" $db \
    --set d0=0.0073 --set end_time=0.27 --set dt_max=0.01 --vary cfl=0.02,0.1,0.2,0.3,0.4,0.6 \
    --vary alpha=0,0.05,0.2,1
  sweep viscosity "viscosity from inviscid to 1 m^2/s, dam break a/10" $db \
    --set d0=0.0146 --set end_time=0.27 --vary viscosity=0,1e-6,1e-4,1e-2,1
  sweep contact "girder's contact stiffness E and restitution eps, 2D wash-out" $gw \
    --set end_time=1.2 --vary girder_young_modulus=1e6,1e8,5e9,1e11 \
    --vary girder_restitution=0.1,0.5,1.0
  sweep density "girder density (ratio to water 0.1 to 20) and d0, 2D wash-out" $gw \
    --set end_time=1.2 --vary girder_density=100,500,1161,5000,20000 --vary d0=0.01,0.0075
  sweep violent_gate "gate opened at once (100 m/s) against free fall, 2D wash-out" $gw \
    --set end_time=1.2 --vary gate_speed=0,100
  sweep violent_washout "the 0.35 m wash-out, 2D, to 2 s" $gw --vary water_height=0.35
  sweep box_drop "a heavy box dropped into water, by drop height" \
    scenes/stability/box_drop_2d.lua --vary drop_height=0.1,0.5
  sweep rest_2d "water at rest for 10 s, 2D" scenes/hydrostatic_2d.lua \
    --set end_time=10 --set output_interval=0.5 --vary d0=0.01,0.005
  sweep rest_3d "water at rest for 10 s, 3D, H/d0 = 10" scenes/hydrostatic_3d.lua \
    --set end_time=10 --set output_interval=0.5 --vary d0=0.01
  sweep rest_body "a floating box at rest for 10 s, 2D" scenes/floating_box_2d.lua \
    --set end_time=10 --set output_interval=0.5 --vary d0=0.01
fi
/usr/bin/python3 scripts/stability_report.py "$out" --report "$report" --mode $mode
