#!/usr/bin/env bash
# glTF loading (issue 13, "Performance"): load + first rasterized frame of the largest sample
# asset, and the memory textures take against the size of their decoded images.
#
#   bench/gltf_load.sh [BUILD_DIR] [REPEATS] [MODELS_DIR]
#
# Defaults: build, 3 repeats, ../shared/assets/gltf. Needs /usr/bin/time (Debian's `time`),
# oiiotool (openimageio-tools) and python3 (standard library only).
#
# 1. The largest asset is the model folder with the most bytes (every file but the .md ones).
#    Each repeat runs, one after another so they see the same load: `obscura --version` (what
#    any process costs: shared libraries), `obscura info FILE` (load only; it prints its load
#    time) and `obscura render FILE --renderer raster` at 512 x 512 (load + first frame; the
#    summary line gives the render alone), each under `/usr/bin/time -v` (wall, user + system
#    CPU, peak RSS); then the render again from a copy without textures (see 2; with the studio
#    environment that the original gets by default), which leaves the frame without the texture
#    preparation.
# 2. For DamagedHelmet and the largest asset, a copy of the file with every texture removed
#    (images, textures, samplers and the materials' references to them; geometry and factors
#    unchanged) is loaded beside the original: the difference in peak RSS is what the textures
#    cost in `info` (the scene's 8-bit copy plus decoding), in the rasterizer (64 x 64, which also
#    builds linear-float mipmapped copies) and in the path tracer (64 x 64, 1 spp), both renders
#    with `--environment studio` (a copy whose emissive texture is gone has an untextured
#    emitter, which would otherwise turn the default studio environment off). The decoded
#    size is sum(w * h * channels * bytes per channel) over the images as `oiiotool --info -v`
#    reports them (the GLB's embedded images are extracted first).
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
BUILD="${1:-$ROOT/build}"
REPEATS="${2:-3}"
MODELS="${3:-$ROOT/../shared/assets/gltf}"
OBSCURA="$BUILD/obscura"
OUT="$(mktemp -d "${TMPDIR:-/tmp}/gltf-load.XXXXXX")"
trap 'rm -rf "$OUT"' EXIT

model_file() {  # NAME.glb, else glTF/NAME.gltf
  local d="$MODELS/$1"
  if [ -f "$d/$1.glb" ]; then echo "$d/$1.glb"; else echo "$d/glTF/$1.gltf"; fi
}
# `/usr/bin/time -v` of a command: "wall_s cpu_s peak_MB" on stdout, the command's stderr kept.
measure() {
  /usr/bin/time -v -o "$OUT/time.txt" "$@" > "$OUT/stdout.txt" 2> "$OUT/stderr.txt"
  python3 - "$OUT/time.txt" <<'EOF'
import sys
t = {}
for line in open(sys.argv[1]):
    k, _, v = line.strip().rpartition(": ")
    t[k] = v
w = t["Elapsed (wall clock) time (h:mm:ss or m:ss)"].split(":")
wall = sum(float(x) * 60 ** i for i, x in enumerate(reversed(w)))
cpu = float(t["User time (seconds)"]) + float(t["System time (seconds)"])
print(f"{wall:.2f} {cpu:.2f} {int(t['Maximum resident set size (kbytes)']) / 1024:.1f}")
EOF
}

echo "date: $(date -u +%Y-%m-%dT%H:%M:%SZ)"
echo "cpu: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//'), $(nproc) cores"
echo "obscura: $("$OBSCURA" --version)"
echo "uptime at start: $(uptime)"

# A copy of a .gltf/.glb without textures (same geometry, same buffers) in directory $2.
strip_textures() {
  python3 - "$1" "$2" <<'EOF'
import json, os, shutil, struct, sys
src, dst = sys.argv[1], sys.argv[2]
def strip(doc):
    for key in ("images", "textures", "samplers"):
        doc.pop(key, None)
    def drop(o):
        if isinstance(o, dict):
            for k in [k for k in o if k.endswith("Texture")]:
                del o[k]
            for v in o.values():
                drop(v)
        elif isinstance(o, list):
            for v in o:
                drop(v)
    drop(doc.get("materials", []))
    for key in ("extensionsUsed", "extensionsRequired"):
        if key in doc:
            doc[key] = [e for e in doc[key] if e != "KHR_texture_transform"]
    return doc
name = os.path.basename(src)
if src.endswith(".glb"):
    data = open(src, "rb").read()
    n = struct.unpack_from("<I", data, 12)[0]
    doc = strip(json.loads(data[20:20 + n]))
    rest = data[20 + n:]  # the BIN chunk, as it was
    js = json.dumps(doc).encode()
    js += b" " * (-len(js) % 4)
    body = struct.pack("<II", len(js), 0x4E4F534A) + js + rest
    open(os.path.join(dst, name), "wb").write(struct.pack("<III", 0x46546C67, 2, 12 + len(body)) + body)
else:
    doc = json.load(open(src))
    for b in doc.get("buffers", []):
        if "uri" in b and not b["uri"].startswith("data:"):
            shutil.copy(os.path.join(os.path.dirname(src), b["uri"]), dst)
    json.dump(strip(doc), open(os.path.join(dst, name), "w"))
EOF
}
# The images of a .gltf/.glb as files in directory $2 (a GLB's embedded ones extracted).
extract_images() {
  python3 - "$1" "$2" <<'EOF'
import json, os, shutil, struct, sys
src, dst = sys.argv[1], sys.argv[2]
if src.endswith(".glb"):
    data = open(src, "rb").read()
    n = struct.unpack_from("<I", data, 12)[0]
    doc = json.loads(data[20:20 + n])
    bin_ = data[20 + n + 8:]
else:
    doc = json.load(open(src))
for i, im in enumerate(doc.get("images", [])):
    if "uri" in im:
        shutil.copy(os.path.join(os.path.dirname(src), im["uri"]), os.path.join(dst, f"{i}_" + os.path.basename(im["uri"])))
    else:
        bv = doc["bufferViews"][im["bufferView"]]
        ext = {"image/png": "png", "image/jpeg": "jpg"}.get(im.get("mimeType"), "bin")
        off = bv.get("byteOffset", 0)
        open(os.path.join(dst, f"{i}.{ext}"), "wb").write(bin_[off:off + bv["byteLength"]])
EOF
}

largest="$(cd "$MODELS" && for d in */; do
  printf '%s %s\n' "$(find "$d" -type f ! -name '*.md' -printf '%s\n' | awk '{s += $1} END {print s}')" "${d%/}"
done | sort -n | tail -n 1)"
big="${largest#* }"
echo
echo "## 1. Load + first frame (rasterizer, 512 x 512): $big, $(printf "%'d" "${largest%% *}") bytes"
echo
echo "| repeat | command | wall s | CPU s | peak RSS MB | Obscura's own timing |"
echo "|---|---|---|---|---|---|"
file="$(model_file "$big")"
mkdir -p "$OUT/bare-$big"
strip_textures "$file" "$OUT/bare-$big"
bare="$OUT/bare-$big/$(basename "$file")"
for rep in $(seq 1 "$REPEATS"); do
  r="$(measure "$OBSCURA" --version)"
  echo "| $rep | \`obscura --version\` | ${r// / | } | |"
  r="$(measure "$OBSCURA" info "$file")"
  echo "| $rep | \`obscura info\` | ${r// / | } | load $(grep -o 'load time *[0-9.]* s' "$OUT/stdout.txt" | awk '{print $3}') s |"
  r="$(measure "$OBSCURA" render "$file" --renderer raster --width 512 --height 512 -o "$OUT/frame.png")"
  echo "| $rep | \`obscura render --renderer raster\` | ${r// / | } | render $(grep -o 'in [0-9.]*s' "$OUT/stderr.txt" | tail -n 1 | tr -dc '0-9.') s |"
  r="$(measure "$OBSCURA" render "$bare" --renderer raster --width 512 --height 512 --environment studio -o "$OUT/frame.png")"
  echo "| $rep | the same without textures, \`--environment studio\` | ${r// / | } | render $(grep -o 'in [0-9.]*s' "$OUT/stderr.txt" | tail -n 1 | tr -dc '0-9.') s |"
done
echo
echo "uptime after part 1: $(uptime)"

echo
echo "## 2. Texture memory"
for model in DamagedHelmet "$big"; do
  file="$(model_file "$model")"
  mkdir -p "$OUT/$model/bare" "$OUT/$model/images"
  strip_textures "$file" "$OUT/$model/bare"
  bare="$OUT/$model/bare/$(basename "$file")"
  extract_images "$file" "$OUT/$model/images"
  echo
  echo "### $model"
  echo
  echo '```'
  decoded=0
  for im in "$OUT/$model/images"/*; do
    info="$(oiiotool --info "$im")"
    echo "${info#"$OUT/$model/images/"}"
    # "W x H, C channel, uint8 png": bytes per channel from the type
    read -r w h c bits <<<"$(sed -E 's/.*: *([0-9]+) x +([0-9]+), ([0-9]+) channel, ([a-z]*[0-9]+).*/\1 \2 \3 \4/' <<<"$info")"
    bytes=$(( $(tr -dc '0-9' <<<"$bits") / 8 ))
    decoded=$((decoded + w * h * c * bytes))
  done
  echo '```'
  echo
  echo "decoded images: $(python3 -c "print(f'{$decoded / 1e6:.1f}')") MB (sum of w*h*channels*bytes)"
  echo
  echo "| command | peak RSS with textures MB | without MB | difference MB | CPU s with / without |"
  echo "|---|---|---|---|---|"
  for mode in info raster path; do
    case $mode in
      info) cmd=(info) ;;
      raster) cmd=(render --renderer raster --environment studio --width 64 --height 64 -q -o "$OUT/m.png") ;;
      path) cmd=(render --renderer path --environment studio --width 64 --height 64 --spp 1 -q -o "$OUT/m.png") ;;
    esac
    read -r _ cw rw <<<"$(measure "$OBSCURA" "${cmd[0]}" "$file" "${cmd[@]:1}")"
    read -r _ cb rb <<<"$(measure "$OBSCURA" "${cmd[0]}" "$bare" "${cmd[@]:1}")"
    echo "| \`obscura ${cmd[*]:0:3}\` | $rw | $rb | $(python3 -c "print(f'{$rw - $rb:.1f}')") | $cw / $cb |"
  done
  echo
  "$OBSCURA" info "$file" 2>/dev/null | grep '^memory'
done
echo
echo "uptime at end: $(uptime)"
