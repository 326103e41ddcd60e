#!/bin/sh
# UI frame times of the real viewer under Xvfb at high rpp, and the stall of a shader-variant
# compile (bench/viewer.md, "Time slicing at high rpp"). Run from the repository root after a
# build: sh bench/viewer_frames.sh [DISPLAY_NUMBER]. Prints the load average before each run.
set -e
N=${1:-93}
Xvfb :$N -screen 0 1280x800x24 -nolisten tcp & XVFB=$!
trap 'kill $XVFB' EXIT
sleep 1
export DISPLAY=:$N
for rpp in 1 64 256; do
    echo "== rpp $rpp: $(uptime)"
    ./build/raylab --ini '' --continuous --frames 400 --report-frames --set render.spp=100000 --set render.rpp=$rpp | grep -v '^raylab:'
done
# Switching to a debug view that needs a new tracer variant compiles it in the UI thread.
printf 'wait-frames 100\ndebug-view normals\nwait-frames 100\ndebug-view nan\nwait-frames 100\ndebug-view boxes\nwait-frames 100\nquit\n' > /tmp/raylab-switch.txt
for rpp in 1 64; do
    echo "== view switches at rpp $rpp: $(uptime)"
    ./build/raylab --ini '' --script /tmp/raylab-switch.txt --frames 100000 --skip-frames 30 --report-frames \
        --set render.spp=100000 --set render.rpp=$rpp 2>&1 | grep -E 'compiled|frames|slowest'
done
# The same switches with the variants already compiled (switch away and back): no compile.
printf 'debug-view normals\ndebug-view nan\ndebug-view boxes\ndebug-view beauty\nwait-frames 100\ndebug-view normals\nwait-frames 100\ndebug-view nan\nwait-frames 100\ndebug-view boxes\nwait-frames 100\nquit\n' > /tmp/raylab-switch2.txt
echo "== switches to compiled variants, rpp 64: $(uptime)"
./build/raylab --ini '' --script /tmp/raylab-switch2.txt --frames 100000 --skip-frames 60 --report-frames \
    --set render.spp=100000 --set render.rpp=64 2>&1 | grep -E 'frames|slowest'
# A variant's first use with Mesa's shader cache off: llvmpipe compiles (JITs) a program's
# shaders at its first draw, so that frame's tracing holds the stall.
echo "== view switches at rpp 64, shader cache off: $(uptime)"
MESA_SHADER_CACHE_DISABLE=true ./build/raylab --ini '' --script /tmp/raylab-switch.txt --frames 100000 --skip-frames 30 \
    --report-frames --set render.spp=100000 --set render.rpp=64 2>&1 | grep -E 'compiled|frames|slowest'
