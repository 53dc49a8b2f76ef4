#!/usr/bin/env bash
# Time to error on the Cornell box: Obscura's path tracer and Blender Cycles, run alternately in
# one invocation so both see the same machine load, against Cycles' 16,384-spp reference of
# ../shared/reference/cornell (128 x 128, box filter 1 px, 65 scattering events, no denoising).
#
#   bench/tracer_vs_cycles.sh [BUILD_DIR] [THREADS] [SPP_LIST] [REPEATS]
#
# For every sample count both renderers render the same glTF scene; the RMSE against the
# reference and the render time (Cycles: its render call, start-up and scene export excluded;
# Obscura: the render loop from the CLI's summary, loading excluded) are recorded. Because the
# RMSE of an unbiased estimator falls as 1/sqrt(time), each renderer's k = RMSE * sqrt(time) is a
# constant; the time either needs to reach Cycles' 256-spp error is (k / target)^2, and the
# ratio of those times is the result. Needs Debian's `blender` (only this comparison uses it).
#
# Beside it, the CPU time of each whole process (user + system, from /usr/bin/time), which the
# machine's load distorts least: fitted as cpu = fixed + cost * spp over the sample counts (the
# fixed part holds start-up, loading and scene sync), each renderer's CPU time to an error is
# cost * RMSE^2 * spp, and their ratio is printed too, with the load average at start and end.
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
BUILD="${1:-$ROOT/build}"
THREADS="${2:-2}"
SPP_LIST="${3:-64 128 256 512}"
REPEATS="${4:-1}"
SHARED="${SHARED:-$ROOT/../shared}"
REF="$SHARED/reference/cornell"
OUT="${OUT:-$(mktemp -d "${TMPDIR:-/tmp}/tracer-vs-cycles.XXXXXX")}"
OBSCURA="$BUILD/obscura"

rmse() { "$OBSCURA" image diff --json "$1" "$REF/cornell_ref.exr" |
  python3 -c 'import json,sys; print(json.load(sys.stdin)["rmse"])'; }

{
  echo "date: $(date -u +%Y-%m-%dT%H:%M:%SZ)"
  echo "cpu: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//'), $(nproc) cores"
  echo "cycles: $(blender --version 2>/dev/null | head -1)"
  echo "loadavg at start: $(cut -d' ' -f1-3 /proc/loadavg)"
} | tee "$OUT/env.txt"

echo "renderer spp seconds rmse cpu_seconds" > "$OUT/runs.txt"
cpu() { awk '{ print $1 + $2 }' "$1"; }
for rep in $(seq 1 "$REPEATS"); do
  for spp in $SPP_LIST; do
    QUIET=1 /usr/bin/time -f "%U %S" -o "$OUT/cycles_$spp.time" \
      "$SHARED/tools/peers/cycles/run.sh" --mode render --width 128 --height 128 \
      --spp "$spp" --seed "$((rep + 10))" --threads "$THREADS" --max-bounces 64 --no-png \
      --name "cycles_$spp" --out "$OUT" > "$OUT/cycles_$spp.log"
    seconds=$(grep -o 'render_s=[0-9.]*' "$OUT/cycles_$spp.log" | cut -d= -f2)
    echo "cycles $spp $seconds $(rmse "$OUT/cycles_$spp.exr") $(cpu "$OUT/cycles_$spp.time")" |
      tee -a "$OUT/runs.txt"

    /usr/bin/time -f "%U %S" -o "$OUT/obscura_$spp.time" "$OBSCURA" render "$REF/cornell.glb" --width 128 --height 128 --spp "$spp" \
      --threads "$THREADS" --seed "$((rep + 10))" --max-depth 65 --filter box \
      --filter-radius 0.5 -o "$OUT/obscura_$spp.exr" 2> "$OUT/obscura_$spp.log" > /dev/null
    seconds=$(grep -o ' in [0-9.]*s' "$OUT/obscura_$spp.log" | grep -o '[0-9.]*')
    echo "obscura $spp $seconds $(rmse "$OUT/obscura_$spp.exr") $(cpu "$OUT/obscura_$spp.time")" |
      tee -a "$OUT/runs.txt"
  done
done

python3 - "$OUT/runs.txt" <<'PY' | tee "$OUT/summary.txt"
import math, statistics, sys
runs = [l.split() for l in open(sys.argv[1]).read().splitlines()[1:]]
k = {}
for name, spp, seconds, rmse, _ in runs:
    k.setdefault(name, []).append(float(rmse) * math.sqrt(float(seconds)))
target = statistics.median(float(r) for n, s, _, r, _ in runs if n == "cycles" and s == "256") \
    if any(n == "cycles" and s == "256" for n, s, _, _, _ in runs) else 0.00716
times = {n: (statistics.median(v) / target) ** 2 for n, v in k.items()}
for n, t in times.items():
    print(f"{n}: k = RMSE*sqrt(s) = {statistics.median(k[n]):.5f}, time to RMSE {target:.5f}: {t:.2f} s")
print(f"obscura / cycles time to error: {times['obscura'] / times['cycles']:.2f}")
# CPU: slope of process CPU time over spp, times the error constant RMSE^2 * spp.
cpu_time = {}
for n in k:
    rows = [(float(s), float(c), float(r)) for m, s, _, r, c in runs if m == n]
    mean_s = sum(r[0] for r in rows) / len(rows)
    mean_c = sum(r[1] for r in rows) / len(rows)
    slope = sum((r[0] - mean_s) * (r[1] - mean_c) for r in rows) / \
        sum((r[0] - mean_s) ** 2 for r in rows)
    error = statistics.median(r[2] ** 2 * r[0] for r in rows)
    cpu_time[n] = slope * error / target ** 2
    print(f"{n}: CPU {mean_c - slope * mean_s:.2f} s + {slope * 1e3:.2f} ms/spp, "
          f"CPU time to RMSE {target:.5f}: {cpu_time[n]:.2f} s")
print(f"obscura / cycles CPU time to error: {cpu_time['obscura'] / cpu_time['cycles']:.2f}")
PY
echo "loadavg at end: $(cut -d' ' -f1-3 /proc/loadavg)" | tee -a "$OUT/env.txt"
