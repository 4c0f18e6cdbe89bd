#!/usr/bin/env bash
# `bash cmake/dev.sh device`: epac on this machine's NVIDIA GPU in one command (docs/gpu.md).
#  1. the GPU's compute capability (nvidia-smi) -> the nearest Kokkos 3.4 arch (Hopper and newer:
#     AMPERE80, whose PTX the driver compiles for the GPU at the first launch);
#  2. Kokkos with CUDA for that arch (cmake/bootstrap-kokkos-cuda.sh, cached);
#  3. epac built with it: the test executables, epac-law-throughput, epac-bench-contacts, epac-run
#     (steps 2-3 are skipped when the bundle holds them prebuilt for this checkout:
#     cmake/device-prebuild.sh);
#  4. the library test suite on the GPU (one ctest per test executable);
#  5. contacts/s per law, double and float, 1e5 to 1e7 contacts (epac-law-throughput), the
#     Hertz-Mindlin kernel variants (epac-bench-contacts: default sums, atomics, deterministic);
#  6. the scaling script's GPU branch (bench/scaling/run_scaling.py: a size sweep of epac-run);
#  7. one JSON and one markdown report: <build>/report/device_report.{json,md}, with each step's
#     log beside them; if $OUT is set, the two reports, the scaling plot and device_logs.tar.gz
#     (the whole report folder) are copied there.
# Without a GPU it stops before building, with a message; EPAC_DEVICE_ARCH=<Kokkos arch> builds
# anyway (steps 1-3) and then stops before step 4 with the same message.
# A GPU machine without a network: `bash cmake/device-bundle.sh` here packs the Kokkos source and
# the Debian build dependencies into .device-bundle/; with that folder present (or
# EPAC_DEVICE_BUNDLE=<dir>) nothing is downloaded: Kokkos is built from the packed source and the
# dependencies are unpacked into <build>/sysroot.
# Warnings are not errors here (CI's device_compile_check makes them errors): a newer host
# compiler's new warning must not cost a rare GPU slot.
# Environment: EPAC_DEVICE_BUILD_DIR (default build-device), EPAC_DEVICE_ARCH (Kokkos arch,
# overrides the query), EPAC_JOBS (default nproc), EPAC_DEVICE_CONTACTS (default 1e5,1e6,1e7),
# EPAC_DEVICE_TARGETS (what step 3 builds; default: every test, the two benchmarks, epac-run),
# EPAC_DEVICE_FLAGS (compile flags, e.g. -gencode=arch=compute_90,code=sm_90 for
# native Hopper code instead of PTX), EPAC_CMAKE_ARGS (extra configure arguments),
# EPAC_DEVICE_PREBUILT=0 (build even where the bundle holds prebuilt executables).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${EPAC_DEVICE_BUILD_DIR:-$root/build-device}"
jobs="${EPAC_JOBS:-$(nproc)}"
mkdir -p "$build"
build="$(cd "$build" && pwd)"
report="$build/report"
rm -rf "$report"
mkdir -p "$report"
t_start=$(date +%s)
steps_file="$report/steps.tsv"
# On any exit, failures included, $OUT (if set) gets the reports and one archive of every log: a
# few files rather than a folder, since some runners bring back only a handful.
copy_out() {
  [ -n "${OUT:-}" ] || return 0
  mkdir -p "$OUT"
  for f in device_report.md device_report.json scaling.png; do [ -f "$report/$f" ] && cp "$report/$f" "$OUT/"; done
  tar -C "$build" -czf "$OUT/device_logs.tar.gz" report
  echo "[device] copied to $OUT: the reports and device_logs.tar.gz"
}
trap copy_out EXIT
: > "$steps_file"
step() { echo "[device] $*"; }
# step_done NAME STATUS SECONDS: one line per step for the report
step_done() { printf '%s\t%s\t%s\n' "$1" "$2" "$3" >> "$steps_file"; }

# 1. the GPU
no_gpu_msg="no NVIDIA GPU found (nvidia-smi is missing or lists no GPU): 'bash cmake/dev.sh device' builds
epac for this machine's GPU and runs the test suite and benchmarks on it."
gpu_cc="" gpu_name=""
if command -v nvidia-smi > /dev/null 2>&1; then
  q="$(nvidia-smi --query-gpu=compute_cap,name --format=csv,noheader 2> /dev/null | head -n1 || true)"
  if [[ "$q" =~ ^([0-9]+)\.([0-9]+),\ *(.*)$ ]]; then gpu_cc="${BASH_REMATCH[1]}.${BASH_REMATCH[2]}"; gpu_name="${BASH_REMATCH[3]}"; fi
fi
# Kokkos 3.4 knows archs up to AMPERE86. A cubin runs on GPUs of the same major version and a
# higher minor one; PTX (which -arch=sm_XY also embeds) runs on any later GPU, compiled by the
# driver at the first launch.
kokkos_arch() {
  local major="${1%%.*}" minor="${1#*.}"
  case "$1" in
    3.0) echo KEPLER30 ;; 3.2) echo KEPLER32 ;; 3.5) echo KEPLER35 ;; 3.7) echo KEPLER37 ;;
    5.0) echo MAXWELL50 ;; 5.2) echo MAXWELL52 ;; 5.3) echo MAXWELL53 ;;
    6.0) echo PASCAL60 ;; 6.1) echo PASCAL61 ;; 7.0) echo VOLTA70 ;; 7.2) echo VOLTA72 ;; 7.5) echo TURING75 ;;
    8.0) echo AMPERE80 ;;
    *) if [ "$major" -eq 8 ] && [ "$minor" -ge 6 ]; then echo AMPERE86; elif [ "$major" -ge 9 ]; then echo AMPERE80
       else echo "unsupported compute capability $1" >&2; return 1; fi ;;
  esac
}
arch="${EPAC_DEVICE_ARCH:-}"
if [ -z "$arch" ]; then
  if [ -z "$gpu_cc" ]; then
    echo "error: $no_gpu_msg" >&2
    echo "(EPAC_DEVICE_ARCH=AMPERE80 bash cmake/dev.sh device builds for that arch without a GPU, then stops)" >&2
    step_done gpu "no GPU" 0
    exit 1
  fi
  arch="$(kokkos_arch "$gpu_cc")"
fi
step "GPU: ${gpu_name:-none} (compute capability ${gpu_cc:-none}); Kokkos arch $arch"
step_done gpu "${gpu_name:-none} cc ${gpu_cc:-none} -> $arch" 0

# 2. Kokkos with CUDA (and, offline, the dependencies from the bundle)
t=$(date +%s)
bundle="${EPAC_DEVICE_BUNDLE:-$root/.device-bundle}"
dep_args=()
if [ -f "$bundle/manifest.txt" ]; then
  step "offline bundle: $bundle"
  export EPAC_KOKKOS_SOURCE="${EPAC_KOKKOS_SOURCE:-$bundle/kokkos-3.4.01-src.tar.xz}"
  sysroot="$build/sysroot"
  rm -rf "$sysroot"
  for d in "$bundle"/debs/*.deb; do dpkg-deb -x "$d" "$sysroot"; done
  dep_args=(-DCMAKE_PREFIX_PATH="$sysroot/usr")
  export LD_LIBRARY_PATH="$sysroot/usr/lib/x86_64-linux-gnu${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
  step_done bundle "ok: $(head -n1 "$bundle/manifest.txt")" $(( $(date +%s) - t ))
fi
# 2-3 from a prebuilt bundle (cmake/device-prebuild.sh): the executables built elsewhere for this
# very checkout, so that a GPU slot is spent running, not compiling. Used only when the checkout and
# build folder have the paths they were built at, the arch is the one chosen above and every file
# they were built from is unchanged; else built here, and the report says why.
use_prebuilt=0
pb() { sed -n "s/^$1=//p" "$bundle/prebuilt.txt"; }
if [ -n "$gpu_cc" ] && [ "${EPAC_DEVICE_PREBUILT:-1}" != 0 ] && [ -f "$bundle/prebuilt.txt" ]; then
  if why="$(bash "$root/cmake/device-prebuilt-check.sh" fits "$bundle" "$root" "$build" "$arch")"; then use_prebuilt=1
  else step "prebuilt bundle not used ($why): building"; step_done prebuilt "not used: $why" 0; fi
fi
if [ "$use_prebuilt" = 1 ]; then
  t=$(date +%s)
  tar -C / -xJf "$bundle/prebuilt.tar.xz"
  export LD_LIBRARY_PATH="$build/prebuilt-lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
  step "prebuilt: $(pb executables) executables of commit $(pb commit), made $(pb made)"
  step_done build "ok: prebuilt (commit $(pb commit), CUDA $(pb nvcc), $(pb host_compiler))" $(( $(date +%s) - t ))
else
  prefix="$(EPAC_JOBS="$jobs" bash "$root/cmake/bootstrap-kokkos-cuda.sh" "$arch")" || {
    rc=$?; [ "$rc" -eq 3 ] && echo "error: no CUDA toolkit (nvcc): set CUDA_HOME or install one" >&2; exit 1; }
  step_done kokkos "ok: $prefix ($(cat "$prefix/.epac-kokkos-ok"))" $(( $(date +%s) - t ))

  # 3. build what runs
  t=$(date +%s)
  flags="${EPAC_DEVICE_FLAGS:-}"
  # Ninja where there is one: with Makefiles, `cmake --build --target A B C` builds the targets one
  # after the other (the top Makefile is .NOTPARALLEL), and the first GPU session spent 12 minutes of
  # a 16-core machine compiling three test executables at a time. A build folder keeps its generator.
  gen=()
  if [ ! -f "$build/CMakeCache.txt" ] && command -v ninja > /dev/null 2>&1; then gen=(-G Ninja); fi
  # shellcheck disable=SC2086
  cmake -S "$root" -B "$build" "${gen[@]}" -DCMAKE_BUILD_TYPE=Release -DKokkos_ROOT="$prefix" \
    -DCMAKE_CXX_COMPILER="$prefix/bin/nvcc_wrapper" -DCMAKE_CXX_FLAGS="$flags" \
    -DEPAC_BUILD_TESTS=ON -DEPAC_BUILD_BENCH=ON -DEPAC_BUILD_DRIVERS=ON "${dep_args[@]}" ${EPAC_CMAKE_ARGS:-} \
    > "$report/configure.log" 2>&1 || { tail -n 50 "$report/configure.log"; exit 1; }
  tests="$(cmake --build "$build" --target help | sed -n -E 's/^(\.\.\. )?(test_[A-Za-z0-9_]+)(: .*| .*)?$/\2/p' | sort -u | tr '\n' ' ')"
  [ -n "$tests" ] || { echo "error: no test targets in $build (configure log: $report/configure.log)" >&2; exit 1; }
  targets="${EPAC_DEVICE_TARGETS:-$tests epac-law-throughput epac-bench-contacts epac-run}"
  step "building (-j $jobs): $targets"
  # shellcheck disable=SC2086
  if ! cmake --build "$build" -j "$jobs" --target $targets \
       > "$report/build.log" 2>&1; then
    grep -E -A5 'error' "$report/build.log" | head -n 100
    step_done build failed $(( $(date +%s) - t ))
    echo "error: build failed (log: $report/build.log)" >&2
    exit 1
  fi
  step_done build ok $(( $(date +%s) - t ))
  step "built in $(( $(date +%s) - t )) s"

fi

if [ -z "$gpu_cc" ]; then
  echo "error: $no_gpu_msg" >&2
  echo "Built for $arch in $build; stopping before the runs." >&2
  step_done run "no GPU" 0
  exit 1
fi

# The driver's JIT cache (PTX -> GPU code) big enough to keep every kernel between processes.
export CUDA_CACHE_MAXSIZE="${CUDA_CACHE_MAXSIZE:-4294967296}"
failed=0

# 4. the test suite
t=$(date +%s)
step "test suite on the GPU"
# One ctest per core: at its first launch each executable has the driver compile its kernels' PTX
# (sm_80 PTX on a newer GPU), CPU work that one GPU shares well between processes.
if (cd "$build" && ctest -R '^test_' -j "$jobs" --timeout 600 --output-on-failure) > "$report/tests.log" 2>&1; then
  step_done tests ok $(( $(date +%s) - t ))
else
  step_done tests failed $(( $(date +%s) - t )); failed=1
fi
tail -n 25 "$report/tests.log"

# 5. benchmarks
t=$(date +%s)
step "contacts/s per law"
if "$build/bench/epac-law-throughput" --contacts "${EPAC_DEVICE_CONTACTS:-1e5,1e6,1e7}" --seconds 0.5 \
     --json "$report/law_throughput.json" > "$report/law_throughput.log" 2>&1; then
  step_done law_throughput ok $(( $(date +%s) - t ))
else
  step_done law_throughput failed $(( $(date +%s) - t )); failed=1
fi
t=$(date +%s)
step "Hertz-Mindlin kernel variants (epac-bench-contacts)"
if "$build/bench/epac-bench-contacts" --benchmark_min_time=0.2 --benchmark_out="$report/bench_contacts.json" \
     --benchmark_out_format=json > "$report/bench_contacts.log" 2>&1; then
  step_done bench_contacts ok $(( $(date +%s) - t ))
else
  step_done bench_contacts failed $(( $(date +%s) - t )); failed=1
fi

# 6. scaling (GPU branch: one run per size)
t=$(date +%s)
step "scaling script (GPU branch)"
if python3 "$root/bench/scaling/run_scaling.py" --exe "$build/drivers/epac-run" --repeats 1 \
     --device-ncell 10 20 30 --json "$report/scaling.json" --png "$report/scaling.png" \
     > "$report/scaling.log" 2>&1; then
  step_done scaling ok $(( $(date +%s) - t ))
else
  step_done scaling failed $(( $(date +%s) - t )); failed=1
fi

# 7. the report
python3 "$root/tests/device/device_report.py" --dir "$report" --build "$build" --total-s $(( $(date +%s) - t_start ))
step "report: $report/device_report.md and device_report.json"
exit "$failed"
