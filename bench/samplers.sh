#!/bin/bash
# The figures of bench/samplers.md: RMSE at equal samples (64 and 192 spp) and CPU milliseconds
# per spp of every sampler with NEE + MIS (the defaults), 96×54, against a 2048-spp independent
# reference of another seed. The samplers take turns within each seed, so a change in the
# machine's load falls on all of them. Run from the repository root after building:
#   nice -n 5 bash bench/samplers.sh
set -e
R=${R:-build/raylab-render}
O=${O:-/tmp/raylab-samplers}
mkdir -p "$O"
S="--width 96 --height 54 --rpp 16 -q --set render.nee=true --set render.mis=true"
SAMPLERS="independent stratified sobol zsobol"
# CPU seconds (user + system, every llvmpipe thread) of one run: on a shared machine the wall
# time is mostly waiting for a core.
cpu() { local TIMEFORMAT="%U %S"; { time "$@" >/dev/null 2>&1; } 2>&1 | awk '{ print $1 + $2 }'; }
rms() { oiiotool "$1" --ch R,G,B "$2" --ch R,G,B --diff 2>/dev/null | sed -n 's/.*RMS error = *\([0-9.e+-]*\).*/\1/p'; }
[ -n "$SKIP_RMSE" ] || for sc in default materials; do
  $R scenes/$sc.json $S --spp 2048 --seed 4242 --set render.sampler=independent -o "$O/${sc}_ref.exr" >/dev/null
  for seed in 1 2 3; do
    for s in $SAMPLERS; do
      for n in 64 192; do
        $R scenes/$sc.json $S --spp $n --seed $seed --set render.sampler=$s -o "$O/${sc}_${s}_$n.exr" >/dev/null
        echo "$sc $s $n $seed $(rms "$O/${sc}_${s}_$n.exr" "$O/${sc}_ref.exr")"
      done
    done
  done
done > "$O/rmse.txt"
# CPU time of 64 and 576 spp, three times each, the samplers in turn.
for sc in default materials; do
  for i in 1 2 3; do
    for s in $SAMPLERS; do
      for n in 64 576; do
        echo "$sc $s $n $(cpu $R scenes/$sc.json $S --spp $n --set render.sampler=$s -o "$O/t.exr")"
      done
    done
  done
done > "$O/cpu.txt"
# Per scene and sampler: RMSE at 64 and 192 spp (root of the mean square over the seeds) and CPU
# ms per spp, (median at 576 − median at 64) / 512, the start-up cancelled.
awk 'function med(s,  a, x, y, z) { split(s, a, " "); x = a[1] + 0; y = a[2] + 0; z = a[3] + 0
                                    return x + y + z - (x > y ? (x > z ? x : z) : (y > z ? y : z)) - (x < y ? (x < z ? x : z) : (y < z ? y : z)) }
     FILENAME ~ /rmse/ { k = $1 " " $2; if ($3 == 64) m64[k] += $5 * $5 / 3; else m192[k] += $5 * $5 / 3; next }
     { k = $1 " " $2; if ($3 == 64) t64[k] = t64[k] " " $4; else t576[k] = t576[k] " " $4 }
     END { for (k in m64) printf "%s rmse64 %.5f rmse192 %.5f cpu-ms/spp %.2f\n", k, sqrt(m64[k]), sqrt(m192[k]), (med(t576[k]) - med(t64[k])) * 1000 / 512 }' \
    "$O/rmse.txt" "$O/cpu.txt" | sort
for sc in default materials; do echo "$sc mean: $(oiiotool "$O/${sc}_ref.exr" --ch R,G,B --printstats | grep Avg)"; done
