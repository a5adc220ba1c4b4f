#!/usr/bin/env bash
# Runs a must-fail deck and checks that it fails with a non-zero status and that
# its output matches every "-- EXPECT_ERROR: <regex>" line (extended regex) and,
# if present, "-- EXPECT_STATUS: <n>". code_aster files (.comm, .export) write "# " for "-- ".
set -u
exe=$1; deck=$2; out=$3
mkdir -p "$out"
output=$("$exe" run "$deck" --out "$out" 2>&1); status=$?
echo "$output"
if [ "$status" -eq 0 ]; then echo "FAIL: $deck exited 0, an error was expected"; exit 1; fi
want_status=$(sed -n 's/^\(--\|#\) EXPECT_STATUS: *//p' "$deck" | head -1)
if [ -n "$want_status" ] && [ "$status" -ne "$want_status" ]; then
  echo "FAIL: exit status $status, expected $want_status"; exit 1
fi
n=0
while IFS= read -r pattern; do
  n=$((n + 1))
  if ! grep -Eq -- "$pattern" <<<"$output"; then echo "FAIL: output does not match: $pattern"; exit 1; fi
done < <(sed -n 's/^\(--\|#\) EXPECT_ERROR: *//p' "$deck")
if [ "$n" -eq 0 ]; then echo "FAIL: $deck has no EXPECT_ERROR line"; exit 1; fi
echo "PASS: $n pattern(s) matched, exit status $status"
