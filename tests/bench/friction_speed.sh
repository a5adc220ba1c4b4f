#!/usr/bin/env bash
# Coulomb friction against the frictionless solve of the same scene: whole runs of `lunaster
# run`, start-up included, timed by /usr/bin/time. Release build required. SSNP121's 2D blocks
# refined K times (12 K x 12 K QUAD4 over 11 K x 11 K, non-matching), CONTINUE (default
# integration), E = 2e11 Pa: pressed by p = 1e6 Pa on CD, then CD dragged by DX in 4 increments,
# without the sides' shear, so that part of the interface sticks and part slips (the run prints
# how many slave nodes slip at the end). The same deck with FROTTEMENT='SANS' (the drag then only
# shears the upper block over a frictionless interface) and with FROTTEMENT='COULOMB' (mu = 0.3).
# Each variant is run R times, alternating, and the median wall time, user CPU and peak RSS are
# printed with the ratio friction / frictionless.
#
# Usage: tests/bench/friction_speed.sh [-r R] [-k K] BINARY
set -euo pipefail
runs=3; k=8
while getopts "r:k:" opt; do case $opt in r) runs=$OPTARG ;; k) k=$OPTARG ;; *) exit 2 ;; esac; done
shift $((OPTIND - 1))
[ $# -eq 1 ] || { echo "usage: $0 [-r R] [-k K] BINARY" >&2; exit 2; }
bin=$(readlink -f "$1"); [ -x "$bin" ] || { echo "$0: not an executable: $1" >&2; exit 2; }
gen="$(dirname "$bin")/lunaster-meshgen"
work=$(mktemp -d); [ -n "${KEEP:-}" ] && echo "work: $work" >&2 || trap 'rm -rf "$work"' EXIT
"$gen" --upper quad4:12 --lower quad4:11 --refine "$k" -o "$work/mesh.med" > /dev/null
deck() {  # $1: name, $2: the friction keywords of DEFI_CONTACT, $3: the zone's
  cat > "$work/$1.lua" <<DECK
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'mesh.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e11, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
FIX = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_MA = 'GH', DX = 0.0, DY = 0.0 } }
PRESS = AFFE_CHAR_MECA{ MODELE = MO, PRES_REP = _F{ GROUP_MA = 'CD', PRES = 1.0e6 } }
PUSH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_MA = 'CD', DX = 1.35e-5 } }
CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'CONTINUE', $2
                     ZONE = _F{ GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', CONTACT_INIT = 'OUI' $3 } }
L = DEFI_LIST_REEL{ VALE = { 0.0, 1.0, 1.25, 1.5, 1.75, 2.0 } }
R1 = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0, 2.0, 1.0 } }
R2 = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 0.0, 2.0, 1.0 } }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, CONTACT = CONT,
                      EXCIT = { _F{ CHARGE = FIX }, _F{ CHARGE = PRESS, FONC_MULT = R1 }, _F{ CHARGE = PUSH, FONC_MULT = R2 } },
                      INCREMENT = _F{ LIST_INST = L } }
T = POST_RELEVE_T{ ACTION = _F{ INTITULE = 'S', RESULTAT = RESU, NOM_CHAM = 'CONT_NOEU', GROUP_NO = 'AB', NOM_CMP = { 'CONT' },
                                OPERATION = 'EXTRACTION', NUME_ORDRE = 5 } }
local n, slip = #T['CONT'], 0
for i = 1, n do if T['CONT'][i] == 2 then slip = slip + 1 end end
print('slave nodes ' .. n .. ', slipping ' .. slip)
FIN()
DECK
}
deck frictionless "" ""
deck friction "FROTTEMENT = 'COULOMB'," ", COULOMB = 0.3"
for v in frictionless friction; do
  (cd "$work" && "$bin" run "$v.lua" > "$v.log" 2>&1) || { echo "$v failed:"; tail -5 "$work/$v.log"; exit 1; }
  grep -o "slave nodes [0-9]*, slipping [0-9]*" "$work/$v.log" | sed "s/^/$v: /"
  echo "$v: $(grep -c 'converged in' "$work/$v.log") steps, $(grep 'converged in' "$work/$v.log" | awk '{s+=$3} END {print s}') Newton iterations"
done
for r in $(seq "$runs"); do
  for v in frictionless friction; do
    (cd "$work" && /usr/bin/time -f "%e %U %M" -o "$v.time.$r" "$bin" run "$v.lua" > /dev/null 2>&1)
  done
done
median() { sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
declare -A wall
for v in frictionless friction; do
  wall[$v]=$(cat "$work/$v.time."* | awk '{print $1}' | median)
  printf '%-13s wall %6.2f s  user %6.2f s  peak RSS %7.1f MB\n' "$v" "${wall[$v]}" \
    "$(cat "$work/$v.time."* | awk '{print $2}' | median)" "$(cat "$work/$v.time."* | awk '{print $3 / 1024}' | median)"
done
awk -v a="${wall[friction]}" -v b="${wall[frictionless]}" 'BEGIN { printf "friction / frictionless (wall): %.2f\n", a / b }'
