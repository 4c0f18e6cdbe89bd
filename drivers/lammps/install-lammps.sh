#!/usr/bin/env bash
# Makes sure LAMMPS 4Feb2025 is built for the plugin, once per version: Open MPI from Debian, then
# Debian's trixie source package (fetch-lammps-source.sh) built with PLUGIN, GRANULAR, OPENMP and
# MPI as shared libraries under $EPAC_LAMMPS_PREFIX (default ~/.cache/epac/lammps/4Feb2025).
# A finished build is marked and reused. Prints two lines: the lmp executable and the LAMMPS src/
# folder (its headers, for -DEPAC_LAMMPS_SOURCE_DIR). Progress goes to stderr.
# Used by drivers/lammps/build.sh and by `bash cmake/dev.sh test` (the plugin's tests).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
prefix="${EPAC_LAMMPS_PREFIX:-$HOME/.cache/epac/lammps/4Feb2025}"
jobs=$(nproc)

bash "$root/cmake/install-deps.sh" libopenmpi-dev openmpi-bin >&2

lmp="$prefix/build/lmp"
src="$prefix/src/lammps-4Feb2025"
if [ ! -x "$lmp" ] || [ ! -f "$prefix/build/.epac-complete" ]; then
  tarball=$(bash "$here/fetch-lammps-source.sh" "$prefix/download" | tail -1)
  mkdir -p "$prefix/src"
  [ -d "$src" ] || tar -C "$prefix/src" -xJf "$tarball"
  echo "[epac] building LAMMPS 4Feb2025 (PLUGIN GRANULAR OPENMP, MPI, shared) in $prefix/build" >&2
  start=$(date +%s)
  cmake -S "$src/cmake" -B "$prefix/build" -D CMAKE_BUILD_TYPE=Release -D BUILD_MPI=on -D BUILD_OMP=on \
    -D BUILD_SHARED_LIBS=on -D PKG_PLUGIN=on -D PKG_GRANULAR=on -D PKG_OPENMP=on > "$prefix/configure.log" 2>&1 \
    || { tail -30 "$prefix/configure.log" >&2; exit 1; }
  cmake --build "$prefix/build" -j "$jobs" > "$prefix/build.log" 2>&1 || { tail -30 "$prefix/build.log" >&2; exit 1; }
  touch "$prefix/build/.epac-complete"
  echo "[epac] LAMMPS built in $(( $(date +%s) - start )) s" >&2
fi
echo "$lmp"
echo "$src/src"
