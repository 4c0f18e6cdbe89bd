#!/usr/bin/env bash
# ctest device_prebuilt_check: the rules of cmake/device-prebuilt-check.sh on a made-up checkout.
# A GPU slot must not run executables built from other sources (a stale bundle), nor rebuild
# because a document changed.
#   bash tests/package/check_device_prebuilt.sh PATH/TO/device-prebuilt-check.sh
set -euo pipefail
check="${1:?usage: check_device_prebuilt.sh device-prebuilt-check.sh}"
work="$(mktemp -d "${TMPDIR:-/tmp}/epac-prebuilt-check.XXXXXX")"
trap 'rm -rf "$work"' EXIT
root="$work/repo" bundle="$work/repo/.device-bundle" build="$work/repo/build-device"
mkdir -p "$root/kernels" "$root/docs" "$bundle"
git -C "$root" init -q
echo 'int a;' > "$root/kernels/a.hpp"
echo 'cmake_minimum_required(VERSION 3.16)' > "$root/CMakeLists.txt"
echo 'prose' > "$root/docs/gpu.md"
echo 'prose' > "$root/README.md"
git -C "$root" add kernels/a.hpp CMakeLists.txt docs/gpu.md README.md
fail() { echo "FAIL: $*"; exit 1; }

bash "$check" hash "$root" > "$bundle/prebuilt.sha256"
grep -q ' kernels/a.hpp$' "$bundle/prebuilt.sha256" || fail "the hash list misses kernels/a.hpp"
grep -q ' CMakeLists.txt$' "$bundle/prebuilt.sha256" || fail "the hash list misses CMakeLists.txt"
if grep -q -e 'docs/' -e 'README' "$bundle/prebuilt.sha256"; then fail "the hash list holds prose"; fi
printf 'root=%s\nbuild=%s\narch=AMPERE80\n' "$root" "$build" > "$bundle/prebuilt.txt"
: > "$bundle/prebuilt.tar.xz"

# fits: exit 0, nothing printed
fits() { bash "$check" fits "$bundle" "$1" "$2" "$3"; }
out="$(fits "$root" "$build" AMPERE80)" || fail "an unchanged checkout does not fit: $out"
[ -z "$out" ] || fail "a fit printed: $out"
echo 'other prose' > "$root/docs/gpu.md"
echo 'other prose' > "$root/README.md"
out="$(fits "$root" "$build" AMPERE80)" || fail "a changed document made it stale: $out"

# does not fit: exit 1, one line naming why
nofit() {  # EXPECTED-TEXT ROOT BUILD ARCH
  local want="$1"; shift
  if out="$(fits "$@")"; then fail "fits, expected '$want'"; fi
  grep -q -- "$want" <<< "$out" || fail "expected '$want', got: $out"
  echo "ok: $out"
}
echo 'int b;' > "$root/kernels/a.hpp"
nofit "kernels/a.hpp" "$root" "$build" AMPERE80
echo 'int a;' > "$root/kernels/a.hpp"
mv "$root/CMakeLists.txt" "$work/moved"
nofit "CMakeLists.txt" "$root" "$build" AMPERE80
mv "$work/moved" "$root/CMakeLists.txt"
fits "$root" "$build" AMPERE80 > /dev/null || fail "the restored checkout does not fit"
nofit "built for AMPERE80" "$root" "$build" AMPERE86
nofit "this build folder is" "$root" "$work/elsewhere" AMPERE80
nofit "this one is" "$work/elsewhere" "$build" AMPERE80
rm "$bundle/prebuilt.tar.xz"
nofit "no prebuilt.tar.xz" "$root" "$build" AMPERE80
echo "device prebuilt check: passed"
