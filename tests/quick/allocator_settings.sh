#!/usr/bin/env bash
# lunaster, the launcher (lua/launcher.c), starts the engine with glibc's allocator tunables
# (lua/allocator_settings.h) unless GLIBC_TUNABLES is already set, and needs the C library alone
# (so that the engine's libraries are loaded once); the engine started directly starts itself
# again with them (lua/main.cpp). Checked from outside, through /proc/PID/environ of a running
# deck: an exec keeps the process id. (glibc writes into the original environment block
# as it parses the tunables, so /proc shows the first of them only; the full string is what the
# process itself and its children see.)
# usage: allocator_settings.sh LUNASTER SCRATCH [sanitized]
set -u
lunaster=$(readlink -f "$1"); scratch=$2
engine=$(dirname "$lunaster")/lunaster-engine
fail=0
# The launcher loads nothing but the C library (a sanitizer build adds its runtime).
needed=$(readelf -d "$lunaster" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p' | tr '\n' ' ')
if [ "${3:-}" != sanitized ] && [ "$needed" != "libc.so.6 " ]; then
  echo "FAIL: the launcher needs '$needed', expected libc.so.6 alone"
  fail=1
fi
if [ "${3:-}" = sanitized ]; then echo "sanitizer build: its own allocator, no restart"; exit 77; fi
rm -rf "$scratch"; mkdir -p "$scratch"; cd "$scratch" || exit 1; scratch=$(pwd -P)
# A deck that says it runs (a line longer than stdout's buffer, written to the file at once),
# then waits for go.lua (the script writes it once it has read the process's environment;
# `require` finds a module next to the deck), however long the machine takes to let the script
# look. A hang guard, far beyond any wait (5e6 looks, about a minute of CPU), ends it with an error.
printf '%s\n' "print('spin: running ' .. ('.'):rep(1 << 16))" "local n = 0" \
  "while not pcall(require, 'go') do" "  n = n + 1" \
  "  if n > 5e6 then error('go.lua never came') end" "end" > spin.lua
trap 'echo > "$scratch/go.lua"' EXIT  # the last deck never waits for a script that has gone

# environment_of PID OUTPUT: the GLIBC_TUNABLES entry of the running process ("absent" if it has
# none), read once the deck runs (it printed to OUTPUT, past lunaster's start and restart), then
# lets the deck end; "ended" if it ended first.
environment_of() {
  local pid=$1 output=$2 i seen
  for i in $(seq 1 2400); do  # a hang guard of 120 s
    [ -r "/proc/$pid/environ" ] || { echo ended; return; }
    grep -q '^spin: running' "$output" 2>/dev/null && break
    sleep 0.05
  done
  if ! grep -q '^spin: running' "$output" 2>/dev/null; then
    seen="still starting"
  elif [ "$(readlink "/proc/$pid/exe")" != "$engine" ]; then
    seen="running $(readlink "/proc/$pid/exe"), not the engine"
  else
    seen=$(tr '\0' '\n' < "/proc/$pid/environ" | grep '^GLIBC_TUNABLES=' || echo absent)
  fi
  echo > go.lua
  echo "$seen"
}

# The arguments go through the new start: `run spin.lua` ends with 0, a lost argument with 2.
rm -f go.lua
env -u GLIBC_TUNABLES "$lunaster" run spin.lua -q > run1.out & pid=$!
seen=$(environment_of $pid run1.out); wait $pid; code=$?
if [ "$seen" != "GLIBC_TUNABLES=glibc.malloc.hugetlb=1" ] || [ $code -ne 0 ]; then
  echo "FAIL: started without GLIBC_TUNABLES, the run saw '$seen' and ended with $code"
  fail=1
fi
rm -f go.lua
GLIBC_TUNABLES= "$lunaster" run spin.lua -q > run2.out & pid=$!
seen=$(environment_of $pid run2.out); wait $pid; code=$?
if [ "$seen" != "GLIBC_TUNABLES=" ] || [ $code -ne 0 ]; then
  echo "FAIL: with GLIBC_TUNABLES set empty by the user, the run saw '$seen' and ended with $code"
  fail=1
fi
rm -f go.lua
env -u GLIBC_TUNABLES "$engine" run spin.lua -q > run3.out & pid=$!
seen=$(environment_of $pid run3.out); wait $pid; code=$?
if [ "$seen" != "GLIBC_TUNABLES=glibc.malloc.hugetlb=1" ] || [ $code -ne 0 ]; then
  echo "FAIL: the engine started directly, without GLIBC_TUNABLES, saw '$seen' and ended with $code"
  fail=1
fi
# A launcher without its engine says so, with the path it tried.
cp "$lunaster" alone; ./alone run spin.lua -q > alone.out 2>&1; code=$?
if [ $code -ne 127 ] || ! grep -q "cannot start the engine $scratch/lunaster-engine" alone.out; then
  echo "FAIL: a launcher without its engine ended with $code: $(cat alone.out)"
  fail=1
fi
[ $fail -eq 0 ] && echo "allocator settings: applied by default (launcher or engine), the user's setting kept"
exit $fail
