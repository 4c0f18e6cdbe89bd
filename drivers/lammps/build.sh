#!/usr/bin/env bash
# One command from nothing to `pair_style epac/...` inside LAMMPS on 2 MPI ranks:
#   1-2. Debian packages (epac's, plus Open MPI) and LAMMPS 4Feb2025 built once per version with
#      PLUGIN, GRANULAR, OPENMP and MPI (install-lammps.sh; cached under $EPAC_LAMMPS_PREFIX,
#      default ~/.cache/epac/lammps/4Feb2025);
#   3. epac configured against those LAMMPS headers, target epacplugin (drivers/lammps/);
#   4. unless --no-run: the example input on 2 MPI ranks.
# Prints the paths of lmp and epacplugin.so at the end.
# Usage: bash drivers/lammps/build.sh [--no-run]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="${EPAC_BUILD_DIR:-$root/build}"
jobs=$(nproc)

lammps=$(bash "$here/install-lammps.sh")
lmp=$(sed -n 1p <<<"$lammps")
src=$(sed -n 2p <<<"$lammps")

mkdir -p "$build"
# shellcheck disable=SC2086
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DEPAC_LAMMPS_SOURCE_DIR="$src" -DEPAC_LAMMPS_EXECUTABLE="$lmp" ${EPAC_CMAKE_ARGS:-} \
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
