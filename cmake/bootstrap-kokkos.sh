#!/usr/bin/env bash
# Bootstraps Kokkos 3.4.01 (OpenMP + Serial) from Debian's trilinos source package into a cache
# prefix, when no Kokkos with OpenMP is installed (docs/design.md section 10). Prints the prefix.
#
# apt-get source needs deb-src entries. We derive them at run time from this machine's own apt
# configuration into a private sources dir and a private state dir, so the system configuration
# is never changed and no host name is written into the repository.
# Idempotent: a finished install (stamp file) is reused at no cost.
set -euo pipefail
prefix="${EPAC_KOKKOS_PREFIX:-${XDG_CACHE_HOME:-$HOME/.cache}/epac/kokkos-3.4.01}"
stamp="$prefix/.epac-kokkos-ok"
if [ -f "$stamp" ]; then echo "$prefix"; exit 0; fi

work="$(mktemp -d "${TMPDIR:-/tmp}/epac-kokkos.XXXXXX")"
trap 'rm -rf "$work"' EXIT
t0=$(date +%s)
mkdir -p "$work/sources.list.d" "$work/lists/partial" "$work/src"

# deb822 files: turn "Types: deb" into "Types: deb-src".
for f in /etc/apt/sources.list.d/*.sources; do
  [ -f "$f" ] || continue
  sed -E 's/^Types:.*/Types: deb-src/' "$f" > "$work/sources.list.d/$(basename "$f")"
done
# one-line format: "deb URI ..." -> "deb-src URI ...".
for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
  [ -f "$f" ] || continue
  grep -E '^\s*deb\s' "$f" | sed -E 's/^\s*deb\s/deb-src /' > "$work/sources.list.d/$(basename "$f").list" || true
done
aptopts=(-o "Dir::Etc::SourceList=/dev/null" -o "Dir::Etc::SourceParts=$work/sources.list.d"
         -o "Dir::State::Lists=$work/lists" -o "Debug::NoLocking=1")
echo "[epac] fetching trilinos source package for Kokkos" >&2
apt-get "${aptopts[@]}" update -qq >&2
(cd "$work/src" && apt-get "${aptopts[@]}" source --download-only -qq trilinos >&2)

tarball=$(ls "$work"/src/trilinos_*.orig.tar.* | head -n1)
echo "[epac] extracting packages/kokkos from $(basename "$tarball")" >&2
tar -xf "$tarball" -C "$work/src" --wildcards '*/packages/kokkos/*'
ksrc=$(ls -d "$work"/src/*/packages/kokkos | head -n1)

cmake -S "$ksrc" -B "$work/build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX="$prefix" \
  -DKokkos_ENABLE_OPENMP=ON -DKokkos_ENABLE_SERIAL=ON -DCMAKE_CXX_STANDARD=17 \
  -DBUILD_SHARED_LIBS=ON -DKokkos_ENABLE_TESTS=OFF >&2
cmake --build "$work/build" -j "$(nproc)" >&2
cmake --install "$work/build" >&2
echo "[epac] Kokkos bootstrap took $(( $(date +%s) - t0 )) s" >&2
touch "$stamp"
echo "$prefix"
