#!/usr/bin/env bash
# A deck on a mesh in parts against the same deck on the shared model (tests/bench/README.md,
# "A deck on a mesh in parts"): a HEXA8 block of N^3 cells (3e6 unknowns for N = 99) clamped on
# BOTTOM, pressed on TOP, CG + BoomerAMG, stresses at the nodes, one TEST_RESU; the mesh read
# with LIRE_MAILLAGE PARTITIONNEUR='PTSCOTCH' (parts) or without it (shared: METHODE='PETSC'
# shares the model among the ranks, every rank holding the whole mesh and fields). The two in
# turn, RUNS times, under mpirun -np NP; each rank's peak from its own /usr/bin/time.
# Usage: tests/bench/parts_deck.sh [BUILD_DIR] [N] [NP] [RUNS]   (Release build; OpenMPI as root
# needs OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1)
set -euo pipefail
build=${1:-build}; n=${2:-99}; np=${3:-2}; runs=${4:-2}
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
"$root/$build/lunaster-meshgen" --block "hexa8:$n" -o "$work/block.med" >/dev/null
dz=-4.894111168e-04; sizz=-4.298346055e+08
for mode in parts shared; do
  partitioner=""; [ "$mode" = parts ] && partitioner=", PARTITIONNEUR = 'PTSCOTCH'"
  cat > "$work/$mode.lua" <<LUA
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'block.med'$partitioner }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e11, NU = 0.3 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_MA = 'BOTTOM', DX = 0.0, DY = 0.0, DZ = 0.0 },
                     PRES_REP = _F{ GROUP_MA = 'TOP', PRES = 1.0e8 } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH }, COMPORTEMENT = _F{ RELATION = 'ELAS' },
                   INCREMENT = _F{ LIST_INST = L },
                   SOLVEUR = _F{ METHODE = 'PETSC', ALGORITHME = 'CG', PRE_COND = 'BOOMER', RESI_RELA = 1.0e-8 } }
R = CALC_CHAMP{ reuse = R, RESULTAT = R, CONTRAINTE = 'SIGM_NOEU' }
TEST_RESU{ RESU = {
  _F{ RESULTAT = R, INST = 1.0, NOM_CHAM = 'DEPL', NOM_CMP = 'DZ', TYPE_TEST = 'MIN', VALE_CALC = $dz },
  _F{ RESULTAT = R, INST = 1.0, NOM_CHAM = 'SIGM_NOEU', NOM_CMP = 'SIZZ', TYPE_TEST = 'MIN', VALE_CALC = $sizz } } }
FIN()
LUA
done
# The VALE_CALC are those of N = 99 (runs of 2026-12-06); other sizes print NOOK with their values.
# A NOOK ends rank 0 with status 1, and mpirun may then end the other ranks before their
# /usr/bin/time writes its peak.
label="N = $n" keep="calc=|check\(s\) OK|mesh in parts on|model shared among"
. "$root/tests/bench/in_turn.sh"
in_turn
