#!/usr/bin/env bash
# Runs every libFuzzer harness of a LUNASTER_FUZZ build for a bounded time.
# usage: run_fuzzers.sh BUILD_DIR [SECONDS_PER_HARNESS] [SEED]
# SEED 0 (the default) lets libFuzzer pick a random seed; CI passes a fixed seed so that a
# red run there is reproducible with the same command.
# New corpus entries go to BUILD_DIR/fuzz-corpus/<harness>/ (the committed corpus in
# tests/fuzz/corpus/<harness>/ is only read); crash inputs go to BUILD_DIR/fuzz-artifacts/.
set -u
build=$1; seconds=${2:-20}; seed=${3:-0}
here=$(cd "$(dirname "$0")" && pwd)
status=0
for harness in fuzz_gmsh_reader fuzz_med_reader fuzz_deck; do
  exe=$build/tests/fuzz/$harness
  if [ ! -x "$exe" ]; then echo "run_fuzzers: $exe missing (configure with -DLUNASTER_FUZZ=ON)"; exit 2; fi
  scratch=$build/fuzz-corpus/$harness; artifacts=$build/fuzz-artifacts/$harness/
  mkdir -p "$scratch" "$artifacts"
  echo "=== $harness: ${seconds}s, seed $seed"
  # -timeout: one input taking over 10 s is a hang; -rss_limit_mb: runaway memory is a bug.
  if ! ASAN_OPTIONS=detect_leaks=1 LSAN_OPTIONS=suppressions=$here/lsan.supp \
       UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
       "$exe" "$scratch" "$here/corpus/$harness" -max_total_time="$seconds" -seed="$seed" -timeout=10 -rss_limit_mb=2048 \
       -artifact_prefix="$artifacts" -print_final_stats=1 2>"$build/fuzz-$harness.log"; then
    echo "FAIL: $harness found a crash; see $build/fuzz-$harness.log and $artifacts"
    tail -40 "$build/fuzz-$harness.log"
    status=1
  else
    grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "$build/fuzz-$harness.log" | sed 's/^/  /'
  fi
done
exit $status
