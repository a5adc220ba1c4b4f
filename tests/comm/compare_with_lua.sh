#!/usr/bin/env bash
# A code_aster command file (.comm, run through its .export) must compute exactly what the Lua deck
# of the same study computes. Usage:
#   compare_with_lua.sh LUNASTER EXPORT LUA_DECK OUTDIR
# Runs, into OUTDIR:
#   lua/        LUNASTER run LUA_DECK                       (must pass: its VALE_CALC are lunaster's)
#   comm/       LUNASTER run EXPORT                         (must pass; its VALE_CALC are code_aster's: reported by default)
#   converted/  LUNASTER convert <the .comm of EXPORT>, then the converted deck run plainly (unit 20 =
#               <name>.med beside it, linked to the mesh of the export); its VALE_CALC are code_aster's,
#               so it may end with NOOK: its exit status only has to say "ran to the end" (0 or 1).
# Then compares the REFERENCE='ANALYTIQUE' lines of TEST_RESU, keyed by what they test (NOM_CHAM,
# point, NOM_CMP; repeated keys are matched in order): both the .comm run and the converted run must
# have the same checks as the Lua run, each computed value within 1e-10 relative of the Lua run's
# (round-off), and every ANALYTIQUE check of the .comm run must be OK. The Lua deck's checks at its
# own tolerance beside code_aster's (LEGENDE '... lunaster: exact', testcases/lib/ssnp121_3d_checks.lua)
# have no twin in the .comm.
set -u

if [ $# -ne 4 ]; then
  echo "usage: $0 LUNASTER EXPORT LUA_DECK OUTDIR" >&2
  exit 2
fi
exe=$1 export_file=$2 deck=$3 out=$4
rel_tol=1e-10

fail() {
  echo "FAIL ($(basename "$export_file") vs $(basename "$deck")): $*" >&2
  exit 1
}

[ -x "$exe" ] || fail "no lunaster executable at $exe"
[ -f "$export_file" ] || fail "no export file $export_file"
[ -f "$deck" ] || fail "no Lua deck $deck"

# The files of the export: "F <type> <path> D|R <unit>", paths relative to the export's folder.
export_dir=$(cd "$(dirname "$export_file")" && pwd)
export_entry() {  # type [unit] -> absolute path of the first matching F line
  awk -v t="$1" -v u="${2:-}" '$1 == "F" && $2 == t && (u == "" || $5 == u) { print $3; exit }' "$export_file"
}
comm_rel=$(export_entry comm 1)
mesh_rel=$(export_entry mmed 20)
[ -n "$comm_rel" ] || fail "$export_file has no 'F comm NAME D 1' line"
[ -n "$mesh_rel" ] || fail "$export_file has no 'F mmed NAME D 20' line"
case $comm_rel in /*) comm=$comm_rel ;; *) comm=$export_dir/$comm_rel ;; esac
case $mesh_rel in /*) mesh=$mesh_rel ;; *) mesh=$export_dir/$mesh_rel ;; esac
[ -f "$comm" ] || fail "the export names $comm_rel, not found in $export_dir"
[ -f "$mesh" ] || fail "the export names the mesh $mesh_rel, not found in $export_dir"
name=$(basename "$comm" .comm)

rm -rf "$out"
mkdir -p "$out/converted"

# 1. The Lua deck: lunaster's own reference run.
"$exe" run "$deck" --out "$out/lua" > "$out/lua.log" 2>&1
status=$?
[ $status -eq 0 ] || fail "the Lua deck failed (exit $status), see $out/lua.log:
$(tail -20 "$out/lua.log")"

# 2. The export.
"$exe" run "$export_file" --out "$out/comm" > "$out/comm.log" 2>&1
status=$?
[ $status -eq 0 ] || fail "lunaster run $(basename "$export_file") failed (exit $status), see $out/comm.log:
$(tail -20 "$out/comm.log")"

# 3. `convert --check` finds nothing to finish in a case that runs; then the converted deck, run as
#    an ordinary Lua deck.
"$exe" convert --check "$comm" > "$out/check.log" 2>&1
status=$?
[ $status -eq 0 ] || fail "lunaster convert --check $(basename "$comm") reports issues (exit $status):
$(tail -20 "$out/check.log")"
converted=$out/converted/$name.lua
"$exe" convert "$comm" -o "$converted" > "$out/convert.log" 2>&1
status=$?
[ $status -eq 0 ] || fail "lunaster convert $(basename "$comm") failed (exit $status), see $out/convert.log:
$(tail -20 "$out/convert.log")"
ln -sf "$mesh" "$out/converted/$name.med"
"$exe" run "$converted" --out "$out/converted-out" > "$out/converted.log" 2>&1
status=$?
[ $status -le 1 ] || fail "the converted deck $converted stopped (exit $status), see $out/converted.log:
$(tail -20 "$out/converted.log")"

# TEST_RESU lines: "<status> ANALYTIQUE <what>  refe=<x>  calc=<y>  err=... tol=... <critere>".
# Prints "key<TAB>calc<TAB>status", key = what + "#" + occurrence number of that what.
analytical_checks() {
  awk '
    /^ *(OK|NOOK) +ANALYTIQUE / {
      status = $1
      line = $0
      sub(/^ *(OK|NOOK) +ANALYTIQUE +/, "", line)
      i = index(line, "  refe=")
      if (i == 0) next
      what = substr(line, 1, i - 1)
      rest = substr(line, i)
      if (!match(rest, /calc=[^ ]+/)) next
      calc = substr(rest, RSTART + 5, RLENGTH - 5)
      n = ++seen[what]
      printf "%s#%d\t%s\t%s\n", what, n, calc, status
    }' "$1"
}
analytical_checks "$out/lua.log" > "$out/lua.checks"
analytical_checks "$out/comm.log" > "$out/comm.checks"
analytical_checks "$out/converted.log" > "$out/converted.checks"
[ -s "$out/lua.checks" ] || fail "the Lua deck printed no REFERENCE='ANALYTIQUE' check (see $out/lua.log)"

# Same checks, same values: ($1 = label, $2 = checks file); prints the problems, returns their count.
compare_checks() {
  awk -F'\t' -v label="$1" -v tol="$rel_tol" '
    function abs(x) { return x < 0 ? -x : x }
    NR == FNR { ref[$1] = $2; order[++n] = $1; next }
    {
      got[$1] = 1
      if (!($1 in ref)) { printf "  %s: check %s is not in the Lua run\n", label, $1; bad++; next }
      a = ref[$1] + 0; b = $2 + 0
      scale = abs(a) > abs(b) ? abs(a) : abs(b)
      d = abs(a - b)
      if (d > tol * scale) {
        printf "  %s: %s calc=%s, Lua deck calc=%s (relative difference %.3e > %g)\n", label, $1, $2, ref[$1], d / scale, tol
        bad++
      }
    }
    END {
      for (i = 1; i <= n; ++i)
        if (!(order[i] in got) && order[i] !~ /lunaster: exact\]#/) { printf "  %s: check %s of the Lua run is missing\n", label, order[i]; bad++ }
      exit (bad > 0 ? 1 : 0)
    }' "$out/lua.checks" "$2"
}

problems=""
if ! report=$(compare_checks ".comm run" "$out/comm.checks"); then problems+="$report"$'\n'; fi
if ! report=$(compare_checks "converted deck" "$out/converted.checks"); then problems+="$report"$'\n'; fi
nook=$(awk -F'\t' '$3 != "OK" { printf "  .comm run: ANALYTIQUE check %s is NOOK (calc=%s)\n", $1, $2 }' "$out/comm.checks")
[ -z "$nook" ] || problems+="$nook"$'\n'

if [ -n "$problems" ]; then
  fail "the .comm and the Lua deck do not compute the same study:
$problems(logs: $out/lua.log, $out/comm.log, $out/converted.log)"
fi
echo "OK: $(wc -l < "$out/comm.checks") analytical check(s) of $(basename "$export_file") and of the converted" \
     "$name.lua equal those of $(basename "$deck") within $rel_tol, all OK"
