#!/usr/bin/env bash
# One entry point for a fresh Debian 12 machine (run as root or with sudo available):
#   bash scripts/bootstrap.sh run    installs what is missing, builds, runs the default scene
#                                    (the girder wash-out, 3D) and plots the girder's motion
#   bash scripts/bootstrap.sh test   installs what is missing, builds, runs the test suite
# Extra arguments after `test` go to ctest (e.g. `-L long` for the long validations).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"
mode="${1:-run}"
shift || true

packages=(build-essential cmake pkg-config git
          liblua5.4-dev libeigen3-dev libsuitesparse-dev libhdf5-dev libhypre-dev
          libosmesa6-dev libpng-dev libgtest-dev clang-format
          python3 python3-matplotlib python3-h5py python3-numpy)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "== installing: ${missing[*]}"
  sudo_cmd=""
  if [ "$(id -u)" -ne 0 ]; then sudo_cmd="sudo"; fi
  export DEBIAN_FRONTEND=noninteractive
  $sudo_cmd apt-get update -qq
  $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

jobs="$(nproc)"
echo "== building (Release, $jobs jobs)"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release > build.log 2>&1 || { cat build.log; exit 1; }
cmake --build build -j "$jobs" >> build.log 2>&1 || { tail -50 build.log; exit 1; }

case "$mode" in
  run)
    scene="${WASHOUT_DEFAULT_SCENE:-scenes/girder_washout.lua}"
    name="$(basename "$scene" .lua)"
    out="runs/$name"
    echo "== running $scene into $out/ (the default, 3D at d0 = 0.02 m, takes about ten minutes on two cores)"
    status=0
    ./build/engine/cli/washout run "$scene" --out "$out" --quiet "$@" || status=$?
    # A run that stopped as unstable (2) keeps its file: draw what it has before failing.
    if [ -f "$out/$name.h5" ] && [ -f "$out/girder.csv" ]; then
      /usr/bin/python3 scripts/plot_washout.py "$out" --out "$out/$name.png" || status=3
    fi
    echo "== done: $out/$name.h5 (open $out/$name.xdmf in ParaView), body CSVs $out/*.csv,"
    echo "   plot $out/$name.png, frames in $out/frames/ (exit status $status)"
    exit $status
    ;;
  test)
    echo "== running the test suite"
    cd build
    if [ $# -gt 0 ]; then ctest --output-on-failure -j "$jobs" "$@"; else ctest --output-on-failure -j "$jobs" -LE long; fi
    ;;
  *)
    echo "usage: bash scripts/bootstrap.sh run|test [args]" >&2
    exit 2
    ;;
esac
