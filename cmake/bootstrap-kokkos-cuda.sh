#!/usr/bin/env bash
# Bootstraps Kokkos 3.4.01 with the CUDA backend (CUDA + Serial, CUDA lambdas) from Debian's
# trilinos source package into a cache prefix, for GPU builds of epac (docs/gpu.md). Prints the
# prefix (~/.cache/epac/kokkos-3.4.01-cuda<version>-<arch>, one per toolkit version). The
# nvcc_wrapper installed there finds nvcc by the absolute path used here. Offline:
# EPAC_KOKKOS_SOURCE=<a tarball holding */packages/kokkos, or a Kokkos 3.4.01 tree> skips apt-get.
#   bash cmake/bootstrap-kokkos-cuda.sh [KOKKOS_ARCH]     (default AMPERE80: sm_80 code + PTX)
# nvcc: $CUDA_HOME/bin, $CUDA_PATH/bin, PATH, then the newest /usr/local/cuda*/bin (CUDA 12 without a
# system install: CUDA_HOME="$(bash cmake/fetch-cuda-debian.sh)"). Without one it
# prints "no CUDA toolkit" and exits 3. Environment: EPAC_KOKKOS_CUDA_PREFIX (the install prefix).
# Idempotent: a finished install (stamp file naming the nvcc version and arch) is reused at no
# cost; a different nvcc makes a fresh build. Concurrent calls wait for each other (flock).
#
# Kokkos 3.4.01 predates CUDA 12; three patches make it build with CUDA 12.x and 13.x (each is a
# no-op on the versions it was written for):
#  1. bin/nvcc_wrapper: default -arch sm_35 (rejected since CUDA 12) -> sm_80; nvcc by absolute path.
#  2. Kokkos_Cuda_Half.hpp: CUDA >= 12's cuda_fp16 no longer gives Kokkos' half_t the functions it
#     uses (__half2double undefined): from CUDA 12 on, Kokkos' own fallback half_t is used.
#  3. Kokkos_CudaSpace.cpp: cudaMemPrefetchAsync takes a cudaMemLocation and flags since CUDA 13.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# shellcheck source=cmake/apt-private.sh
source "$root/cmake/apt-private.sh"
arch="${1:-${EPAC_KOKKOS_CUDA_ARCH:-AMPERE80}}"
arch_lc="$(tr '[:upper:]' '[:lower:]' <<<"$arch")"

nvcc=""
for c in "${CUDA_HOME:+$CUDA_HOME/bin/nvcc}" "${CUDA_PATH:+$CUDA_PATH/bin/nvcc}" "$(command -v nvcc || true)" \
         /usr/local/cuda/bin/nvcc $(ls -d /usr/local/cuda-*/bin/nvcc 2>/dev/null | sort -V -r); do
  if [ -n "$c" ] && [ -x "$c" ]; then nvcc="$(readlink -f "$c")"; break; fi
done
if [ -z "$nvcc" ]; then
  echo "[epac] no CUDA toolkit (no nvcc in \$CUDA_HOME, \$CUDA_PATH, PATH or /usr/local/cuda*)" >&2
  exit 3
fi
cuda_version="$("$nvcc" --version | sed -n 's/.*release \([0-9.]*\),.*/\1/p')"
prefix="${EPAC_KOKKOS_CUDA_PREFIX:-${XDG_CACHE_HOME:-$HOME/.cache}/epac/kokkos-3.4.01-cuda$cuda_version-$arch_lc}"
stamp="$prefix/.epac-kokkos-ok"
want="nvcc=$nvcc cuda=$cuda_version arch=$arch"
if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$want" ]; then echo "$prefix"; exit 0; fi

mkdir -p "$(dirname "$prefix")"
exec 9>"$prefix.lock"
flock 9
if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$want" ]; then echo "$prefix"; exit 0; fi
if [ -f "$stamp" ]; then rm -rf "$prefix"; fi  # our own install, for another nvcc or arch

work="$(mktemp -d "${TMPDIR:-/tmp}/epac-kokkos-cuda.XXXXXX")"
trap 'rm -rf "$work"' EXIT
t0=$(date +%s)
epac_kokkos_source "$work"
ksrc="$work/kokkos"

# 1. nvcc_wrapper: a default arch every CUDA >= 11 knows, and this nvcc unless CUDA_ROOT says else.
sed -i -e 's/^default_arch="sm_35"$/default_arch="sm_80"/' \
       -e "s|^nvcc_compiler=nvcc\$|nvcc_compiler=\"$nvcc\"|" "$ksrc/bin/nvcc_wrapper"
grep -q '^default_arch="sm_80"$' "$ksrc/bin/nvcc_wrapper"
grep -q "^nvcc_compiler=\"$nvcc\"\$" "$ksrc/bin/nvcc_wrapper"
# 2. half_t: CUDA's __half only before CUDA 12 (nvcc defines __CUDACC_VER_MAJOR__).
half="$ksrc/core/src/Cuda/Kokkos_Cuda_Half.hpp"
perl -0pi -e 's/(#if !\(defined\(KOKKOS_COMPILER_CLANG\) && KOKKOS_COMPILER_CLANG < 900\) && \\\n)/$1    !(defined(__CUDACC_VER_MAJOR__) && __CUDACC_VER_MAJOR__ >= 12) && \\\n/' "$half"
grep -q '__CUDACC_VER_MAJOR__ >= 12' "$half"
# 3. cudaMemPrefetchAsync(ptr, bytes, cudaMemLocation, flags, stream) from CUDA 13 on.
space="$ksrc/core/src/Cuda/Kokkos_CudaSpace.cpp"
perl -0pi -e 's/(    CUDA_SAFE_CALL\(cudaMemPrefetchAsync\(ptr, bytes, space\.cuda_device\(\),\n\s*space\.cuda_stream\(\)\)\);\n)/#if CUDA_VERSION >= 13000\n    cudaMemLocation loc{};\n    loc.type = cudaMemLocationTypeDevice;\n    loc.id   = space.cuda_device();\n    CUDA_SAFE_CALL(cudaMemPrefetchAsync(ptr, bytes, loc, 0, space.cuda_stream()));\n#else\n$1#endif\n/' "$space"
grep -q 'CUDA_VERSION >= 13000' "$space"

cmake -S "$ksrc" -B "$work/build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX="$prefix" \
  -DCMAKE_CXX_COMPILER="$ksrc/bin/nvcc_wrapper" -DCMAKE_CXX_STANDARD=17 \
  -DKokkos_ENABLE_CUDA=ON -DKokkos_ENABLE_CUDA_LAMBDA=ON -DKokkos_ENABLE_SERIAL=ON \
  -DKokkos_ARCH_"$arch"=ON -DBUILD_SHARED_LIBS=ON -DKokkos_ENABLE_TESTS=OFF >&2
cmake --build "$work/build" -j "${EPAC_JOBS:-$(nproc)}" >&2
cmake --install "$work/build" >&2
echo "[epac] Kokkos (CUDA $cuda_version, $arch) bootstrap took $(( $(date +%s) - t0 )) s" >&2
echo "$want" > "$stamp"
echo "$prefix"
