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
# About half a second of Lua, long enough to read the environment of the running process.
printf 'local x = 0\nfor i = 1, 3e8 do x = x + i end\n' > spin.lua

# environment_of PID: the GLIBC_TUNABLES entry of the running process ("absent" if it has none),
# once the process runs the deck (lunaster is past its start); "ended" if it ended first.
environment_of() {
  local pid=$1 i
  for i in $(seq 1 100); do
    [ -r "/proc/$pid/environ" ] || { echo ended; return; }
    if [ "$(readlink "/proc/$pid/exe")" = "$engine" ] && [ "$i" -gt 4 ]; then
      tr '\0' '\n' < "/proc/$pid/environ" | grep '^GLIBC_TUNABLES=' || echo absent
      return
    fi
    sleep 0.05
  done
  echo "still starting"
}

# The arguments go through the new start: `run spin.lua` ends with 0, a lost argument with 2.
env -u GLIBC_TUNABLES "$lunaster" run spin.lua -q & pid=$!
seen=$(environment_of $pid); wait $pid; code=$?
if [ "$seen" != "GLIBC_TUNABLES=glibc.malloc.hugetlb=1" ] || [ $code -ne 0 ]; then
  echo "FAIL: started without GLIBC_TUNABLES, the run saw '$seen' and ended with $code"
  fail=1
fi
GLIBC_TUNABLES= "$lunaster" run spin.lua -q & pid=$!
seen=$(environment_of $pid); wait $pid; code=$?
if [ "$seen" != "GLIBC_TUNABLES=" ] || [ $code -ne 0 ]; then
  echo "FAIL: with GLIBC_TUNABLES set empty by the user, the run saw '$seen' and ended with $code"
  fail=1
fi
env -u GLIBC_TUNABLES "$engine" run spin.lua -q & pid=$!
seen=$(environment_of $pid); wait $pid; code=$?
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
