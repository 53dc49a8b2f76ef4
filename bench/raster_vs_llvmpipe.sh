#!/usr/bin/env bash
# The rasterizer and Mesa's llvmpipe on the same workloads, in one invocation, alternating the two
# renderers per thread count so that both see the same machine load.
#
#   bench/raster_vs_llvmpipe.sh [BUILD_DIR] [REPEATS] [THREADS]
#
# llvmpipe's LP_NUM_THREADS=N runs N rasterizer threads besides the application thread, which does
# its vertex work and binning, so with N = 1 it keeps up to ~1.8 cores busy. With 1 in THREADS the
# script therefore also runs LP_NUM_THREADS=0 (everything on one thread: the single-core peer of
# our 1 thread). The summary (summary.md) has the median over repeats of each side's median frame,
# wall and CPU time, and the load average at the start and at the end.
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
    peers="$t"
    [ "$t" = 1 ] && peers="1 0"
    for lp in $peers; do
      echo "## repeat $rep threads $t: llvmpipe LP_NUM_THREADS=$lp" | tee -a "$OUT/raw.txt"
      LP_NUM_THREADS="$lp" "$OUT/lpbench" bench --frames "$FRAMES" --warmup 1 | tee -a "$OUT/raw.txt"
    done
    echo "## repeat $rep threads $t: obscura" | tee -a "$OUT/raw.txt"
    "$BUILD/bench/raster_bench" --benchmark_filter="/$t/" --benchmark_min_time=1 \
      --benchmark_min_warmup_time=0.2 | tee -a "$OUT/raw.txt"
  done
done
echo "loadavg at end: $(cut -d' ' -f1-3 /proc/loadavg)" | tee -a "$OUT/env.txt"

# Medians over repeats; ratio = llvmpipe time / obscura time (our throughput relative to its), by
# wall time and by CPU time. Our CPU time is the process's (Google Benchmark's CPU column with
# MeasureProcessCPUTime); llvmpipe's is its median frame times its process CPU / wall over the
# timed frames (proc_cpu_util). CPU time is what the load of other processes distorts least: a
# loaded machine stretches wall time, but a ratio of CPU times still compares work done.
{
  echo "loadavg (1, 5, 15 min) at start: $(grep 'at start' "$OUT/env.txt" | cut -d: -f2- | sed 's/^ *//'); at end: $(grep 'at end' "$OUT/env.txt" | cut -d: -f2- | sed 's/^ *//')"
  echo
  awk '
  function median(list,   n, v, i, j, t) {
    n = split(list, v, " ")
    for (i = 1; i <= n; ++i) for (j = i + 1; j <= n; ++j) if (v[j] + 0 < v[i] + 0) { t = v[i]; v[i] = v[j]; v[j] = t }
    return n % 2 ? v[(n + 1) / 2] : (v[n / 2] + v[n / 2 + 1]) / 2
  }
  function to_ms(value, unit) { return unit == "us" ? value / 1000 : unit == "s" ? value * 1000 : unit == "ns" ? value / 1e6 : value }
  /^workload=/ {
    for (i = 1; i <= NF; ++i) { split($i, kv, "="); f[kv[1]] = kv[2] }
    key = f["workload"] " " f["shader"] " " f["threads"]
    lp[key] = lp[key] " " f["ms_median"]
    lpcpu[key] = lpcpu[key] " " f["ms_median"] * f["proc_cpu_util"]
    util[key] = util[key] " " f["proc_cpu_util"]
    tris[f["workload"]] = f["tris"]; covered[f["workload"]] = f["frags_covered"]
    passed[f["workload"]] = f["frags_passed"]
    next
  }
  /real_time / && $1 ~ /^[a-z0-9_]+\/[a-z]+\/[0-9]+\// {
    split($1, p, "/"); key = p[1] " " p[2] " " p[3]
    ob[key] = ob[key] " " to_ms($2, $3)
    obcpu[key] = obcpu[key] " " to_ms($4, $5)
    if (!(key in seen)) { seen[key] = 1; order[++n] = key }
  }
  END {
    print "| workload | shader | threads | obscura ms wall / CPU | llvmpipe ms wall / CPU (LP_NUM_THREADS = threads; its cores) | ratio wall / CPU | llvmpipe ms wall / CPU, one thread (LP_NUM_THREADS=0) | ratio wall / CPU | obscura Mtris/s | obscura Mpx/s covered / passed |"
    print "|---|---|---|---|---|---|---|---|---|---|"
    for (i = 1; i <= n; ++i) {
      k = order[i]; split(k, p, " "); o = median(ob[k]); oc = median(obcpu[k])
      if (!(k in lp)) continue
      l = median(lp[k]); lc = median(lpcpu[k])
      line = sprintf("| %s | %s | %s | %.1f / %.1f | %.1f / %.1f (%.2f) | %.2f× / %.2f× |", p[1], p[2], p[3], o, oc, l, lc, median(util[k]), l / o, lc / oc)
      k0 = p[1] " " p[2] " 0"
      if (p[3] == 1 && (k0 in lp)) line = line sprintf(" %.1f / %.1f | %.2f× / %.2f× |", median(lp[k0]), median(lpcpu[k0]), median(lp[k0]) / o, median(lpcpu[k0]) / oc)
      else line = line " | |"
      # Rates from the frame triangle and fragment counts (from llvmpipe occlusion queries; the
      # bench counts the same for ours, see bench/raster_bench.cpp).
      line = line sprintf(" %.3g | %.0f / %.0f |", tris[p[1]] / o / 1000, covered[p[1]] / o / 1000, passed[p[1]] / o / 1000)
      print line
    }
  }' "$OUT/raw.txt"
} | tee "$OUT/summary.md"
echo "results in: $OUT"
