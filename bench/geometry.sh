#!/bin/sh
# Geometry benchmarks for bench/geometry.md: frame time against triangle count (10^2 .. 10^6),
# BVH build time and SAH cost, and the specialised against the all-features shader.
# Usage: bench/geometry.sh [BUILD_DIR]   (default: build). Run from the repository root.
# Writes its meshes and scenes to a temporary directory; prints Markdown to stdout.
set -eu
BUILD=${1:-build}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
echo "### BVH build and SAH cost (raylab-meshgen --report, one thread)"
echo
echo '```'
for n in 100 1000 10000 100000 1000000; do
  "$BUILD/raylab-meshgen" --triangles $n -o "$TMP/terrain_$n.obj" --report
done
echo '```'
echo
echo "### Frame time against triangle count (fragment tracer, 256x144, 4 spp per run, median of 3)"
for n in 100 1000 10000 100000 1000000; do
  cat > "$TMP/terrain_$n.json" <<JSON
{ "camera": { "position": [0, 2.2, 5.5], "look_at": [0, 0, 0], "fov": 40 },
  "render": { "max_bounces": 4 },
  "sky": { "type": "gradient" },
  "objects": [ { "type": "mesh", "file": "terrain_$n.obj",
                 "transform": { "rotation": [0, 30, 0], "scale": [3, 2, 3] } } ] }
JSON
  echo
  echo "#### $n triangles (requested)"
  "$BUILD/raylab-bench" --scene "$TMP/terrain_$n.json" --variants fragment --width 256 --height 144 \
      --spp 4 --repeat 3 --results '' 2>/dev/null | grep '^|'
done
echo
echo "### Specialised against all-features shader (scenes/default.json, 320x180, 8 spp, median of 5)"
echo
"$BUILD/raylab-bench" --scene scenes/default.json --variants fragment --specialise both --width 320 \
    --height 180 --spp 8 --repeat 5 --results '' 2>/dev/null | grep '^|'
