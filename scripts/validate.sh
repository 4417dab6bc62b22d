#!/usr/bin/env bash
# The validation report in one command: `washout study` on every validation case at two or
# three resolutions, then docs/validation.md (table of errors, wall times, observed orders,
# plots in docs/images/validation/). Fails (exit 1) if a run does not complete or an error
# exceeds the bound its scene documents (washout.validation{bound = ...}).
#
#   bash scripts/validate.sh            full: three resolutions where affordable (~30 min, 2 cores)
#   bash scripts/validate.sh --quick    the coarsest resolutions of the cheap cases (about a minute;
#                                       ctest runs it as validation.quick)
#
# WASHOUT=path/to/washout picks the program (default build/engine/cli/washout);
# VALIDATION_OUT=DIR the study folders (default runs/validation); REPORT=FILE the report
# (default docs/validation.md); VALIDATION_THREADS=N threads per run (default 1: OpenMP teams
# that share cores with other work spin at their barriers and the wall times become noise).
set -euo pipefail
cd "$(dirname "$0")/.."
mode=full
for arg in "$@"; do
  case "$arg" in
    --quick) mode=quick ;;
    -h|--help) sed -n '2,15p' "$0"; exit 0 ;;
    *) echo "validate.sh: unknown option '$arg'" >&2; exit 1 ;;
  esac
done
washout=${WASHOUT:-build/engine/cli/washout}
if [ ! -x "$washout" ]; then
  echo "validate.sh: $washout not found: build first (bash scripts/bootstrap.sh test) or set WASHOUT" >&2
  exit 1
fi
out=${VALIDATION_OUT:-runs/validation}
report=${REPORT:-docs/validation.md}
images=$(dirname "$report")/images/validation
mkdir -p "$out" "$images"

# name | dim | scene | what | quick d0 (empty: full report only) | full d0 | fixed --set (space separated)
# Every d0 must divide the scene's lengths (particles sit on the lattice (i + 1/2) d0): a d0
# that does not leaves a gap at a wall and a lower water level, which is not a resolution effect.
cases=(
  "hydrostatic_2d|2|scenes/hydrostatic_2d.lua|water at rest, H = 0.1 m, analytic|0.01,0.005|0.01,0.005,0.0025|end_time=0.5"
  "hydrostatic_3d|3|scenes/hydrostatic_3d.lua|water at rest, H = 0.1 m, t = 0.1 s (3D still water is disturbed later, docs/method.md)|0.01,0.005|0.01,0.0071428571,0.005|end_time=0.1 output_interval=0.05"
  "dambreak_2d|2|scenes/dambreak_2d.lua|Martin & Moyce n^2 = 2 front, a = 0.146 m, T <= 3 (tabulated experiment)|0.0146,0.0073|0.0146,0.0073,0.00365|"
  "dambreak_3d|3|scenes/dambreak_3d.lua|Martin & Moyce n^2 = 2 front in a tank a/2 wide, T <= 3|0.0146|0.0146,0.0073|"
  "lobovsky_2d|2|scenes/validation/lobovsky_2d.lua|Lobovsky et al. 2014, H = 0.3 m (experiment: front, gauges H1-H4, sensor 1)||0.01,0.0075,0.005|"
  "spheric_test2_3d|3|scenes/validation/spheric_test2_3d.lua|SPHERIC Test 2, Kleefsman et al. 2005: a 3D dam break against a box (experiment: arrivals, gauges H1-H4, pressures P1-P4 on the box)||0.05,0.025|"
  "poiseuille_2d|2|scenes/poiseuille_2d.lua|plane Poiseuille start-up, series solution (L/d0 >= 20: the periodic length needs 3 kernel supports)|0.005|0.005,0.0033333333,0.0025|"
  "floating_box_2d|2|scenes/floating_box_2d.lua|box of density 500 released at draft 0.03 m, Archimedes D = 0.05 m, t <= 1.5 s|0.01|0.01,0.005|end_time=1.5"
)

dirs=()
start=$(date +%s)
for c in "${cases[@]}"; do
  IFS='|' read -r name dim scene what quick full sets <<<"$c"
  d0s=$full
  [ "$mode" = quick ] && d0s=$quick
  [ -n "$d0s" ] || continue  # not in the quick report (a case too slow for CI)
  dir=$out/$name
  rm -rf "$dir"
  mkdir -p "$dir"
  echo "$name|$dim|$scene|$what" >"$dir/case.txt"
  args=(study "$scene" --vary "d0=$d0s" --out "$dir" --threads "${VALIDATION_THREADS:-1}")
  for s in $sets; do args+=(--set "$s"); done
  echo "== $name: washout ${args[*]}"
  "$washout" "${args[@]}" | tee "$dir/study.log"
  [ -f "$dir/study.png" ] && cp "$dir/study.png" "$images/$name.png"
  dirs+=("$dir")
done
echo "== all studies in $(( $(date +%s) - start )) s"
/usr/bin/python3 scripts/validation_report.py "$report" "$mode" "${dirs[@]}"
