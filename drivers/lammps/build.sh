#!/usr/bin/env bash
# One command from nothing to `pair_style epac/...` inside LAMMPS on 2 MPI ranks:
#   1. Debian packages (epac's, plus Open MPI);
#   2. LAMMPS 4Feb2025 from Debian's trixie source package (fetch-lammps-source.sh), built once per
#      version with PLUGIN, GRANULAR, OPENMP and MPI as shared libraries, cached under
#      $EPAC_LAMMPS_PREFIX (default ~/.cache/epac/lammps/4Feb2025);
#   3. epac configured against those LAMMPS headers, target epacplugin (drivers/lammps/);
#   4. unless --no-run: the example input on 2 MPI ranks.
# Prints the paths of lmp and epacplugin.so at the end.
# Usage: bash drivers/lammps/build.sh [--no-run]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
prefix="${EPAC_LAMMPS_PREFIX:-$HOME/.cache/epac/lammps/4Feb2025}"
build="${EPAC_BUILD_DIR:-$root/build}"
jobs=$(nproc)

bash "$root/cmake/install-deps.sh" libopenmpi-dev openmpi-bin

lmp="$prefix/build/lmp"
src="$prefix/src/lammps-4Feb2025"
if [ ! -x "$lmp" ] || [ ! -f "$prefix/build/.epac-complete" ]; then
  tarball=$(bash "$here/fetch-lammps-source.sh" "$prefix/download" | tail -1)
  mkdir -p "$prefix/src"
  [ -d "$src" ] || tar -C "$prefix/src" -xJf "$tarball"
  echo "[epac] building LAMMPS 4Feb2025 (PLUGIN GRANULAR OPENMP, MPI, shared) in $prefix/build"
  cmake -S "$src/cmake" -B "$prefix/build" -D CMAKE_BUILD_TYPE=Release -D BUILD_MPI=on -D BUILD_OMP=on \
    -D BUILD_SHARED_LIBS=on -D PKG_PLUGIN=on -D PKG_GRANULAR=on -D PKG_OPENMP=on > "$prefix/configure.log" 2>&1 \
    || { tail -30 "$prefix/configure.log"; exit 1; }
  cmake --build "$prefix/build" -j "$jobs" > "$prefix/build.log" 2>&1 || { tail -30 "$prefix/build.log"; exit 1; }
  touch "$prefix/build/.epac-complete"
fi

mkdir -p "$build"
# shellcheck disable=SC2086
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DEPAC_LAMMPS_SOURCE_DIR="$src/src" ${EPAC_CMAKE_ARGS:-} \
  > "$build/epac-configure.log" 2>&1 || { cat "$build/epac-configure.log"; exit 1; }
cmake --build "$build" -j "$jobs" --target epacplugin
plugin="$build/drivers/lammps/epacplugin.so"

if [ "${1:-}" != "--no-run" ]; then
  cd "$here/examples"
  OMP_NUM_THREADS=1 mpirun --allow-run-as-root --oversubscribe -np 2 "$lmp" -var plugin "$plugin" \
    -in in.settling -log none
fi
echo "lmp:    $lmp"
echo "plugin: $plugin"
