#!/usr/bin/env bash
# Installs epac's Debian dependencies when missing (docs/design.md section 10). Idempotent: when
# every package is already present it does nothing and asks no registry.
# Extra package names given as arguments are installed too (drivers/lammps/build.sh: Open MPI).
set -euo pipefail
pkgs=(cmake g++ make catch2 libbenchmark-dev libeigen3-dev libtomlplusplus-dev libcli11-dev
      nlohmann-json3-dev python3-matplotlib dpkg-dev xz-utils clang-format "$@")
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "[epac] installing: ${missing[*]}"
  SUDO=""; [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
