#!/usr/bin/env bash
# Compile-and-link check of epac for a GPU (CUDA): configures epac with a Kokkos that has the CUDA
# backend and builds every target (library tests, driver tests, benchmarks, epac-run and the
# other tools, the LAMMPS plugin's engine, plus the benchmark built on request only) with
# warnings as errors, nvcc's own diagnostics included (e.g. 20011/20013: a host function called
# from a __host__ __device__ one; 20012: an annotation on a defaulted function). Nothing is run
# (docs/gpu.md).
#   bash cmake/check-device-compile.sh [KOKKOS_CUDA_PREFIX]
# The prefix may also come from EPAC_KOKKOS_CUDA_ROOT; otherwise Kokkos with CUDA is bootstrapped
# (cmake/bootstrap-kokkos-cuda.sh, AMPERE80). Without a CUDA toolkit it prints "skipped: no CUDA
# toolkit" and exits 0, except under CI=true, where a missing toolkit is a failure.
# Any line of the build that reads as a warning (host compiler, nvcc, ptxas, nvlink) fails it too.
# Environment: EPAC_DEVICE_BUILD_DIR (default build-device-check), EPAC_DEVICE_TARGETS (default:
# all, and epac-mdr-steady), EPAC_DEVICE_FLAGS (default -Xcudafe --promote_warnings -Werror),
# EPAC_DEVICE_LAMMPS_SOURCE_DIR (LAMMPS src/: the whole plugin, not yet tried; default: its
# engine only), EPAC_JOBS (default: nproc), EPAC_CMAKE_ARGS (extra configure arguments).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
t0=$(date +%s)

has_cuda() { grep -qs '^#define KOKKOS_ENABLE_CUDA$' "$1/include/KokkosCore_config.h"; }
prefix=""
for c in "${1:-}" "${EPAC_KOKKOS_CUDA_ROOT:-}"; do
  if [ -n "$c" ]; then
    has_cuda "$c" || { echo "error: $c is not a Kokkos with CUDA (no KOKKOS_ENABLE_CUDA in include/KokkosCore_config.h)"; exit 1; }
    prefix="$c"; break
  fi
done
if [ -z "$prefix" ]; then
  rc=0
  prefix="$(bash "$root/cmake/bootstrap-kokkos-cuda.sh")" || rc=$?
  if [ "$rc" -eq 3 ]; then
    if [ "${CI:-}" = true ]; then
      echo "error: no CUDA toolkit (nvcc), and CI=true: CI machines have one (/usr/local/cuda*), so this is a failure"
      exit 1
    fi
    echo "skipped: no CUDA toolkit (no nvcc in \$CUDA_HOME, PATH or /usr/local/cuda*)"
    exit 0
  elif [ "$rc" -ne 0 ]; then
    echo "error: the CUDA Kokkos bootstrap failed (cmake/bootstrap-kokkos-cuda.sh)"
    exit 1
  fi
fi

compiler="$prefix/bin/nvcc_wrapper"
build="${EPAC_DEVICE_BUILD_DIR:-$root/build-device-check}"
jobs="${EPAC_JOBS:-$(nproc)}"
mkdir -p "$build"
echo "Kokkos with CUDA at $prefix ($(sed -n 's/.*cuda=\([0-9.]*\).*arch=\(.*\)/CUDA \1, \2/p' "$prefix/.epac-kokkos-ok" 2>/dev/null)); build dir $build"
# -Werror for the host compiler (nvcc_wrapper passes it on) and --promote_warnings for nvcc's
# front end (cudafe: the cross-execution-space diagnostics 20011-20014). In this order: CMake's
# compiler check strips "-Werror <next word>" and g++ would then reject a lone --promote_warnings.
flags="${EPAC_DEVICE_FLAGS:--Xcudafe --promote_warnings -Werror}"
lammps=()
if [ -n "${EPAC_DEVICE_LAMMPS_SOURCE_DIR:-}" ]; then lammps=(-DEPAC_LAMMPS_SOURCE_DIR="$EPAC_DEVICE_LAMMPS_SOURCE_DIR"); fi
# What this check exists for is decided before code generation for the host: nvcc's front end
# (cudafe: cross-execution-space calls, lambdas), its device compiler (cicc, always optimising) and
# ptxas, and the link. So the host side is compiled at -O0 (half of each file's time at -O3), and
# each target's sources in unity batches (CMake's UNITY_BUILD: the Kokkos headers parsed, and
# shared kernels instantiated, once per batch, not once per file; the sources keep no file-local
# names that would collide). Measured on a 2-core machine: see docs/gpu.md. The host compiler's
# flow warnings (-Wmaybe-uninitialized needs -O1) are the host build's, which compiles every file
# on its own at -O3. EPAC_CMAKE_ARGS="-DCMAKE_UNITY_BUILD=OFF -DCMAKE_CXX_FLAGS_RELEASE=-O3"
# restores the file-by-file, optimised check.
# Ninja where it can be had (Debian's ninja-build): it compiles a target's files while the
# libraries it links are still being built, where Makefiles wait target by target, so both cores
# stay busy to the end. A build folder keeps the generator it was made with.
gen=()
if [ ! -f "$build/CMakeCache.txt" ]; then
  command -v ninja > /dev/null 2>&1 || bash "$root/cmake/install-deps.sh" ninja-build > /dev/null 2>&1 || true
  if command -v ninja > /dev/null 2>&1; then gen=(-G Ninja); fi
fi
# shellcheck disable=SC2086
cmake -S "$root" -B "$build" "${gen[@]}" -DCMAKE_BUILD_TYPE=Release -DKokkos_ROOT="$prefix" -DCMAKE_CXX_COMPILER="$compiler" \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_CXX_FLAGS_RELEASE="-O0 -DNDEBUG" -DCMAKE_UNITY_BUILD=ON \
  -DEPAC_BUILD_TESTS=ON -DEPAC_BUILD_BENCH=ON -DEPAC_BUILD_DRIVERS=ON \
  "${lammps[@]}" ${EPAC_CMAKE_ARGS:-} > "$build/epac-configure.log" 2>&1 \
  || { cat "$build/epac-configure.log"; echo "error: configure failed"; exit 1; }
targets="${EPAC_DEVICE_TARGETS:-all epac-mdr-steady}"
echo "building: $targets (-j $jobs)"
log="$build/epac-device-build.log"
keep_going=(-- -k)  # every error of the tree in one run (Makefiles; Ninja: -k 0)
[ -f "$build/build.ninja" ] && keep_going=(-- -k 0)
set +e
# shellcheck disable=SC2086
cmake --build "$build" -j "$jobs" --target $targets "${keep_going[@]}" > "$log" 2>&1
rc=$?
set -e
# warnings that did not stop the build (nvcc driver, ptxas, nvlink, linker) fail the check too
warnings="$(grep -E '(^|[ :])([Ww]arning)( #[0-9]+-D)? ?:' "$log" || true)"
if [ "$rc" -ne 0 ] || [ -n "$warnings" ]; then
  grep -E -B2 -A6 '(error|[Ww]arning)( #[0-9]+-D)? ?:|Error [0-9]' "$log" | head -n 300
  echo "device compile check FAILED after $(( $(date +%s) - t0 )) s (build exit $rc; full log: $log)"
  exit 1
fi
echo "device compile check passed in $(( $(date +%s) - t0 )) s: $targets"
