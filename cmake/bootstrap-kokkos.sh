#!/usr/bin/env bash
# Bootstraps Kokkos 3.4.01 (OpenMP + Serial) from Debian's trilinos source package into a cache
# prefix, when no Kokkos with OpenMP is installed (docs/design.md section 10). Prints the prefix.
#
# apt-get source needs deb-src entries: cmake/apt-private.sh derives them at run time from this
# machine's own apt configuration into private folders (the system configuration is never
# changed). Offline: EPAC_KOKKOS_SOURCE (see cmake/apt-private.sh).
# Idempotent: a finished install (stamp file) is reused at no cost.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# shellcheck source=cmake/apt-private.sh
source "$root/cmake/apt-private.sh"
prefix="${EPAC_KOKKOS_PREFIX:-${XDG_CACHE_HOME:-$HOME/.cache}/epac/kokkos-3.4.01}"
stamp="$prefix/.epac-kokkos-ok"
if [ -f "$stamp" ]; then echo "$prefix"; exit 0; fi

work="$(mktemp -d "${TMPDIR:-/tmp}/epac-kokkos.XXXXXX")"
trap 'rm -rf "$work"' EXIT
t0=$(date +%s)
epac_kokkos_source "$work"
ksrc="$work/kokkos"

cmake -S "$ksrc" -B "$work/build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX="$prefix" \
  -DKokkos_ENABLE_OPENMP=ON -DKokkos_ENABLE_SERIAL=ON -DCMAKE_CXX_STANDARD=17 \
  -DBUILD_SHARED_LIBS=ON -DKokkos_ENABLE_TESTS=OFF >&2
cmake --build "$work/build" -j "$(nproc)" >&2
cmake --install "$work/build" >&2
echo "[epac] Kokkos bootstrap took $(( $(date +%s) - t0 )) s" >&2
touch "$stamp"
echo "$prefix"
