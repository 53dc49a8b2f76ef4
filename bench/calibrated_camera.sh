#!/usr/bin/env bash
# Calibrated cameras (issue 14, "Performance"): what a distorted lens costs each renderer next to
# the pinhole with the same K, pose and scene, run alternately in one invocation so every camera
# sees the same machine load.
#
#   bench/calibrated_camera.sh [BUILD_DIR] [REPEATS] [THREADS]
#
# Defaults: build, 3 repeats, 2 threads.
#  (a) The tracer: the Cornell box (512², 32 spp, path tracer) through its perspective camera and
#      through calibrated cameras with the same K (read from `obscura camera --export
#      opencv-yaml`): no distortion, OpenCV's 5-coefficient model (k1 k2 p1 p2 k3) and a
#      Kannala–Brandt fisheye. Same rays per pixel, nearly the same framing: the difference is
#      the inverse lens map per sample.
#  (b) The rasterizer at 1920×1080: spheres-and-lights through its perspective camera (one
#      matrix) and through lens views (calibrated: no distortion, OpenCV 5, Kannala–Brandt with
#      the same K; and a 200° Kannala–Brandt fisheye, which needs the cube faces).
# Per run: wall and CPU (user + system) from /usr/bin/time, and the render's own time from the
# summary line (scene loading and image writing excluded). Medians over the repeats; ratio =
# median render time / the perspective camera's. The load average is printed before and after.
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
BUILD="${1:-$ROOT/build}"
REPEATS="${2:-3}"
THREADS="${3:-2}"
OBSCURA="$BUILD/obscura"
OUT="$(mktemp -d "${TMPDIR:-/tmp}/calibrated-camera.XXXXXX")"
trap 'rm -rf "$OUT"' EXIT

OPENCV5="opencv:-0.28,0.12,0.006,-0.004,-0.02"
KB="kannala-brandt:-0.013,0.004,-0.0012,0.0002"

echo "date: $(date -u +%Y-%m-%dT%H:%M:%SZ)"
echo "cpu: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//'), $(nproc) cores"
echo "obscura: $("$OBSCURA" --version)"
echo "load at start: $(cut -d' ' -f1-3 /proc/loadavg)"

# fx,fy,cx,cy of a scene's camera at a resolution, from the OpenCV export.
intrinsics() {  # SCENE W H
  "$OBSCURA" camera "$1" --width "$2" --height "$3" --export opencv-yaml |
    python3 -c '
import re, sys
m = re.search(r"camera_matrix:.*?data: \[([^\]]*)\]", sys.stdin.read(), re.S)
k = [float(v) for v in m.group(1).split(",")]
print(f"{k[0]!r},{k[4]!r},{k[2]!r},{k[5]!r}")'
}

# One timed run: appends "wall cpu render_s" to FILE.
run() {  # FILE, obscura arguments...
  local file="$1"
  shift
  /usr/bin/time -f "%e %U %S" -o "$OUT/time.txt" "$OBSCURA" "$@" > /dev/null 2> "$OUT/err.txt"
  python3 - "$OUT/time.txt" "$OUT/err.txt" >> "$file" <<'PY'
import re, sys
wall, user, system = map(float, open(sys.argv[1]).read().split()[-3:])
m = re.search(r"rendered .* in ([0-9.]+)(m?s)", open(sys.argv[2]).read())
render = float(m.group(1)) * (1e-3 if m.group(2) == "ms" else 1) if m else float("nan")
print(f"{wall:.3f} {user + system:.3f} {render:.3f}")
PY
}

# bench TITLE COMMON_ARGS -- NAME1 "ARGS1" NAME2 "ARGS2" ...: the cameras alternate in each repeat.
bench() {
  local title="$1" common="$2"
  shift 3
  local names=() args=()
  while [ $# -gt 0 ]; do
    names+=("$1")
    args+=("$2")
    shift 2
  done
  echo
  echo "$title"
  for i in "${!names[@]}"; do
    : > "$OUT/$i.txt"
    echo "  ${names[$i]}: obscura render $common ${args[$i]}"
  done
  for ((r = 0; r < REPEATS; r++)); do
    for i in "${!names[@]}"; do
      # shellcheck disable=SC2086  # the argument strings are word lists
      run "$OUT/$i.txt" render $common ${args[$i]} -o "$OUT/out.exr"
    done
  done
  local files=()
  for i in "${!names[@]}"; do files+=("${names[$i]}" "$OUT/$i.txt"); done
  python3 - "$REPEATS" "${files[@]}" <<'PY'
import statistics, sys
repeats, rest = sys.argv[1], sys.argv[2:]
rows = {}
for name, path in zip(rest[::2], rest[1::2]):
    rows[name] = [list(map(float, l.split())) for l in open(path) if l.strip()]
med = lambda rs, k: statistics.median(r[k] for r in rs)
base = med(next(iter(rows.values())), 2)
print(f"  median of {repeats}:  {'wall s':>8} {'cpu s':>8} {'render s':>9} {'ratio':>6}")
for name, rs in rows.items():
    print(f"  {name:<34} {med(rs,0):8.2f} {med(rs,1):8.2f} {med(rs,2):9.2f} {med(rs,2)/base:6.3f}")
PY
}

K_CORNELL="$(intrinsics cornell-box 512 512)"
bench "(a) tracer: cornell-box 512x512, 32 spp, path, $THREADS threads" \
  "cornell-box --width 512 --height 512 --spp 32 --threads $THREADS" -- \
  "perspective" "" \
  "calibrated, no distortion" "--projection calibrated --intrinsics $K_CORNELL" \
  "calibrated, opencv 5 coefficients" "--projection calibrated --intrinsics $K_CORNELL --distortion $OPENCV5" \
  "calibrated, kannala-brandt" "--projection calibrated --intrinsics $K_CORNELL --distortion $KB"

K_SPHERES="$(intrinsics spheres-and-lights 1920 1080)"
bench "(b) rasterizer: spheres-and-lights 1920x1080, $THREADS threads" \
  "spheres-and-lights --renderer raster --width 1920 --height 1080 --threads $THREADS" -- \
  "perspective" "" \
  "calibrated, no distortion" "--projection calibrated --intrinsics $K_SPHERES" \
  "calibrated, opencv 5 coefficients" "--projection calibrated --intrinsics $K_SPHERES --distortion $OPENCV5" \
  "calibrated, kannala-brandt" "--projection calibrated --intrinsics $K_SPHERES --distortion $KB" \
  "kannala-brandt 200 deg (cube faces)" "--projection calibrated --intrinsics 380,380,959.5,539.5 --distortion $KB --max-field-angle 100"

echo
echo "load at end: $(cut -d' ' -f1-3 /proc/loadavg)"
