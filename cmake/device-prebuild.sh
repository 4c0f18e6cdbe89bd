#!/usr/bin/env bash
# Builds here what `bash cmake/dev.sh device` would build on the GPU machine and packs it into the
# device bundle, so that a GPU session spends its minutes running, not compiling (docs/gpu.md,
# "Prebuilt"). The first GPU session (2026-12-04) built on the GPU machine and its 15 minutes ran
# out before the tests: the CUDA build of the tests, benchmarks and epac-run takes about 40
# minutes of two cores here.
#   bash cmake/device-prebuild.sh [BUNDLE_DIR]     (default .device-bundle; makes it if missing)
# Adds to BUNDLE_DIR:
#   prebuilt.tar.xz   the executables, every CTestTestfile.cmake, and the Kokkos and CUDA runtime
#                     libraries they load, at the absolute paths of this build folder
#   prebuilt.sha256   the hash of every tracked file they were built from
#   prebuilt.txt      commit, Kokkos arch, nvcc and host compiler, paths, sizes
# cmake/device-run.sh unpacks it in place of its steps 2-3 when the checkout and build folder have
# the same paths as here, the arch is the one it would choose and every tracked file matches
# prebuilt.sha256; else it builds, and says why. The GPU machine then needs no CUDA toolkit, only
# a driver for CUDA 13.
# Environment: EPAC_DEVICE_ARCH (default AMPERE80: sm_80 code and PTX, which Hopper and newer
# compile at the first launch), EPAC_DEVICE_BUILD_DIR (default build-device), EPAC_JOBS.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bundle="${1:-$root/.device-bundle}"
[ -f "$bundle/manifest.txt" ] || bash "$root/cmake/device-bundle.sh" "$bundle"
bundle="$(cd "$bundle" && pwd)"
build="${EPAC_DEVICE_BUILD_DIR:-$root/build-device}"
arch="${EPAC_DEVICE_ARCH:-AMPERE80}"

# device-run.sh without a GPU builds for $arch and stops before the runs (exit 1): the build log
# says whether the build itself passed.
set +e
EPAC_DEVICE_BUNDLE="$bundle" EPAC_DEVICE_ARCH="$arch" EPAC_DEVICE_BUILD_DIR="$build" \
  bash "$root/cmake/device-run.sh"
set -e
build="$(cd "$build" && pwd)"
if ! grep -q $'^build\tok' "$build/report/steps.tsv"; then
  echo "error: the CUDA build failed (log: $build/report/build.log)" >&2
  exit 1
fi
prefix="$(sed -n 's/^Kokkos_DIR:PATH=\(.*\)\/lib\/cmake\/Kokkos$/\1/p' "$build/CMakeCache.txt")"
[ -d "$prefix/lib" ] || { echo "error: no Kokkos install found from $build/CMakeCache.txt" >&2; exit 1; }

# The shared libraries the executables load from outside the build (Kokkos, the CUDA runtime) are
# copied into <build>/prebuilt-lib, which device-run.sh puts first on LD_LIBRARY_PATH: the
# archive unpacks inside the build folder alone and overwrites nothing of the GPU machine's.
libdir="$build/prebuilt-lib"
rm -rf "$libdir"
mkdir -p "$libdir"
cp -a "$prefix"/lib/*.so* "$libdir/"
probe="$(find "$build/tests" -type f -name 'test_core' | head -n1)"
cudart="$(ldd "$probe" | sed -n 's/.*libcudart[^ ]* => \([^ ]*\).*/\1/p' | head -n1)"
if [ -n "$cudart" ]; then cp -L "$cudart" "$libdir/"; fi
stage="$(mktemp -d "${TMPDIR:-/tmp}/epac-prebuilt.XXXXXX")"
trap 'rm -rf "$stage"' EXIT
list="$stage/files"
# Executables (ELF files with the execute bit), the ctest files that name them, the libraries;
# paths relative to /, so that they unpack where they were built.
(cd / && find "${build#/}" -type f -perm -u+x ! -path '*/CMakeFiles/*' ! -path '*/sysroot/*' \
   ! -path '*/prebuilt-lib/*' -exec sh -c 'head -c4 "$1" | grep -q ELF' _ {} \; -print) > "$list"
nexe=$(wc -l < "$list")
(cd / && find "${build#/}" -name CTestTestfile.cmake ! -path '*/sysroot/*') >> "$list"
(cd / && find "${libdir#/}" -mindepth 1) >> "$list"
raw=$(cd / && xargs -a "$list" du -cb | tail -n1 | cut -f1)
echo "[prebuild] packing $nexe executables ($((raw / 1048576)) MiB with the libraries) into $bundle/prebuilt.tar.xz"
tar -C / --no-recursion -cf - -T "$list" | xz -T0 -6 > "$bundle/prebuilt.tar.xz"
# What the executables were built from, checked file by file on the GPU machine.
bash "$root/cmake/device-prebuilt-check.sh" hash "$root" > "$bundle/prebuilt.sha256"
nvcc="$(sed -n 's/^nvcc=\([^ ]*\).*/\1/p' "$prefix/.epac-kokkos-ok")"
{
  echo "commit=$(git -C "$root" rev-parse HEAD)"
  echo "tree=$(if [ -z "$(git -C "$root" status --porcelain --untracked-files=no)" ]; then echo clean; else echo "modified (prebuilt.sha256 holds what was built)"; fi)"
  echo "root=$root"
  echo "build=$build"
  echo "kokkos=$prefix"
  echo "arch=$arch"
  echo "nvcc=$("$nvcc" --version | sed -n 's/.*release \([0-9.]*\),.*/\1/p')"
  echo "host_compiler=$(g++ --version | head -n1)"
  echo "made=$(date -u +%Y-%m-%dT%H:%MZ) on $(. /etc/os-release && echo "$PRETTY_NAME")"
  echo "executables=$nexe"
  echo "bytes=$(stat -c %s "$bundle/prebuilt.tar.xz")"
} > "$bundle/prebuilt.txt"
cat "$bundle/prebuilt.txt"
echo "[prebuild] $bundle: $(du -sh "$bundle" | cut -f1) in all"
