# Sourced (not run) by the bootstrap scripts: apt access through a private configuration derived
# from this machine's own, so the system configuration is never changed and no host name is
# written into the repository (docs/design.md section 10).
#
#   epac_apt_private DIR TYPE [SUITE [COMPONENTS]]
#     Writes sources and state under DIR and sets the array EPAC_APT_OPTS (for apt-get/apt-cache).
#     TYPE: deb or deb-src. SUITE (e.g. trixie) replaces the suites of the main archive entries
#     (security entries are dropped then: another release's packages come from its main archive);
#     COMPONENTS (e.g. "main non-free") replaces their components.
#   epac_kokkos_source WORK
#     Puts a Kokkos 3.4.01 source tree at WORK/kokkos (the packages/kokkos folder of Debian's
#     trilinos 13.2.0 source). Offline: EPAC_KOKKOS_SOURCE = a Kokkos source tree, or a tarball
#     holding */packages/kokkos/ (the trilinos orig tarball, or what cmake/device-bundle.sh packs).

epac_apt_private() {
  local dir="$1" type="$2" suite="${3:-}" comps="${4:-}" f
  mkdir -p "$dir/sources.list.d" "$dir/lists/partial" "$dir/archives/partial"
  for f in /etc/apt/sources.list.d/*.sources; do
    [ -f "$f" ] || continue
    # deb822: stanzas separated by blank lines
    awk -v type="$type" -v suite="$suite" -v comps="$comps" '
      function flush() { if (n && !(suite != "" && sec)) { for (i = 1; i <= n; i++) print s[i]; print "" } n = 0; sec = 0 }
      /^[[:space:]]*$/ { flush(); next }
      { line = $0
        if (line ~ /^Types:/) line = "Types: " type
        if (line ~ /^URIs:/ && line ~ /security/) sec = 1
        if (suite != "" && line ~ /^Suites:/) line = "Suites: " suite
        if (comps != "" && line ~ /^Components:/) line = "Components: " comps
        s[++n] = line }
      END { flush() }' "$f" > "$dir/sources.list.d/$(basename "$f")"
  done
  for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
    [ -f "$f" ] || continue
    # one-line format: deb [options] URI SUITE COMPONENT...
    awk -v type="$type" -v suite="$suite" -v comps="$comps" '
      $1 != "deb" { next }
      { i = 2; if ($2 ~ /^\[/) { while ($i !~ /\]$/) i++; i++ }
        if (suite != "" && $i ~ /security/) next
        out = type; for (k = 2; k <= i; k++) out = out " " $k
        out = out " " (suite != "" ? suite : $(i + 1))
        if (comps != "") out = out " " comps; else for (k = i + 2; k <= NF; k++) out = out " " $k
        print out }' "$f" > "$dir/sources.list.d/$(basename "$f").list"
  done
  EPAC_APT_OPTS=(-o "Dir::Etc::SourceList=/dev/null" -o "Dir::Etc::SourceParts=$dir/sources.list.d"
                 -o "Dir::State::Lists=$dir/lists" -o "Dir::Cache::archives=$dir/archives" -o "Debug::NoLocking=1")
}

epac_kokkos_source() {
  local work="$1" src="${EPAC_KOKKOS_SOURCE:-}"
  mkdir -p "$work/src"
  if [ -d "$src" ]; then  # a source tree: copied, since the CUDA bootstrap patches it
    cp -r "$src" "$work/kokkos"
    return
  fi
  if [ -z "$src" ]; then
    echo "[epac] fetching Debian's trilinos source package for Kokkos 3.4.01" >&2
    epac_apt_private "$work/apt" deb-src
    apt-get "${EPAC_APT_OPTS[@]}" update -qq >&2
    (cd "$work/src" && apt-get "${EPAC_APT_OPTS[@]}" source --download-only -qq trilinos >&2)
    src=$(ls "$work"/src/trilinos_*.orig.tar.* | head -n1)
  fi
  echo "[epac] extracting packages/kokkos from $(basename "$src")" >&2
  tar -xf "$src" -C "$work/src" --wildcards '*/packages/kokkos/*'
  mv "$(ls -d "$work"/src/*/packages/kokkos | head -n1)" "$work/kokkos"
}
