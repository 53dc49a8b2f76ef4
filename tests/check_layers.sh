#!/usr/bin/env bash
# The dependency rule of docs/architecture.md: each layer of src/obscura/ may include only the
# layers listed for it. Prints every violation; exits 1 if there is any.
set -euo pipefail
root="${1:-$(dirname "$0")/..}"
cd "$root/src/obscura"

declare -A allowed=(
  [math]="math"
  [color]="color math"
  [camera]="camera math"
  [scene]="scene math color camera"
  [shading]="shading math color scene"
  [film]="film math color"
  [sensor]="sensor math color film"
  [io]="io scene film color math camera sensor"
  [trace]="trace math color camera scene film shading"
  [raster]="raster math color camera scene film shading"
  [reyes]="reyes math color camera scene film shading"
  [render]="render math color camera scene shading film sensor io trace raster reyes"
)

status=0
for layer in "${!allowed[@]}"; do
  [ -d "$layer" ] || continue
  while IFS= read -r line; do
    file=${line%%:*}
    included=$(sed -E 's/.*#include "obscura\/([a-z_]+)\/.*/\1/' <<<"$line")
    if ! grep -qw -- "$included" <<<"${allowed[$layer]}"; then
      echo "layering: src/obscura/$file includes obscura/$included/ (allowed for $layer: ${allowed[$layer]})"
      status=1
    fi
  done < <(grep -rn '#include "obscura/[a-z_]*/' "$layer" || true)
done
exit $status
