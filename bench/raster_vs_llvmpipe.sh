#!/usr/bin/env bash
# The rasterizer and Mesa's llvmpipe on the same workloads, in one invocation, alternating the two
# renderers per thread count so that both see the same machine load.
#
#   bench/raster_vs_llvmpipe.sh [BUILD_DIR] [REPEATS] [THREADS]
#
# BUILD_DIR holds bench/raster_bench (default: build). The llvmpipe harness is
# ../shared/tools/peers/llvmpipe beside the repository (override with PEER=DIR); it needs
# libegl1-mesa-dev and libgl1-mesa-dev, which only this comparison uses. Raw output goes to
# $OUT (default: a new directory under ${TMPDIR:-/tmp}).
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
BUILD="${1:-$ROOT/build}"
REPEATS="${2:-1}"
THREADS="${3:-1 2}"
PEER="${PEER:-$ROOT/../shared/tools/peers/llvmpipe}"
OUT="${OUT:-$(mktemp -d "${TMPDIR:-/tmp}/raster-vs-llvmpipe.XXXXXX")}"
FRAMES="${FRAMES:-5}"

g++ -O2 -std=c++17 -o "$OUT/lpbench" "$PEER/lpbench.cpp" -lEGL -lOpenGL 2>/dev/null ||
  g++ -O2 -std=c++17 -o "$OUT/lpbench" "$PEER/lpbench.cpp" -lEGL -lGL
export LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=llvmpipe

{
  echo "date: $(date -u +%Y-%m-%dT%H:%M:%SZ)"
  echo "cpu: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//'), $(nproc) cores"
  echo "llvmpipe: $("$OUT/lpbench" info)"
  echo "loadavg at start: $(cut -d' ' -f1-3 /proc/loadavg)"
} | tee "$OUT/env.txt"

for rep in $(seq 1 "$REPEATS"); do
  for t in $THREADS; do
    echo "## repeat $rep threads $t: llvmpipe" | tee -a "$OUT/raw.txt"
    LP_NUM_THREADS="$t" "$OUT/lpbench" bench --frames "$FRAMES" --warmup 1 | tee -a "$OUT/raw.txt"
    echo "## repeat $rep threads $t: obscura" | tee -a "$OUT/raw.txt"
    "$BUILD/bench/raster_bench" --benchmark_filter="/$t/" --benchmark_min_time=1 \
      --benchmark_min_warmup_time=0.2 | tee -a "$OUT/raw.txt"
  done
done
echo "loadavg at end: $(cut -d' ' -f1-3 /proc/loadavg)" | tee -a "$OUT/env.txt"
echo "results in: $OUT"
