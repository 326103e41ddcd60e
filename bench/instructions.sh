#!/bin/bash
# Instructions executed per camera path on llvmpipe, counted by valgrind (cachegrind without
# cache simulation): a throughput figure that does not depend on the machine's load, so two
# shader versions can be compared on a busy 2-core machine. The shader JIT is subtracted by
# running each scene twice (10 and 50 spp at 96×54) and taking the difference.
#   bench/instructions.sh [-e RENDER_EXE] [-s SHADER_DIR] [-x KEY=VALUE]... SCENE...
# (-x: a scene key for every run, as raylab-render --set; repeatable)
# Needs valgrind (apt-get install valgrind). Minutes per scene: valgrind runs ~50× slower.
set -euo pipefail
exe=build/raylab-render
shaders=
sets=()
while getopts e:s:x: opt; do
    case $opt in e) exe=$OPTARG ;; s) shaders=$OPTARG ;; x) sets+=(--set "$OPTARG") ;; *) exit 2 ;; esac
done
shift $((OPTIND - 1))
[ $# -gt 0 ] || { echo "usage: $0 [-e RENDER_EXE] [-s SHADER_DIR] [-x KEY=VALUE]... SCENE..." >&2; exit 2; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
refs() {   # scene spp -> instructions of the whole run
    env ${shaders:+RAYLAB_SHADER_DIR=$shaders} MESA_SHADER_CACHE_DISABLE=true LP_NUM_THREADS=0 \
        valgrind --tool=cachegrind --cache-sim=no --cachegrind-out-file=/dev/null \
        "$exe" "$1" ${sets[@]+"${sets[@]}"} --width 96 --height 54 --spp "$2" --rpp 10 --seed 1 -q -o "$out/x.exr" 2>&1 |
        sed -n 's/.*I *refs: *//p' | tr -d ,
}
echo "| scene | instructions per path |"
echo "|---|---|"
for scene in "$@"; do
    a=$(refs "$scene" 10)
    b=$(refs "$scene" 50)
    echo "| $scene | $(( (b - a) / (40 * 96 * 54) )) |"
done
