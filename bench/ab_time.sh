#!/bin/bash
# Paths per second of two shader trees on the same build, in interleaved pairs, so that a drift of
# the machine's speed (a shared VM's neighbours) falls on both alike: a shader change's time, where
# bench/instructions.sh gives its instruction count. The first pair compiles both variants; quote
# the others. An empty shader directory means the build's own (source tree) shaders.
#   bench/ab_time.sh [-n PAIRS] [-e RENDER_EXE] OLD_SHADERS NEW_SHADERS SCENE SPP [raylab-render args]...
# e.g. old shaders from git: mkdir -p /tmp/old && git archive HEAD shaders | tar -x -C /tmp/old
#      bench/ab_time.sh /tmp/old/shaders '' scenes/cornell_box.json 1024 --set render.adaptive=false
set -euo pipefail
pairs=4
exe=build/raylab-render
while getopts n:e: opt; do
    case $opt in n) pairs=$OPTARG ;; e) exe=$OPTARG ;; *) exit 2 ;; esac
done
shift $((OPTIND - 1))
[ $# -ge 4 ] || { echo "usage: $0 [-n PAIRS] [-e RENDER_EXE] OLD_SHADERS NEW_SHADERS SCENE SPP [args]..." >&2; exit 2; }
old=$1 new=$2 scene=$3 spp=$4
shift 4
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
rate() {   # shader dir -> Mpaths/s of the render's last progress line
    env ${1:+RAYLAB_SHADER_DIR=$1} "$exe" "$scene" --width 96 --height 54 --spp "$spp" --rpp 16 "${@:2}" -o "$out/x.exr" 2>&1 |
        tr '\r' '\n' | sed -n "s|.*$spp/$spp spp.* \([0-9.]*\) Mpaths/s.*|\1|p" | tail -1
}
echo "| pair | old Mpaths/s | new Mpaths/s |"
echo "|---|---|---|"
for i in $(seq "$pairs"); do
    echo "| $i | $(rate "$old" "$@") | $(rate "$new" "$@") |"
done
