#!/usr/bin/env bash
# The prebuilt bundle's two rules, shared by cmake/device-prebuild.sh (which writes it) and
# cmake/device-run.sh (which uses it only where it fits), tested by ctest device_prebuilt_check:
#   bash cmake/device-prebuilt-check.sh hash ROOT
#       prints the sha256 of every file git tracks in ROOT but the prose (docs/, *.md): what the
#       executables are built from
#   bash cmake/device-prebuilt-check.sh fits BUNDLE ROOT BUILD ARCH
#       exit 0 when BUNDLE's prebuilt executables were built in checkout ROOT and build folder
#       BUILD, for Kokkos arch ARCH, from files that are all unchanged; else exit 1 and one line
#       saying why. Needs no git (a GPU machine's copy of the checkout may have none).
set -uo pipefail
mode="${1:-}"
case "$mode" in
  hash)
    root="${2:?usage: device-prebuilt-check.sh hash ROOT}"
    cd "$root" && git ls-files -z -- . ':!:docs/**' ':!:*.md' | xargs -0 sha256sum
    ;;
  fits)
    [ $# -eq 5 ] || { echo "usage: device-prebuilt-check.sh fits BUNDLE ROOT BUILD ARCH" >&2; exit 2; }
    bundle="$2" root="$3" build="$4" arch="$5"
    for f in prebuilt.txt prebuilt.tar.xz prebuilt.sha256; do
      [ -f "$bundle/$f" ] || { echo "no $f in $bundle"; exit 1; }
    done
    pb() { sed -n "s/^$1=//p" "$bundle/prebuilt.txt"; }
    if [ "$(pb root)" != "$root" ]; then echo "built in the checkout $(pb root), this one is $root"; exit 1; fi
    if [ "$(pb build)" != "$build" ]; then echo "built in $(pb build), this build folder is $build"; exit 1; fi
    if [ "$(pb arch)" != "$arch" ]; then echo "built for $(pb arch), this GPU takes $arch"; exit 1; fi
    changed="$(cd "$root" && sha256sum --quiet -c "$bundle/prebuilt.sha256" 2>&1 | sed -n 's/: FAILED.*//p')"
    if [ -n "$changed" ]; then
      echo "$(wc -l <<< "$changed") file(s) differ from what it was built from: $(head -n 5 <<< "$changed" | tr '\n' ' ')"
      exit 1
    fi
    ;;
  *)
    echo "usage: device-prebuilt-check.sh hash ROOT | fits BUNDLE ROOT BUILD ARCH" >&2
    exit 2
    ;;
esac
