#!/usr/bin/env bash
# CXX_COMPILER_LAUNCHER of the host-only targets in a CUDA build (drivers/CMakeLists.txt): their
# sources have no kernels and include no Kokkos, and some third-party headers (toml++) do not get
# through nvcc's front end. The command's nvcc_wrapper is replaced by the host compiler it wraps
# (NVCC_WRAPPER_DEFAULT_COMPILER, default g++, as nvcc_wrapper does) and nvcc-only flags
# (-Xcudafe <arg>) are dropped; everything else (-Werror, a ccache in front) is kept.
set -euo pipefail
host="${NVCC_WRAPPER_DEFAULT_COMPILER:-g++}"
args=()
while [ $# -gt 0 ]; do
  case "$1" in
    nvcc_wrapper|*/nvcc_wrapper) args+=("$host") ;;
    -Xcudafe) shift ;;
    *) args+=("$1") ;;
  esac
  shift
done
exec "${args[@]}"
