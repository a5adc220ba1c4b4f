#!/usr/bin/env bash
# Contact on a mesh in parts against the same deck on the shared model (tests/bench/README.md,
# "Contact on a mesh in parts"): tests/bench/ssnp121i_refined_mortar.lua (mortar LAGRANGIEN, V1
# HEXA8 under V2 HEXA20, about 3.2e5 unknowns for REFINE = 10) solved by CG + BoomerAMG to 1e-12,
# its mesh read with LIRE_MAILLAGE PARTITIONNEUR='PTSCOTCH' (parts: each rank its part and the
# contact surfaces whole) or without it (shared: METHODE='PETSC' shares the model among the ranks,
# every rank holding the whole mesh and fields), and beside them the glued elastic solve of the same
# mesh in parts (glued: tests/bench/ssnp121i_refined_glued.lua, LIAISON_MAIL with ELIM_LAGR = 'OUI',
# the same solver). The three in turn, RUNS times, under mpirun -np NP; each rank's peak from its
# own /usr/bin/time. The decks check the analytical values (mortar at 1e-8; the tie at 5e-3, what a
# node-to-cell tie reaches on this non-matching interface).
# Usage: tests/bench/contact_parts.sh [BUILD_DIR] [REFINE] [NP] [RUNS]   (Release build; OpenMPI as
# root needs OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1)
set -euo pipefail
build=${1:-build}; refine=${2:-10}; np=${3:-2}; runs=${4:-3}
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
"$root/$build/lunaster-meshgen" --v1 hexa8:5x5x1 --v2 hexa20:4x4x1 --refine "$refine" \
  -o "$work/ssnp121i_refined.med" >/dev/null
solveur="METHODE = 'PETSC', ALGORITHME = 'CG', PRE_COND = 'BOOMER', RESI_RELA = 1.0e-12"
in_parts="FICHIER = 'ssnp121i_refined.med', PARTITIONNEUR = 'PTSCOTCH' }"
for mode in parts shared; do
  partitioner="FICHIER = 'ssnp121i_refined.med' }"; [ "$mode" = parts ] && partitioner=$in_parts
  sed -e "s/FICHIER = 'ssnp121i_refined.med' }/$partitioner/" \
      -e "s/INCREMENT = _F{ LIST_INST = L_INST } }/INCREMENT = _F{ LIST_INST = L_INST }, SOLVEUR = _F{ $solveur } }/" \
      "$root/tests/bench/ssnp121i_refined_mortar.lua" > "$work/$mode.lua"
done
sed -e "s/FICHIER = 'ssnp121i_refined.med' }/$in_parts/" \
    -e "s/SOLVEUR = _F{ ELIM_LAGR = 'OUI' } }/SOLVEUR = _F{ $solveur, ELIM_LAGR = 'OUI' } }/" \
    "$root/tests/bench/ssnp121i_refined_glued.lua" > "$work/glued.lua"
for mode in parts shared glued; do
  grep -q "METHODE = 'PETSC'" "$work/$mode.lua" ||
    { echo "the $mode deck's STAT_NON_LINE changed: update $0" >&2; exit 2; }
done
grep -q PARTITIONNEUR "$work/glued.lua" || { echo "the glued deck's LIRE_MAILLAGE changed: update $0" >&2; exit 2; }
modes="parts shared glued"
label="refine $refine" keep="check\(s\) OK|mesh in parts on|model shared among|linear solve|linear relation"
. "$root/tests/bench/in_turn.sh"
in_turn
