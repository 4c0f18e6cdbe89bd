#!/bin/sh
# Runs every MDR validation scene (drivers/scenes/mdr_*.toml) with epac-run into one folder,
# one sub-folder per scene, then the plot script (bench/plots/plot_mdr.py) into the same folder.
#   bench/plots/run_mdr_scenes.sh EPAC_RUN OUT_DIR [THREADS] [PACKING_STEPS]
# EPAC_RUN: the epac-run executable (e.g. build/drivers/epac-run). THREADS (default 2) is for the
# packing scene (the single-sphere scenes run on one thread). PACKING_STEPS overrides the
# steps of the 10^4-sphere compaction scene (default: the scene's own, about a minute on 2 cores).
set -e
EXE=${1:?usage: run_mdr_scenes.sh EPAC_RUN OUT_DIR [THREADS] [PACKING_STEPS]}
OUT=${2:?usage: run_mdr_scenes.sh EPAC_RUN OUT_DIR [THREADS] [PACKING_STEPS]}
THREADS=${3:-2}
PACKING_STEPS=${4:-}
HERE=$(cd "$(dirname "$0")" && pwd)
SCENES="$HERE/../../drivers/scenes"
mkdir -p "$OUT"
export OMP_PROC_BIND=false
for scene in "$SCENES"/mdr_*.toml; do
  stem=$(basename "$scene" .toml)
  extra=""
  threads=1  # one or two particles: more threads only add barrier waits to tiny kernels
  if [ "$stem" = "mdr_compaction_packing" ]; then
    threads=$THREADS
    if [ -n "$PACKING_STEPS" ]; then extra="--steps $PACKING_STEPS"; fi
  fi
  echo "== $stem"
  # shellcheck disable=SC2086
  if ! "$EXE" "$scene" --out "$OUT/$stem" --overwrite --threads "$threads" $extra > "$OUT/$stem.log" 2>&1; then
    cat "$OUT/$stem.log" >&2
    echo "run_mdr_scenes.sh: $stem failed" >&2
    exit 1
  fi
  grep -E "steps in|mdr_" "$OUT/$stem.log" || true
done
if /usr/bin/python3 -c "import matplotlib, numpy" 2>/dev/null; then
  /usr/bin/python3 "$HERE/plot_mdr.py" "$OUT" --scenes "$SCENES"
else
  echo "run_mdr_scenes.sh: /usr/bin/python3 has no matplotlib/numpy: no plots" >&2
fi
