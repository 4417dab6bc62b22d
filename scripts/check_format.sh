#!/usr/bin/env bash
# Fails (exit 1) and lists the files when any tracked C++ source differs from what clang-format
# (.clang-format at the root) makes of it. Run by ctest as style.clang_format; fix with
#   git ls-files '*.cpp' '*.hpp' | xargs clang-format -i
set -uo pipefail
cd "$(dirname "$0")/.."
command -v clang-format >/dev/null || { echo "check_format: clang-format is not installed (bash scripts/bootstrap.sh installs it)"; exit 1; }
files=$(git ls-files '*.cpp' '*.hpp' 2>/dev/null) || { echo "check_format: not a git checkout"; exit 1; }
bad=()
for f in $files; do
  clang-format --dry-run --Werror "$f" >/dev/null 2>&1 || bad+=("$f")
done
if [ ${#bad[@]} -gt 0 ]; then
  echo "check_format: ${#bad[@]} file(s) not formatted: ${bad[*]}"
  exit 1
fi
echo "check_format: $(echo "$files" | wc -l) files formatted"
