#!/bin/bash
# Many single-process runs at once, each starting MPI for PETSc (a verification suite run in
# parallel, a study's sweep, two users on one machine). An MPI singleton of OpenMPI 4 creates its
# session directory under /tmp/ompi.<host>.<uid>/jf.0, the same for every singleton, and removes
# it when it ends: a run starting while another ends could fail in MPI_Init ("A call to mkdir was
# unable to create the desired directory"). About 1 run in 60 failed so on a 2-core machine.
# Usage: concurrent_runs.sh LUNASTER SOURCE_DIR SCRATCH [COPIES]
set -u
lunaster=$1 source=$2 scratch=$3 copies=${4:-96}
rm -rf "$scratch" && mkdir -p "$scratch" || exit 1
cat > "$scratch/deck.lua" <<DECK
DEBUT()
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.3 } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '$source/testcases/meshes/patch_quad4.med' }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'LEFT', DX = 0.0 }, _F{ GROUP_NO = 'BOTTOM', DY = 0.0 },
                                               _F{ GROUP_NO = 'TOP', DY = -0.01 } } }
R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH }, COMPORTEMENT = _F{ RELATION = 'ELAS' },
                   INCREMENT = _F{ LIST_INST = L }, SOLVEUR = _F{ METHODE = 'PETSC' } }
TEST_RESU{ RESU = _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', NOM_CMP = 'DY', TYPE_TEST = 'MIN',
                      GROUP_NO = 'TOP', REFERENCE = 'ANALYTIQUE', VALE_REFE = -0.01, PRECISION = 1.0e-10 } }
FIN()
DECK
for i in $(seq "$copies"); do
  "$lunaster" run "$scratch/deck.lua" --out "$scratch/run$i" > "$scratch/run$i.log" 2>&1 &
done
failed=0
for job in $(jobs -p); do wait "$job" || failed=$((failed + 1)); done
if [ "$failed" -ne 0 ]; then
  echo "$failed of $copies concurrent runs failed; the first one's output:"
  for i in $(seq "$copies"); do
    if ! grep -q "1 check(s) OK, 0 NOOK" "$scratch/run$i.log"; then cat "$scratch/run$i.log"; break; fi
  done
  exit 1
fi
echo "$copies concurrent runs passed"
