#!/usr/bin/env bash
# Packs what `bash cmake/dev.sh device` downloads into one folder, for a GPU machine that reaches
# no network (docs/gpu.md, "A GPU machine without a network"): run it here, copy or carry the
# folder there, and the device command finds it and asks no registry.
#   bash cmake/device-bundle.sh [DIR]          (default: .device-bundle in the repository, ignored by git)
# DIR then holds:
#   kokkos-3.4.01-src.tar.xz   packages/kokkos of Debian's trilinos 13.2.0 source (EPAC_KOKKOS_SOURCE)
#   debs/*.deb                 epac's build dependencies from Debian (Catch2, Google Benchmark, toml++,
#                              CLI11, nlohmann-json, Eigen), unpacked by cmake/device-run.sh into its
#                              build folder's sysroot (no system install there)
#   manifest.txt               what is in it, and from which release
# About 5 MB. Not needed where the GPU machine reaches Debian's registries.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# shellcheck source=cmake/apt-private.sh
source "$root/cmake/apt-private.sh"
out="${1:-$root/.device-bundle}"
mkdir -p "$out"
out="$(cd "$out" && pwd)"
work="$(mktemp -d "${TMPDIR:-/tmp}/epac-device-bundle.XXXXXX")"
trap 'rm -rf "$work"' EXIT

epac_kokkos_source "$work"
mkdir -p "$work/pack/trilinos-13.2.0/packages"
mv "$work/kokkos" "$work/pack/trilinos-13.2.0/packages/kokkos"
tar -C "$work/pack" -cJf "$out/kokkos-3.4.01-src.tar.xz" trilinos-13.2.0

# The packages install-deps.sh names that a build needs (not the tools: cmake, g++, python3 are on
# any GPU machine image), plus their library packages.
pkgs=(catch2 libbenchmark-dev libbenchmark1debian libtomlplusplus-dev libtomlplusplus3 libcli11-dev
      nlohmann-json3-dev libeigen3-dev)
epac_apt_private "$work/apt" deb
apt-get "${EPAC_APT_OPTS[@]}" update -qq
rm -rf "$out/debs"
mkdir -p "$out/debs"
(cd "$out/debs" && apt-get "${EPAC_APT_OPTS[@]}" download -qq "${pkgs[@]}" 2>&1 | grep -v unsandboxed || true)
for p in "${pkgs[@]}"; do
  ls "$out/debs/${p}_"*.deb > /dev/null 2>&1 || { echo "error: $p was not downloaded" >&2; exit 1; }
done
{
  echo "epac device bundle, made $(date -u +%Y-%m-%dT%H:%MZ) on $(. /etc/os-release && echo "$PRETTY_NAME")"
  echo "kokkos-3.4.01-src.tar.xz  $(du -h "$out/kokkos-3.4.01-src.tar.xz" | cut -f1)"
  (cd "$out/debs" && ls -1 ./*.deb | sed 's|^\./|debs/|')
} > "$out/manifest.txt"
cat "$out/manifest.txt"
echo "bundle: $out ($(du -sh "$out" | cut -f1))"
