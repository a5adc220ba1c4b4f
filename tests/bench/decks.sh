#!/usr/bin/env bash
# Wall time of whole deck runs (start-up included): median of R runs per deck.
# Usage: tests/bench/decks.sh [BUILD_DIR] [R] [DECK...]   (default: every testcases/*.lua, R=5)
set -euo pipefail
build=${1:-build}; runs=${2:-5}; shift 2 || shift $#
root=$(cd "$(dirname "$0")/../.." && pwd)
decks=("$@"); [ ${#decks[@]} -gt 0 ] || decks=("$root"/testcases/*.lua)
out=$(mktemp -d); trap 'rm -rf "$out"' EXIT
printf "%-40s %10s %10s\n" deck median_s max_MB
for deck in "${decks[@]}"; do
  times=(); mem=0
  for _ in $(seq "$runs"); do
    /usr/bin/time -f "%e %M" -o "$out/t" "$root/$build/lunaster" run "$deck" --out "$out/o" -q >/dev/null 2>&1 || true
    read -r wall kb < "$out/t"; times+=("$wall"); [ "$kb" -gt "$mem" ] && mem=$kb
  done
  median=$(printf "%s\n" "${times[@]}" | sort -g | sed -n "$(( (runs + 1) / 2 ))p")
  printf "%-40s %10s %10d\n" "$(basename "$deck")" "$median" $((mem / 1024))
done
