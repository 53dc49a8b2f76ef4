#!/usr/bin/env bash
# Time to equal error on the Cornell box: spectral transport (--spectral) against RGB transport,
# both with Obscura's path tracer, run alternately so both see the same machine load.
#
#   bench/spectral_vs_rgb.sh [BUILD_DIR] [THREADS] [SPP_LIST] [REFERENCE_SPP]
#
# The two modes converge to slightly different images (spectral products of the walls' colours
# are not the products of their RGB), so each is measured against its own reference: the same
# scene at REFERENCE_SPP in that mode, another seed. RMSE² against a reference holds the
# reference's own variance too; it is removed (its share is spp / REFERENCE_SPP of the run's).
# An unbiased estimator's RMSE falls as 1/sqrt(time), so k = RMSE * sqrt(render seconds) is
# each mode's constant; time to a common error scales as k², and the ratio of the k² is the
# result (render loop only: the CLI's summary time, loading and the table fit excluded).
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
BUILD="${1:-$ROOT/build}"
THREADS="${2:-2}"
SPP_LIST="${3:-16 32 64 128}"
REFERENCE_SPP="${4:-2048}"
SHARED="${SHARED:-$ROOT/../shared}"
SCENE="$SHARED/reference/cornell/cornell.glb"
OUT="${OUT:-$(mktemp -d "${TMPDIR:-/tmp}/spectral-vs-rgb.XXXXXX")}"
OBSCURA="$BUILD/obscura"

flag() { [ "$1" = spectral ] && echo --spectral || true; }
render() {  # mode spp seed output
  "$OBSCURA" render "$SCENE" --width 128 --height 128 --spp "$2" --seed "$3" \
    --threads "$THREADS" --max-depth 65 --filter box --filter-radius 0.5 $(flag "$1") -o "$4" \
    2> "$4.log" > /dev/null
  # The summary's time: "6.24s" or "1m11s".
  grep -o ' in [0-9m.]*s' "$4.log" | sed 's/ in //' |
    awk -F'm' '{ if (NF == 2) print $1 * 60 + $2; else print $1 + 0 }'
}
rmse() { "$OBSCURA" image diff --json "$1" "$2" |
  python3 -c 'import json,sys; print(json.load(sys.stdin)["rmse"])'; }

{
  echo "date: $(date -u +%Y-%m-%dT%H:%M:%SZ)"
  echo "cpu: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//'), $(nproc) cores"
  echo "loadavg at start: $(cut -d' ' -f1-3 /proc/loadavg)"
} | tee "$OUT/env.txt"
for mode in rgb spectral; do
  echo "$mode reference: $(render "$mode" "$REFERENCE_SPP" 1000 "$OUT/ref_$mode.exr") s" |
    tee -a "$OUT/env.txt"
done
echo "mode spp seconds rmse" > "$OUT/runs.txt"
for spp in $SPP_LIST; do
  for mode in rgb spectral; do
    seconds=$(render "$mode" "$spp" 1 "$OUT/${mode}_$spp.exr")
    echo "$mode $spp $seconds $(rmse "$OUT/${mode}_$spp.exr" "$OUT/ref_$mode.exr")" |
      tee -a "$OUT/runs.txt"
  done
done
python3 - "$OUT/runs.txt" "$REFERENCE_SPP" <<'PY' | tee "$OUT/summary.txt"
import math, statistics, sys
runs = [l.split() for l in open(sys.argv[1]).read().splitlines()[1:]]
reference_spp = float(sys.argv[2])
k2 = {}
for mode, spp, seconds, rmse in runs:
    # The reference's variance is spp / reference_spp of this run's: remove it.
    mse = float(rmse) ** 2 / (1 + float(spp) / reference_spp)
    k2.setdefault(mode, []).append(mse * float(seconds))
for mode, v in k2.items():
    print(f"{mode}: k^2 = MSE * seconds = {statistics.median(v):.3e} (per run: "
          + ", ".join(f"{x:.2e}" for x in v) + ")")
print(f"spectral / rgb time to equal RMSE: "
      f"{statistics.median(k2['spectral']) / statistics.median(k2['rgb']):.2f}")
PY
echo "loadavg at end: $(cut -d' ' -f1-3 /proc/loadavg)" | tee -a "$OUT/env.txt"
