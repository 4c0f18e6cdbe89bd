#!/usr/bin/env bash
# Checks that every tracked C++ file is formatted by .clang-format (Debian's clang-format 14, which
# cmake/install-deps.sh installs). Prints the files that differ and the command that fixes them.
#   bash cmake/check-format.sh          check (exit 1 on any difference)
#   bash cmake/check-format.sh --fix    format in place
# A different clang-format major version may format some constructs differently: the check then
# says which version it ran, so a difference is not mistaken for a style error.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
cf=""
for c in "${CLANG_FORMAT:-}" clang-format-14 clang-format; do
  if [ -n "$c" ] && command -v "$c" >/dev/null 2>&1; then cf="$c"; break; fi
done
if [ -z "$cf" ]; then echo "check-format: no clang-format (bash cmake/install-deps.sh installs it)" >&2; exit 1; fi
# the tracked C++ sources (git when this is a checkout, else a find over the source folders)
if git -C "$root" rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  mapfile -t files < <(git ls-files -- '*.cpp' '*.hpp' '*.h' '*.cu')
else
  mapfile -t files < <(find kernels drivers tests bench -name '*.cpp' -o -name '*.hpp' -o -name '*.h' -o -name '*.cu' | sort)
fi
if [ "${1:-}" = --fix ]; then
  "$cf" -i --style=file "${files[@]}"
  echo "check-format: formatted ${#files[@]} files with $("$cf" --version)"
  exit 0
fi
bad=()
for f in "${files[@]}"; do
  [ -f "$f" ] || continue
  if ! "$cf" --style=file "$f" | cmp -s - "$f"; then bad+=("$f"); fi
done
if ((${#bad[@]})); then
  echo "check-format: ${#bad[@]} of ${#files[@]} files are not formatted ($("$cf" --version)):"
  printf '  %s\n' "${bad[@]}"
  echo "fix with: bash cmake/check-format.sh --fix"
  exit 1
fi
echo "check-format: ${#files[@]} files formatted ($("$cf" --version))"
