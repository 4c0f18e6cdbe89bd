#!/usr/bin/env bash
# Compile-only check of the library for a GPU: configures epac with a Kokkos that has the CUDA
# backend and builds the library tests (not the drivers or benchmarks) with warnings as errors,
# nvcc's own diagnostics included (e.g. 20011/20013: a host function called from a
# __host__ __device__ one; 20012: an annotation on a defaulted function). Nothing is run.
#   bash cmake/check-device-compile.sh [KOKKOS_CUDA_PREFIX]
# The prefix may also come from EPAC_KOKKOS_CUDA_ROOT or Kokkos_ROOT; otherwise the usual
# prefixes are searched. Without a Kokkos with CUDA it prints "skipped: no Kokkos with CUDA" and
# exits 0. Environment: EPAC_DEVICE_BUILD_DIR (default build-device), EPAC_DEVICE_TARGETS (default:
# every library test target), EPAC_DEVICE_FLAGS (default -Werror -Xcudafe --promote_warnings, for
# nvcc_wrapper), EPAC_CMAKE_ARGS (extra configure arguments).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

has_cuda() { grep -qs '^#define KOKKOS_ENABLE_CUDA$' "$1/include/KokkosCore_config.h"; }
prefix=""
candidates=("${1:-}" "${EPAC_KOKKOS_CUDA_ROOT:-}" "${Kokkos_ROOT:-}")
IFS=: read -r -a cpp <<< "${CMAKE_PREFIX_PATH:-}"
candidates+=("${cpp[@]}" /usr/local /opt/kokkos /usr/local/kokkos /opt/kokkos-cuda)
for c in "${candidates[@]}"; do
  [ -n "$c" ] || continue
  if has_cuda "$c"; then prefix="$c"; break; fi
done
if [ -z "$prefix" ]; then
  echo "skipped: no Kokkos with CUDA (searched: ${candidates[*]})"
  exit 0
fi

compiler="${CXX:-}"
if [ -x "$prefix/bin/nvcc_wrapper" ]; then compiler="$prefix/bin/nvcc_wrapper"; fi
build="${EPAC_DEVICE_BUILD_DIR:-$root/build-device}"
echo "Kokkos with CUDA at $prefix; compiler ${compiler:-default}; build dir $build"
# -Werror for the host compiler (nvcc_wrapper passes it on) and --promote_warnings for nvcc's
# front end (cudafe: the cross-execution-space diagnostics 20011-20014). Both spellings are ones
# nvcc_wrapper knows (it would hand an unknown nvcc flag such as --Werror to the host compiler).
flags="${EPAC_DEVICE_FLAGS:--Werror -Xcudafe --promote_warnings}"
# shellcheck disable=SC2086
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DKokkos_ROOT="$prefix" \
  ${compiler:+-DCMAKE_CXX_COMPILER="$compiler"} -DCMAKE_CXX_FLAGS="$flags" \
  -DEPAC_BUILD_TESTS=ON -DEPAC_BUILD_BENCH=OFF -DEPAC_BUILD_DRIVERS=OFF ${EPAC_CMAKE_ARGS:-}
targets="${EPAC_DEVICE_TARGETS:-}"
if [ -z "$targets" ]; then
  # every executable under tests/ (the library tests; the driver tests are off with the drivers)
  targets="$(cmake --build "$build" --target help | sed -n 's/^\.\.\. \(test_[A-Za-z0-9_]*\).*/\1/p' | tr '\n' ' ')"
fi
echo "building: $targets"
# shellcheck disable=SC2086
cmake --build "$build" -j "$(nproc)" --target $targets
echo "device compile check passed: $targets"
