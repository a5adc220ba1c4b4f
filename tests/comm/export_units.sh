#!/usr/bin/env bash
# An .export's result units and message file, and the migration report through `lunaster verify`:
#   - `F rmed NAME R 80` makes IMPR_RESU(UNITE=80) write NAME in the output folder;
#   - `F mess NAME R 6` gets a copy of everything the run prints;
#   - `F datg NAME D 16` (the script that made the mesh, which no study reads) is skipped with a
#     line in the log naming its line;
#   - the VALE_CALC of a .comm are code_aster's: by default `run` and `verify` report them (SAME/DIFF
#     lines, exit 0 on testcases/comm/ssnp121a.export, whose code_aster values differ from lunaster's
#     beyond TOLE_MACHINE), --vale-calc=check counts them (NOOK, exit 1), and the same checks in a
#     Lua deck (the .comm converted) count by default (NOOK, exit 1);
#   - verify --json carries each comparison with code_aster (the "code_aster" array);
#   - convert --check lists every form to finish in a file, with its line, and exits 2.
# Usage: export_units.sh LUNASTER SOURCE_DIR OUTDIR
set -u
exe=$1; src=$2; out=$3
rm -rf "$out"; mkdir -p "$out/case"
fail() { echo "FAIL: $*"; exit 1; }

cp "$src/testcases/comm/ssnp121a.comm" "$out/case/"
echo "* the script that generated the mesh: never read by the study" > "$out/case/ssnp121a.datg"
cat > "$out/case/study.export" <<EOT
P time_limit 60
P memory_limit 512
F comm ssnp121a.comm D 1
F mmed $src/testcases/ssnp121a.med D 20
F rmed contact_result.rmed R 80
F mess study.mess R 6
F datg ssnp121a.datg D 16
EOT
"$exe" run "$out/case/study.export" --vale-calc=report --out "$out/run" > "$out/run.log" 2>&1
status=$?
[ $status -eq 0 ] || fail "run exited $status: $(tail -5 "$out/run.log")"
grep -q "study.export: file type 'datg' (line 7, ssnp121a.datg) is not read by the study: skipped" "$out/run.log" ||
  fail "no line saying the datg file of line 7 is skipped"
[ -s "$out/run/contact_result.rmed" ] || fail "IMPR_RESU(UNITE=80) did not write contact_result.rmed: $(ls "$out/run")"
[ -s "$out/run/study.mess" ] || fail "no message file study.mess"
grep -q '^ OK  ANALYTIQUE     DEPL  O  LAGS_C' "$out/run/study.mess" || fail "the message file lacks the TEST_RESU lines"
grep -q '^\(SAME\|DIFF\) CODE_ASTER     DEPL  O  LAGS_C  refe=-1.003510000e+05' "$out/run.log" ||
  fail "no CODE_ASTER report line for LAGS_C at O"
grep -q "comparison(s) with code_aster's VALE_CALC" "$out/run.log" || fail "no comparison summary"

# The default for a .comm's VALE_CALC: reported; --vale-calc=check: counted.
case_export=$src/testcases/comm/ssnp121a.export
"$exe" run "$case_export" --out "$out/default" > "$out/default.log" 2>&1
status=$?
[ $status -eq 0 ] || fail "run ssnp121a.export (default) exited $status: $(tail -5 "$out/default.log")"
grep -q '^DIFF CODE_ASTER ' "$out/default.log" || fail "run ssnp121a.export (default): no DIFF line"
grep -q '^NOOK' "$out/default.log" && fail "run ssnp121a.export (default): a NOOK line"
grep -q "beyond tolerance, .*; reported, not counted (--vale-calc=check counts them)" "$out/default.log" ||
  fail "run ssnp121a.export (default): the summary does not say the comparisons are reported"
"$exe" run "$case_export" --vale-calc=check --out "$out/vale-check" > "$out/vale-check.log" 2>&1
status=$?
[ $status -eq 1 ] || fail "run ssnp121a.export --vale-calc=check exited $status, expected 1 (NOOK)"
grep -q '^NOOK CODE_ASTER ' "$out/vale-check.log" || fail "run ssnp121a.export --vale-calc=check: no NOOK CODE_ASTER line"
# The same checks in a Lua deck are lunaster's own non-regression values: counted by default.
mkdir -p "$out/lua"
"$exe" convert "$src/testcases/comm/ssnp121a.comm" -o "$out/lua/ssnp121a.lua" > "$out/convert.log" 2>&1 ||
  fail "convert ssnp121a.comm: $(cat "$out/convert.log")"
ln -sf "$src/testcases/ssnp121a.med" "$out/lua/ssnp121a.med"
"$exe" run "$out/lua/ssnp121a.lua" --out "$out/lua-run" > "$out/lua.log" 2>&1
status=$?
[ $status -eq 1 ] || fail "the converted Lua deck exited $status, expected 1 (its VALE_CALC count)"
grep -q '^NOOK NON_REGRESSION ' "$out/lua.log" || fail "the converted Lua deck: no NOOK NON_REGRESSION line"

"$exe" verify "$out/case" -j 1 --vale-calc=report --out "$out/verify" --json "$out/verify.json" > "$out/verify.log" 2>&1
status=$?
[ $status -eq 0 ] || fail "verify --vale-calc=report exited $status: $(tail -5 "$out/verify.log")"
grep -q '"code_aster": \[{"check": "DEPL  A  DY", "lunaster": ' "$out/verify.json" || fail "JSON lacks the code_aster array"
grep -q 'comparisons with code_aster' "$out/verify.log" || fail "verify prints no comparison table"
"$exe" verify "$out/case" -j 1 --out "$out/verify-default" > "$out/verify-default.log" 2>&1
status=$?
[ $status -eq 0 ] || fail "verify (default: reported) exited $status: $(tail -5 "$out/verify-default.log")"
grep -q "beyond tolerance (reported, not counted" "$out/verify-default.log" || fail "verify (default) does not say it reports"
"$exe" verify "$out/case" -j 1 --vale-calc=check --out "$out/verify-check" > "$out/verify-check.log" 2>&1
[ $? -eq 1 ] || fail "verify --vale-calc=check should count the comparisons beyond TOLE_MACHINE as NOOK"

"$exe" convert --check "$src/testcases/errors/comm_python_loop.comm" > "$out/check.log" 2>&1
status=$?
[ $status -eq 2 ] || fail "convert --check exited $status on a file with forms to finish"
grep -q "comm_python_loop.comm:8: 'for' loop" "$out/check.log" || fail "convert --check: no line 8 'for' loop: $(cat "$out/check.log")"
grep -q "comm_python_loop.comm:10: " "$out/check.log" || fail "convert --check: no line 10 import: $(cat "$out/check.log")"
echo "PASS"
