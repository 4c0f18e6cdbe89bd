#!/usr/bin/env bash
# The README's two commands. Each installs what it needs (Debian packages, Kokkos bootstrap via
# CMake), configures and builds, then:
#   bash cmake/dev.sh run [SCENE.toml] [epac-run options]   runs the driver (default scene)
#   bash cmake/dev.sh test [ctest options]                  builds and runs every test
#   bash cmake/dev.sh bench [benchmark options]             runs the contact-kernel benchmarks
#   bash cmake/dev.sh fuzz [Catch2 options]                 builds test_fuzz and runs the long fuzz
#       (docs/stability.md): EPAC_FUZZ_PATHS random paths per law and precision, each a wall and
#       a pair contact (default 500000: 1e6 contact paths), all five laws in double and float;
#       EPAC_FUZZ_LAWS=mdr runs only the laws whose name contains it (more options, e.g. one
#       precision or a first path index: tests/stability/test_fuzz_paths.cpp). About 50 min of CPU on one
#       core (67 min wall on this project's busy 2-core machine): EPAC_THREADS=1 bash cmake/dev.sh fuzz
#   bash cmake/dev.sh device                                builds for this machine's NVIDIA GPU and
#       runs the test suite, the benchmarks and the scaling script on it (cmake/device-run.sh)
# `test` includes the GPU compile check (ctest device_compile_check: every target compiled and
# linked with nvcc, warnings as errors; skipped without a CUDA toolkit, a failure then if CI=true).
# Environment: EPAC_BUILD_DIR (default build), EPAC_THREADS (default: all cores; sets
# OMP_NUM_THREADS), EPAC_CMAKE_ARGS (extra configure arguments, e.g. -DKokkos_ROOT=...),
# EPAC_LAMMPS (default on; off: `test` neither builds LAMMPS nor runs the plugin's tests).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cmd="${1:-}"; shift || true
build="${EPAC_BUILD_DIR:-$root/build}"
threads="${EPAC_THREADS:-${OMP_NUM_THREADS:-$(nproc)}}"
export OMP_NUM_THREADS="$threads" OMP_PROC_BIND="${OMP_PROC_BIND:-false}"

if [ "$cmd" = device ]; then
  # its own build dir and Kokkos (CUDA); with an offline bundle it installs nothing
  [ -f "${EPAC_DEVICE_BUNDLE:-$root/.device-bundle}/manifest.txt" ] || bash "$root/cmake/install-deps.sh"
  exec bash "$root/cmake/device-run.sh" "$@"
fi
bash "$root/cmake/install-deps.sh"
lammps_args=()
if [ "$cmd" = test ] && [ "${EPAC_LAMMPS:-on}" != off ]; then
  # the LAMMPS plugin's tests (tests/lammps/) need LAMMPS itself: built once, cached
  lammps=$(bash "$root/drivers/lammps/install-lammps.sh")
  lammps_args=(-DEPAC_LAMMPS_EXECUTABLE="$(sed -n 1p <<<"$lammps")" -DEPAC_LAMMPS_SOURCE_DIR="$(sed -n 2p <<<"$lammps")")
fi
mkdir -p "$build"
# shellcheck disable=SC2086
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release "${lammps_args[@]}" ${EPAC_CMAKE_ARGS:-} > "$build/epac-configure.log" 2>&1 \
  || { cat "$build/epac-configure.log"; exit 1; }
jobs=$(nproc)

case "$cmd" in
  run)
    cmake --build "$build" -j "$jobs" --target epac-run
    scene="$root/drivers/scenes/settling.toml"
    if [ $# -gt 0 ] && [[ "$1" != -* ]]; then scene="$1"; shift; fi
    # --overwrite: each `run` replaces the previous one's outputs (epac-run refuses a used folder)
    exec "$build/drivers/epac-run" "$scene" --threads "$threads" --overwrite "$@"
    ;;
  test)
    cmake --build "$build" -j "$jobs"
    cd "$build"
    # ctest runs $jobs tests at once, each with $threads OpenMP threads: more threads than cores.
    # Spinning OpenMP barriers then stall for whole scheduler slices; passive waiting does not.
    export OMP_WAIT_POLICY="${OMP_WAIT_POLICY:-passive}"
    exec ctest --output-on-failure -j "$jobs" "$@"
    ;;
  bench)
    cmake --build "$build" -j "$jobs" --target epac-bench-contacts
    exec "$build/bench/epac-bench-contacts" "$@"
    ;;
  fuzz)
    cmake --build "$build" -j "$jobs" --target test_fuzz
    export EPAC_FUZZ_PATHS="${EPAC_FUZZ_PATHS:-500000}"
    echo "[epac] long fuzz: $EPAC_FUZZ_PATHS paths per law and precision, $OMP_NUM_THREADS thread(s)"
    exec "$build/tests/stability/test_fuzz" "[.long]" "$@"
    ;;
  *)
    echo "usage: bash cmake/dev.sh run [SCENE.toml] [options] | test [ctest options] | bench [options] | fuzz [options] | device" >&2
    exit 2
    ;;
esac
