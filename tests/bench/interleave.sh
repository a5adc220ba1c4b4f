#!/usr/bin/env bash
# Contact against glued (or elastic) runs on a machine whose speed drifts: whole runs of
# `lunaster run DECK -q`, timed by /usr/bin/time, every deck once per round, R rounds. Prints
# each round's wall times, then per deck the median wall and the median of the per-round
# ratios to the first deck, or to the REF-th (runs of one round are seconds apart, so the ratio
# sees one speed).
# The decks are those that `KEEP=1 tests/bench/contact_speed.sh -r 1 -c CASES BINARY` keeps. A
# CalculiX input (NAME.inp, e.g. written by tests/bench/study/ccx/med2inp.py from the same mesh) is
# run as `ccx -i NAME` in its folder, in the same rounds (Debian's calculix-ccx, which
# `scripts/install-deps.sh study` installs).
#
# Usage: [REF=K] tests/bench/interleave.sh BINARY R DECK|INP [DECK|INP ...]
#   REF=K: the ratios are to the K-th deck (default 1, the first)
set -euo pipefail
[ $# -ge 3 ] || { echo "usage: $0 BINARY R DECK [DECK ...]" >&2; exit 2; }
bin=$(readlink -f "$1"); rounds=$2; shift 2
t=$(mktemp); trap 'rm -f "$t"' EXIT
rows=()
for _ in $(seq 1 "$rounds"); do
  line=""
  for deck in "$@"; do
    if [ "${deck%.inp}" != "$deck" ]; then
      (cd "$(dirname "$deck")" && /usr/bin/time -f "%e" -o "$t" ccx -i "$(basename "${deck%.inp}")" >/dev/null 2>&1) ||
        { echo "$0: ccx on $deck failed" >&2; exit 1; }
    else
      (cd "$(dirname "$deck")" && /usr/bin/time -f "%e" -o "$t" "$bin" run "$(basename "$deck")" -q >/dev/null 2>&1) ||
        { echo "$0: $deck failed" >&2; exit 1; }
    fi
    line="$line $(cat "$t")"
  done
  echo "$line"
  rows+=("$line")
done
printf '%s\n' "${rows[@]}" | /usr/bin/python3 -c '
import statistics, sys
rows = [list(map(float, l.split())) for l in sys.stdin if l.strip()]
names = sys.argv[2:]
ref = int(sys.argv[1]) - 1
for k, name in enumerate(names):
    ratios = [r[k] / r[ref] for r in rows]
    print(f"{name}: median {statistics.median(c[k] for c in rows):.2f} s, against {names[ref]} "
          f"{statistics.median(ratios):.2f} ({min(ratios):.2f}-{max(ratios):.2f})")
' "${REF:-1}" "$@"
