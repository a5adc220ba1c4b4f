#!/usr/bin/env bash
# usage: run_logged.sh LOG COMMAND...: runs COMMAND, its standard output and error merged, prints
# what it prints and keeps a copy in LOG; exits with COMMAND's status. The log tests
# (lunaster_log_test, tests/CMakeLists.txt) keep their run's log so that
# tests/decks/log_tests_fail.py can check that wrong versions of it fail them.
set -u
log=$1; shift
mkdir -p "$(dirname "$log")"
"$@" 2>&1 | tee "$log"
exit "${PIPESTATUS[0]}"
