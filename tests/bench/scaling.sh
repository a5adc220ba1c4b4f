#!/usr/bin/env bash
# Scaling benchmark (issue: foundation performance): the glued SSNP121 2D geometry at increasing
# refinement, read + assemble + factorise + solve + stresses, timed as whole runs of `lunaster run`
# (start-up included) with peak memory from /usr/bin/time. Release build required.
# Usage: tests/bench/scaling.sh [BUILD_DIR] [N...]   (N = cells per side of each block)
set -euo pipefail
build=${1:-build}; shift || true
sizes=("$@"); [ ${#sizes[@]} -gt 0 ] || sizes=(12 46 92 184 368)
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
printf "%6s %10s %10s %10s %12s\n" N nodes unknowns wall_s peak_MB
for n in "${sizes[@]}"; do
  mesh="$work/glued_$n.med"
  "$root/$build/lunaster-meshgen" --upper "quad4:$n" --lower "quad4:$n" --glued -o "$mesh" >/dev/null
  deck="$work/glued_$n.lua"
  cat > "$deck" <<LUA
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'glued_$n.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 },
                                               _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH },
                   COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L } }
R = CALC_CHAMP{ reuse = R, RESULTAT = R, CONTRAINTE = { 'SIGM_ELNO', 'SIGM_NOEU' } }
TEST_RESU{ RESU = _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = 'SIGM_NOEU', NOM_CMP = 'SIYY', TYPE_TEST = 'MIN',
                      REFERENCE = 'ANALYTIQUE', VALE_REFE = -1.0e5, PRECISION = 1.0e-8 } }
FIN()
LUA
  nodes=$(( (n + 1) * (n + 1) * 2 - (n + 1) ))
  /usr/bin/time -f "%e %M" -o "$work/time" "$root/$build/lunaster" run "$deck" --out "$work/out" -q >/dev/null
  read -r wall kb < "$work/time"
  printf "%6d %10d %10d %10s %12d\n" "$n" "$nodes" $((2 * nodes)) "$wall" $((kb / 1024))
done
