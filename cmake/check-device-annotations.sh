#!/usr/bin/env bash
# nvcc's execution-space diagnostics on epac's headers without a CUDA Kokkos: compiles
# tests/device/annotations_mock.cu (see there) with nvcc against the host Kokkos epac is
# configured with, and fails on any nvcc diagnostic except the calls into Kokkos's host-only math
# (device functions in a CUDA Kokkos). Compile only. Skipped (exit 0, "skipped: no nvcc") without
# nvcc. The full check with a CUDA Kokkos is cmake/check-device-compile.sh.
#   bash cmake/check-device-annotations.sh KOKKOS_PREFIX EPAC_BUILD_DIR
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
kokkos="$1"; build="$2"
nvcc="$(command -v nvcc || true)"
[ -n "$nvcc" ] || { [ -x /usr/local/cuda/bin/nvcc ] && nvcc=/usr/local/cuda/bin/nvcc; } || true
if [ -z "$nvcc" ]; then echo "skipped: no nvcc"; exit 0; fi
arch="${EPAC_CUDA_ARCH:-sm_90}"
log="$build/device-annotations.log"
set +e
"$nvcc" -x cu -std=c++17 -arch="$arch" -c "$root/tests/device/annotations_mock.cu" -o "$build/device-annotations.o" \
  -I"$root/kernels" -I"$build/include" -I"$kokkos/include" -Xcompiler -fopenmp > "$log" 2>&1
rc=$?
set -e
# The expected noise: diagnostics located in kokkos_compat.hpp's wrappers of Kokkos's math.
unexpected="$(grep -E 'warning #|error' "$log" | grep -v 'kokkos_compat.hpp' || true)"
echo "$("$nvcc" --version | tail -1); $(grep -c 'warning #' "$log") diagnostics, all in kokkos_compat.hpp's Kokkos math calls unless listed below"
if [ $rc -ne 0 ] || [ -n "$unexpected" ]; then
  echo "nvcc (exit $rc) reported diagnostics on epac's code:"; echo "$unexpected"; cat "$log" | head -60
  exit 1
fi
echo "device annotations check passed"
