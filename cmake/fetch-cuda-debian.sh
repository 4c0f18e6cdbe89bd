#!/usr/bin/env bash
# A CUDA 12 toolkit without a system install: Debian trixie's non-free CUDA 12.4 packages
# (nvidia-cuda-toolkit: nvcc, cicc, ptxas; nvidia-cuda-dev: headers, cudart, the libcuda stub;
# libnvvm4; libcu++-dev), downloaded through a private apt configuration derived from this
# machine's own (cmake/apt-private.sh) and unpacked with dpkg-deb into a cache folder. Prints the
# CUDA_HOME to use:
#   CUDA_HOME="$(bash cmake/fetch-cuda-debian.sh)" bash cmake/check-device-compile.sh
# It lets the GPU compile check run against CUDA 12 on a machine whose own toolkit is 13 (or that
# has none). Nothing is run on a GPU with it. About 1 GB is downloaded, 2.7 GB unpacked.
# Environment: EPAC_CUDA_DEBIAN_SUITE (default trixie), EPAC_CUDA_DEBIAN_PREFIX (the folder).
# Idempotent (stamp file); concurrent calls wait for each other (flock).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# shellcheck source=cmake/apt-private.sh
source "$root/cmake/apt-private.sh"
suite="${EPAC_CUDA_DEBIAN_SUITE:-trixie}"
prefix="${EPAC_CUDA_DEBIAN_PREFIX:-${XDG_CACHE_HOME:-$HOME/.cache}/epac/cuda-debian-$suite}"
home="$prefix/usr/lib/nvidia-cuda-toolkit"  # nvcc's own folder: CUDA_HOME
stamp="$prefix/.epac-cuda-ok"
if [ -f "$stamp" ]; then echo "$home"; exit 0; fi
mkdir -p "$(dirname "$prefix")"
exec 9>"$prefix.lock"
flock 9
if [ -f "$stamp" ]; then echo "$home"; exit 0; fi
rm -rf "$prefix"

work="$(mktemp -d "${TMPDIR:-/tmp}/epac-cuda-debian.XXXXXX")"
trap 'rm -rf "$work"' EXIT
t0=$(date +%s)
epac_apt_private "$work/apt" deb "$suite" "main non-free"
apt-get "${EPAC_APT_OPTS[@]}" update -qq >&2
mkdir -p "$work/debs"
(cd "$work/debs" && apt-get "${EPAC_APT_OPTS[@]}" download -qq \
   nvidia-cuda-toolkit nvidia-cuda-dev libcudart12 libnvvm4 libcu++-dev 2>&1 | grep -v unsandboxed >&2 || true)
for d in "$work"/debs/*.deb; do dpkg-deb -x "$d" "$prefix"; done
[ -x "$home/bin/nvcc" ] || { echo "[epac] no nvcc in the unpacked packages ($home/bin)" >&2; exit 1; }
# Debian's nvcc.profile is a link to /etc/nvcc.profile with absolute /usr paths: a profile of our
# own points nvcc at the unpacked tools (cicc here, ptxas/fatbinary/nvlink in usr/bin), libdevice,
# headers and libraries (the libcuda stub included: links without a driver).
rm -f "$home/bin/nvcc.profile"
cat > "$home/bin/nvcc.profile" <<EOF
NVVMIR_LIBRARY_DIR = $home/libdevice
PATH += $home/bin:$prefix/usr/bin:
INCLUDES += -I$prefix/usr/include \$(_SPACE_)
LIBRARIES =+ \$(_SPACE_) -L$prefix/usr/lib/x86_64-linux-gnu/stubs -L$prefix/usr/lib/x86_64-linux-gnu
EOF
# CMake and Kokkos look for lib64/ and include/ beside bin/.
ln -sfn "$prefix/usr/include" "$home/include"
ln -sfn "$prefix/usr/lib/x86_64-linux-gnu" "$home/lib64"
version="$("$home/bin/nvcc" --version | sed -n 's/.*release \([0-9.]*\),.*/\1/p')"
echo "[epac] CUDA $version from Debian $suite unpacked in $(( $(date +%s) - t0 )) s: $home" >&2
echo "cuda=$version suite=$suite" > "$stamp"
echo "$home"
