#!/usr/bin/env bash
# code_aster's own SSNP121 decks, modelisations A to K, run as they are: their .comm and .export read
# from a code_aster clone (its git directory in ASTEST_GIT: none is vendored; without it the test is
# skipped, exit 77) into OUTDIR, their binary MED meshes (not in the public clone) stood in for by the
# project's SSNP121 meshes (testcases/ssnp121*.med) copied under the names the .export gives.
# `lunaster run X.export` must exit 0, with every VALE_REFE (ANALYTIQUE) check OK and as many of them
# as the deck has; the VALE_CALC (code_aster's values) are reported, not
# counted, and their largest difference printed. The log must also say what the decks' NEWTON
# REAC_INCR and MATRICE='ELASTIQUE' with contact do, and CREA_CHAMP what it extracted.
# Usage: ASTEST_GIT=<code_aster .git> astest_ssnp121.sh LUNASTER MESHGEN SOURCE_DIR OUTDIR
set -u
exe=$1 gen=$2 src=$3 out=$4
[ -n "${ASTEST_GIT:-}" ] || { echo "ASTEST_GIT is not set: skipped"; exit 77; }
mkdir -p "$out" && cd "$out" || exit 1
failed=0
# The project's SSNP121 meshes under the .export's names; code_aster's decks of the 2D mesh name node
# N14, so that one is made again with the node names of code_aster's GIBI script (same nodes, cells,
# groups and order as testcases/ssnp121a.med: tools/make_meshes.sh).
"$gen" --upper quad4:12 --lower quad4:11 --gibi-node-names -o "$out/ssnp121a.med" > /dev/null 2>&1 &&
  mv "$out/ssnp121a.med" "$out/ssnp121a.mmed" || { echo "FAIL: lunaster-meshgen could not make ssnp121a.mmed"; failed=1; }
for x in d e f h i j k; do cp "$src/testcases/ssnp121$x.med" "$out/ssnp121$x.mmed" || failed=1; done
for x in a b c d e f g h i j k; do
  t=ssnp121$x
  for ext in comm export; do
    git --git-dir="$ASTEST_GIT" show "HEAD:astest/$t.$ext" > "$t.$ext" 2>/dev/null ||
      { echo "FAIL: $t.$ext is not in the clone"; failed=1; continue 2; }
  done
  "$exe" run "$t.export" --out "$out/out-$t" > "$t.log" 2>&1
  rc=$?
  refe=$(grep -c "VALE_REFE" "$t.comm")
  ok=$(grep -c "^ OK  ANALYTIQUE" "$t.log")
  nook=$(grep -c "^NOOK ANALYTIQUE" "$t.log")
  calc=$(grep -oE "largest difference [0-9.e+-]+" "$t.log" | head -1)
  if [ "$rc" != 0 ] || [ "$ok" != "$refe" ] || [ "$nook" != 0 ]; then
    echo "FAIL: $t: exit $rc, $ok of $refe VALE_REFE checks OK, $nook NOOK ($(grep -m1 -E '^[^ ]+:[0-9]+: [A-Z_]+: ' "$t.log"))"
    failed=1
  else
    echo "ok   $t: $ok of $refe VALE_REFE checks OK; VALE_CALC (code_aster's) $calc"
  fi
done
# What the decks' keywords did, said in the log.
for pair in "ssnp121a:NEWTON REAC_INCR = 1: the matrix is formed anew at the first iteration of every increment" \
            "ssnp121d:NEWTON MATRICE = 'ELASTIQUE' with contact: the matrix is the elastic stiffness plus the contact terms" \
            "ssnp121a:SIGM_ELNO of 'RESU' at NUME_ORDRE 1 (INST 1): ELNO_SIEF_R, " \
            "ssnp121d:NOEUD                 DX              DY              DZ          LAGS_C"; do
  t=${pair%%:*} line=${pair#*:}
  grep -qF "$line" "$t.log" out-$t/*.resu 2>/dev/null || { echo "FAIL: $t: no '$line' in its log or .resu"; failed=1; }
done
exit $failed
