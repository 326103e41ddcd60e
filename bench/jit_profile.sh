#!/bin/bash
# Where the tracer's time goes inside llvmpipe's JIT-compiled shader, which perf cannot name: perf
# samples a running render's instruction addresses (cpu-clock, no hardware counters needed), gdb
# copies the executable mapping that holds them, objdump disassembles it, and jit_profile.py
# charges the samples to the mapping's functions (llvmpipe's texel-fetch routines end in ret),
# to its loops (backward jumps) and to the per-lane loads (inline gathers, storage-buffer lane
# loops). The addresses belong to this one process, so all three steps run on it.
#   bench/jit_profile.sh [-s SHADER_DIR] [-t SECONDS] SCENE [raylab-render args]...
# e.g. bench/jit_profile.sh scenes/cornell_box.json --set render.adaptive=false
# Needs perf (Debian linux-perf), gdb and binutils; run from the repository root after building.
set -euo pipefail
shaders=
seconds=6
while getopts s:t: opt; do
    case $opt in s) shaders=$OPTARG ;; t) seconds=$OPTARG ;; *) exit 2 ;; esac
done
shift $((OPTIND - 1))
[ $# -ge 1 ] || { echo "usage: $0 [-s SHADER_DIR] [-t SECONDS] SCENE [raylab-render args]..." >&2; exit 2; }
scene=$1
shift
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
env ${shaders:+RAYLAB_SHADER_DIR=$shaders} build/raylab-render "$scene" --width 96 --height 54 --spp 1000000 \
    --rpp 16 --seed 1 -q -o "$out/x.exr" "$@" &
pid=$!
trap 'kill $pid 2>/dev/null; rm -rf "$out"' EXIT
sleep 2.5   # past the compile and the first passes
perf record -q -e cpu-clock -F 4000 -p "$pid" -o "$out/perf.data" -- sleep "$seconds" >/dev/null 2>&1
perf script -i "$out/perf.data" -F ip 2>/dev/null >"$out/ips.txt"
# The executable anonymous mapping that holds the most samples is the shader's.
range=$(python3 - "$pid" "$out/ips.txt" <<'EOF'
import collections, sys
pid, ips = sys.argv[1], sys.argv[2]
counts = collections.Counter(int(l, 16) for l in open(ips) if l.strip())
best = (0, None)
for line in open(f"/proc/{pid}/maps"):
    f = line.split()
    if "x" not in f[1] or len(f) > 5:
        continue
    lo, hi = (int(x, 16) for x in f[0].split("-"))
    n = sum(v for a, v in counts.items() if lo <= a < hi)
    best = max(best, (n, (lo, hi)), key=lambda b: b[0])
print("%x %x" % best[1])
EOF
)
read -r lo hi <<<"$range"
gdb -p "$pid" -batch -ex "dump binary memory $out/jit.bin 0x$lo 0x$hi" >/dev/null 2>&1
kill "$pid"
objdump -D -b binary -mi386:x86-64 --adjust-vma="0x$lo" "$out/jit.bin" >"$out/jit.asm"
python3 "$(dirname "$0")/jit_profile.py" "$out/jit.asm" "$out/ips.txt" "$lo" "$hi"
