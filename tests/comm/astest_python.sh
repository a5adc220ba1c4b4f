#!/usr/bin/env bash
# code_aster's own contact decks whose Python (math, loops, defs, comprehensions, formatting, FORMULE)
# lunaster translates: `lunaster convert --check` on each must report no untranslated Python form, only
# commands and keywords the catalogue does not have yet. The decks are read from a code_aster clone
# (its git directory in ASTEST_GIT: none is vendored); without it the test is skipped (exit 77).
# Usage: ASTEST_GIT=<code_aster .git> astest_python.sh LUNASTER OUTDIR
set -u
exe=$1 out=$2
[ -n "${ASTEST_GIT:-}" ] || { echo "ASTEST_GIT is not set: skipped"; exit 77; }
decks="forma04a forma04b forma04c sdnv100a sdnv100b sdnv100c sdnv100h ssna105a ssna105b ssnp152a ssnp152b
ssnp152e ssnp152f ssnp152h ssnp165c ssnp170e ssnp170p ssnp170r ssnp170z ssnp503a ssnp503c ssnp503e ssnp503g
ssnp503i ssnp503k ssnp504a ssnp504c ssnp504e ssnv209a ssnv209f ssnv228a wslp100a"
mkdir -p "$out"
failed=0
for t in $decks; do
  git --git-dir="$ASTEST_GIT" show "HEAD:astest/$t.comm" > "$out/$t.comm" 2>/dev/null || { echo "FAIL: $t.comm is not in the clone"; failed=1; continue; }
  "$exe" convert --check "$out/$t.comm" > "$out/$t.check" 2>&1
  python=$(grep -E "^[^ ]+:[0-9]+: " "$out/$t.check" | sed -E 's/^[^ ]+:[0-9]+: //' |
           grep -vE "^unknown command|^[A-Z_0-9]+: unknown keyword|^[A-Z_0-9]+: reuse is not")
  if [ -n "$python" ]; then echo "FAIL: $t: $python" | head -3; failed=1; else echo "ok   $t"; fi
done
exit $failed
