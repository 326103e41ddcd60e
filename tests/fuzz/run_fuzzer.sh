#!/bin/sh
# Runs one libFuzzer harness of a RAYLAB_FUZZ build for SECONDS, new inputs kept in
# BUILD/tests/fuzz/runs/HARNESS beside the read-only seeds (make_seed_corpus.py), its log in
# BUILD/tests/fuzz/runs/HARNESS.log. Exit status non-zero on a finding (crash-*, leak-*, timeout-*
# files in BUILD/tests/fuzz/runs/). Usage: tests/fuzz/run_fuzzer.sh BUILD HARNESS SECONDS [libFuzzer flags]
set -eu
build=$1 harness=$2 seconds=$3
shift 3
case "$harness" in
  fuzz_scene) max_len=16384 ;;   # the longest shipped scene is about 9 KB
  fuzz_gltf) max_len=16384 ;;
  fuzz_obj) max_len=8192 ;;
  fuzz_script) max_len=8192 ;;
  *) echo "run_fuzzer.sh: unknown harness '$harness'" >&2; exit 2 ;;
esac
fuzz="$build/tests/fuzz"
runs="$fuzz/runs"
mkdir -p "$runs/$harness"
# -timeout: one input may take 10 s under ASan before it counts as a hang; -rss_limit_mb: the loaders
# refuse sizes past their limits long before 2 GB.
"$fuzz/$harness" "$runs/$harness" "$fuzz/corpus/$harness" -dict="$fuzz/corpus/$harness.dict" \
  -max_len="$max_len" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
  -artifact_prefix="$runs/$harness-" "$@" > "$runs/$harness.log" 2>&1 || {
  status=$?
  tail -n 60 "$runs/$harness.log" >&2
  exit "$status"
}
tail -n 12 "$runs/$harness.log"
