#!/usr/bin/env bash
# Checks that the C++ sources follow .clang-format (the house style, 120 columns): lists each file clang-format
# would change and fails if there is one. Fix with: clang-format -i FILE (scripts/setup.sh installs clang-format).
set -euo pipefail
cd "$(dirname "$0")/.."
if ! command -v clang-format >/dev/null 2>&1; then echo "check-format: clang-format not found (scripts/setup.sh installs it)"; exit 1; fi
mapfile -t files < <(git ls-files 'src/*.cpp' 'src/*.hpp' 'src/*.h' 'tests/*.cpp' 'tests/*.hpp' 'bench/*.cpp' 'bench/*.hpp' 'fuzz/*.cpp' 'fuzz/*.hpp')
bad=0
for f in "${files[@]}"; do
  if ! clang-format --dry-run --Werror "$f" >/dev/null 2>&1; then echo "check-format: $f is not formatted (clang-format -i $f)"; bad=$((bad + 1)); fi
done
echo "check-format: ${#files[@]} files, $bad not formatted"
[ "$bad" -eq 0 ]
