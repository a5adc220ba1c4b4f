#!/usr/bin/env bash
# DEBUT MESURE_TEMPS on testcases/comm/ssnp121a.comm, whose DEBUT is rewritten in a scratch copy:
#   - NIVE_DETAIL=1: after STAT_NON_LINE the wall time of the command and of its phases;
#   - NIVE_DETAIL=2, MOYENNE='OUI': the same times as mean and standard deviation over the ranks
#     (one here), and the counts of the command's instants, iterations and factorisations;
#   - NIVE_DETAIL=0, and no MESURE_TEMPS: no report;
#   - NIVE_DETAIL=3 (code_aster's times per time step) stops the deck at DEBUT's line with the reason.
# Every run but the last keeps its checks OK.
# Usage: mesure_temps.sh LUNASTER SOURCE_DIR OUTDIR
set -u
exe=$1; src=$2; out=$3
rm -rf "$out"; mkdir -p "$out"
fail() { echo "FAIL: $*"; exit 1; }
run() {  # run NAME DEBUT-ARGUMENTS: the log in $out/NAME.log, the exit status returned
  sed "s/^DEBUT(CODE='OUI')/DEBUT(CODE='OUI', $2)/" "$src/testcases/comm/ssnp121a.comm" > "$out/$1.comm"
  grep -qF "$2" "$out/$1.comm" || fail "$1: DEBUT not rewritten"
  printf 'F comm %s.comm D 1\nF mmed %s/testcases/ssnp121a.med D 20\n' "$1" "$src" > "$out/$1.export"
  "$exe" run "$out/$1.export" --out "$out/run-$1" > "$out/$1.log" 2>&1
}
phases='^    (total|assembly|contact|factorisation|solve) +[0-9]+\.[0-9]{3} s'
run one "MESURE_TEMPS=_F()" || fail "NIVE_DETAIL=1 exited $?"
[ "$(grep -cE "$phases\$" "$out/one.log")" = 5 ] || fail "NIVE_DETAIL=1: not the 5 phase times"
grep -q "time of the command (MESURE_TEMPS, wall clock)" "$out/one.log" || fail "NIVE_DETAIL=1: no report header"
grep -qE "^    [0-9]+ instant\(s\), " "$out/one.log" && fail "NIVE_DETAIL=1 printed the counts of level 2"
run two "MESURE_TEMPS=_F(NIVE_DETAIL=2, MOYENNE='OUI')" || fail "NIVE_DETAIL=2 exited $?"
[ "$(grep -cE "$phases \(standard deviation 0\.000 s over 1 rank\(s\)\)\$" "$out/two.log")" = 5 ] ||
  fail "MOYENNE='OUI': not the 5 times with their standard deviation over 1 rank"
grep -qE '^    [1-9][0-9]* instant\(s\), [1-9][0-9]* Newton iteration\(s\), [1-9][0-9]* factorisation\(s\), [0-9]+ contact pass\(es\), [0-9]+ refinement step\(s\), [1-9][0-9]* unknowns$' \
  "$out/two.log" || fail "NIVE_DETAIL=2: no counts"
run zero "MESURE_TEMPS=_F(NIVE_DETAIL=0)" || fail "NIVE_DETAIL=0 exited $?"
grep -qE "MESURE_TEMPS, wall clock|$phases" "$out/zero.log" && fail "NIVE_DETAIL=0 printed a report"
run three "MESURE_TEMPS=_F(NIVE_DETAIL=3)" && fail "NIVE_DETAIL=3 was accepted"
grep -qE "three\.comm:11: DEBUT: MESURE_TEMPS.*NIVE_DETAIL: expected 0, 1 or 2 \(the times of whole commands\), got 3" \
  "$out/three.log" || fail "NIVE_DETAIL=3: not refused at DEBUT's line: $(head -2 "$out/three.log")"
grep -q "measures a nonlinear command as a whole" "$out/three.log" || fail "NIVE_DETAIL=3: no reason"
for r in one two zero; do
  grep -qE "[1-9][0-9]* check\(s\) OK, 0 NOOK" "$out/$r.log" || fail "$r: checks not all OK"
done
"$exe" run "$src/testcases/comm/ssnp121a.export" --out "$out/run-none" > "$out/none.log" 2>&1 || fail "no MESURE_TEMPS: exit $?"
grep -qE "MESURE_TEMPS, wall clock|$phases" "$out/none.log" && fail "a report without MESURE_TEMPS"
echo "MESURE_TEMPS: levels 0, 1, 2 and MOYENNE as documented, level 3 refused"
