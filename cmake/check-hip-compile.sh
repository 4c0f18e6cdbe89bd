#!/usr/bin/env bash
# Opt-in compile-and-link check of epac for an AMD GPU (HIP), the counterpart of
# cmake/check-device-compile.sh (not in CI: on 2 cores the HIP Kokkos alone takes the better part
# of an hour). Uses Debian bookworm's hipcc 5.2.3 (apt-get install hipcc libamdhip64-dev) and
# bootstraps Kokkos 3.4.01 with HIP + Serial for EPAC_KOKKOS_HIP_ARCH (default VEGA908, MI100)
# into ~/.cache/epac/kokkos-3.4.01-hip-<arch> from Debian's trilinos source (no patch needed).
# Nothing is run (no AMD GPU is needed). docs/gpu.md says what it has compiled.
#   bash cmake/check-hip-compile.sh
# Environment: EPAC_HIP_BUILD_DIR (default build-hip-check), EPAC_HIP_TARGETS (default: all and
# epac-mdr-steady, as the CUDA check),
# EPAC_JOBS (default nproc), EPAC_CMAKE_ARGS. Without hipcc: "skipped: no hipcc", exit 0.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# shellcheck source=cmake/apt-private.sh
source "$root/cmake/apt-private.sh"
hipcc="$(command -v hipcc || true)"
if [ -z "$hipcc" ]; then echo "skipped: no hipcc (Debian: apt-get install hipcc libamdhip64-dev)"; exit 0; fi
arch="${EPAC_KOKKOS_HIP_ARCH:-VEGA908}"
jobs="${EPAC_JOBS:-$(nproc)}"
prefix="${XDG_CACHE_HOME:-$HOME/.cache}/epac/kokkos-3.4.01-hip-$(tr '[:upper:]' '[:lower:]' <<<"$arch")"
t0=$(date +%s)

# shared, as the other bootstraps: the LAMMPS engine is a module (a static libkokkoscore.a without
# -fPIC cannot be linked into it); the marker's name changed with it, so a static cache is rebuilt
if [ ! -f "$prefix/.epac-kokkos-shared-ok" ]; then
  work="$(mktemp -d "${TMPDIR:-/tmp}/epac-kokkos-hip.XXXXXX")"
  trap 'rm -rf "$work"' EXIT
  epac_kokkos_source "$work"
  ksrc="$work/kokkos"
  cmake -S "$ksrc" -B "$work/build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX="$prefix" \
    -DCMAKE_CXX_COMPILER="$hipcc" -DCMAKE_CXX_STANDARD=17 -DKokkos_ENABLE_HIP=ON -DKokkos_ENABLE_SERIAL=ON \
    -DKokkos_ARCH_"$arch"=ON -DBUILD_SHARED_LIBS=ON -DKokkos_ENABLE_TESTS=OFF
  cmake --build "$work/build" -j "$jobs"
  cmake --install "$work/build"
  touch "$prefix/.epac-kokkos-shared-ok"
fi

build="${EPAC_HIP_BUILD_DIR:-$root/build-hip-check}"
# shellcheck disable=SC2086
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DKokkos_ROOT="$prefix" -DCMAKE_CXX_COMPILER="$hipcc" \
  -DEPAC_BUILD_TESTS=ON -DEPAC_BUILD_BENCH=ON -DEPAC_BUILD_DRIVERS=ON ${EPAC_CMAKE_ARGS:-}
# shellcheck disable=SC2086
cmake --build "$build" -j "$jobs" --target ${EPAC_HIP_TARGETS:-all epac-mdr-steady}
echo "HIP compile check passed in $(( $(date +%s) - t0 )) s"
