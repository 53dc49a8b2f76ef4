#!/usr/bin/env bash
# Distributed rendering (issue 17, "Performance"): the same frame rendered by one process with 2
# threads and by `mpirun -np 2` ranks of 1 thread each, alternating, on this machine's cores.
#
#   bench/distributed.sh [BUILD_DIR] [REPEATS] [MODELS_DIR]
#
# Defaults: build, 3 repeats, ../shared/assets/gltf. Scenes: the default Cornell box (512², 64
# spp, path tracer) and DamagedHelmet under the studio environment (512², 64 spp), plus the
# rasterizer with depth of field by accumulation (scenes/depth-of-field.json, 1024², 64 frames).
# Per run: wall and CPU (user + system of the process and its children, mpirun's ranks included)
# from /usr/bin/time, and the render's own time from the summary line (rank 0's: from the scene
# loaded to the frame rendered, before the gather). Efficiency = time(1 process × 2 threads) /
# time(2 ranks × 1 thread): 1 means the ranks lose nothing to splitting. Also the bytes the ranks
# send rank 0 (the summary line) and the pixel count of each rank's share. The load average is
# printed before and after, so a busy machine is visible. Needs Open MPI (scripts/setup).
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
BUILD="${1:-$ROOT/build}"
REPEATS="${2:-3}"
MODELS="${3:-$ROOT/../shared/assets/gltf}"
OBSCURA="$BUILD/obscura"
MPIRUN=(mpirun --allow-run-as-root --oversubscribe --bind-to none)
OUT="$(mktemp -d "${TMPDIR:-/tmp}/distributed.XXXXXX")"
trap 'rm -rf "$OUT"' EXIT

echo "date: $(date -u +%Y-%m-%dT%H:%M:%SZ)"
echo "cpu: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//'), $(nproc) cores"
echo "obscura: $("$OBSCURA" --version); $(mpirun --version | head -1)"
echo "load at start: $(cut -d' ' -f1-3 /proc/loadavg)"

# One timed run: prints "wall cpu render_s mb_to_rank0".
run() {
  /usr/bin/time -f "%e %U %S" -o "$OUT/time.txt" "$@" > /dev/null 2> "$OUT/err.txt"
  python3 - "$OUT/time.txt" "$OUT/err.txt" <<'PY'
import re, sys
wall, user, system = map(float, open(sys.argv[1]).read().split()[-3:])
err = open(sys.argv[2]).read()
m = re.search(r"rendered .* in ([0-9.]+)(m?s)", err)
render = float(m.group(1)) * (1e-3 if m and m.group(2) == "ms" else 1) if m else float("nan")
mb = re.search(r"([0-9.]+) MB to rank 0", err)
print(f"{wall:.3f} {user + system:.3f} {render:.3f} {mb.group(1) if mb else '0'}")
PY
}

bench() {  # NAME, render arguments...
  local name="$1"
  shift
  : > "$OUT/one.txt"
  : > "$OUT/two.txt"
  for ((i = 0; i < REPEATS; i++)); do
    run "$OBSCURA" render "$@" --threads 2 -o "$OUT/one.exr" >> "$OUT/one.txt"
    run "${MPIRUN[@]}" -np 2 "$OBSCURA" render "$@" --threads 1 -o "$OUT/two.exr" >> "$OUT/two.txt"
  done
  local same="differ"
  [ "$(oiiotool --hash "$OUT/one.exr" | grep SHA)" = "$(oiiotool --hash "$OUT/two.exr" | grep SHA)" ] &&
    same="bit-identical"
  python3 - "$name" "$OUT/one.txt" "$OUT/two.txt" "$same" <<'PY'
import statistics, sys
name, one, two, same = sys.argv[1:]
rows = lambda p: [list(map(float, l.split())) for l in open(p) if l.strip()]
a, b = rows(one), rows(two)
med = lambda rs, k: statistics.median(r[k] for r in rs)
print(f"{name}: median of {len(a)} (images {same})")
print(f"  1 process x 2 threads: wall {med(a,0):.2f} s, cpu {med(a,1):.2f} s, render {med(a,2):.2f} s")
print(f"  2 ranks x 1 thread:    wall {med(b,0):.2f} s, cpu {med(b,1):.2f} s, render {med(b,2):.2f} s, "
      f"{med(b,3):.2f} MB to rank 0")
print(f"  efficiency (1x2 / 2x1): wall {med(a,0)/med(b,0):.3f}, render {med(a,2)/med(b,2):.3f}; "
      f"cpu ratio (2x1 / 1x2) {med(b,1)/med(a,1):.3f}")
PY
}

bench "cornell-box 512x512 64spp path" --width 512 --height 512 --spp 64
if [ -d "$MODELS/DamagedHelmet" ]; then
  bench "DamagedHelmet 512x512 64spp path" "$MODELS/DamagedHelmet/DamagedHelmet.glb" \
    --width 512 --height 512 --spp 64
fi
bench "depth-of-field 1024x1024 raster 64 frames" "$ROOT/scenes/depth-of-field.json" \
  --renderer raster --width 1024 --height 1024 --raster-samples 64
echo "load at end: $(cut -d' ' -f1-3 /proc/loadavg)"
