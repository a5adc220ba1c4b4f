#!/usr/bin/env bash
# Contact against the glued elastic solve of the same mesh (the issue "contact costs one
# elastic solve"): whole runs of `lunaster run`, start-up included, timed by /usr/bin/time.
# Release build required. Each case is run R times per binary, binaries alternating
# (A B A B ...), and the median wall time, user/sys CPU, peak RSS, context switches (voluntary
# plus involuntary) and page faults (minor plus major) are printed.
#
# Usage: tests/bench/contact_speed.sh [-r R] [-c CASE,...] BINARY [BINARY2]
#   BINARY2 (e.g. a build of an older commit) is run side by side: ratios are only
#   meaningful between runs taken in one call.
# Cases:
#   glued2d_k16   SSNP121 2D geometry glued, 184 x 184 QUAD4 per block (about the unknowns of cont2d_k16)
#   cont2d_k16    192 x 192 over 176 x 176 QUAD4 in contact, CONTINUE, SIMPSON ORDRE_INT=4, CONTACT_INIT='NON' (SSNP121 A)
#   glued2d_k32 / cont2d_k32   the same with 368 and 384 / 352 cells per side
#   glued2d_c16   cont2d_k16's own mesh glued: AFFE_CHAR_MECA LIAISON_MAIL (AB's nodes follow PLAQUE2's
#                  cells), SOLVEUR ELIM_LAGR='OUI' (SPD, CHOLMOD): the glued solve of the same mesh
#   elas3d        SSNP121 3D geometry, HEXA8 20x20x4 under HEXA20 16x16x4, interface displacement imposed
#   cont3d        the same mesh in contact, CONTINUE, SIMPSON ORDRE_INT=4
#   elas2d_1inst / elas2d_10inst   glued k=16, 1 instant against 10 instants of the same ramp (FONC_MULT:
#                  each instant solves for a new load)
#   mortar2d_k16 / mortar2d_k32    the cont2d meshes with mortar contact (DEFI_CONT, LAGRANGIEN, CONTACT_INIT='OUI')
#   mortar2d_k16_init_non          the same with CONTACT_INIT='NON' (a first solve without contact)
#   mortar3d      the cont3d mesh with mortar contact (CONTACT_INIT='OUI')
#   glued3d       the cont3d mesh glued: AFFE_CHAR_MECA LIAISON_MAIL (SURESC's nodes follow V2's HEXA20
#                  cells), SOLVEUR ELIM_LAGR='OUI' (no multipliers: SPD, CHOLMOD); the two bodies
#                  coupled as contact couples them, where elas3d cuts them apart
#   elas3d_r3 / cont3d_r3   elas3d and cont3d one refinement down (HEXA8 15x15x3 under HEXA20
#                  12x12x3, 8.4e3 free unknowns with contact: below MUMPS's 1e4)
set -euo pipefail
runs=3; cases="glued2d_k16,cont2d_k16,elas3d,glued3d,cont3d"
while getopts "r:c:" opt; do case $opt in r) runs=$OPTARG ;; c) cases=$OPTARG ;; *) exit 2 ;; esac; done
shift $((OPTIND - 1))
[ $# -ge 1 ] || { echo "usage: $0 [-r R] [-c CASE,...] BINARY [BINARY2]" >&2; exit 2; }
bins=(); for b in "$@"; do bins+=("$(readlink -f "$b")"); done
for b in "${bins[@]}"; do [ -x "$b" ] || { echo "$0: not an executable: $b" >&2; exit 2; }; done
root=$(cd "$(dirname "$0")/../.." && pwd)
gen="$(dirname "${bins[0]}")/lunaster-meshgen"
work=$(mktemp -d); [ -n "${KEEP:-}" ] && echo "work: $work" >&2 || trap 'rm -rf "$work"' EXIT

mesh2d() { [ -f "$work/$1.med" ] || "$gen" "${@:2}" -o "$work/$1.med" >/dev/null; }
deck2d() {  # name mesh contact(0/1/mortar/mortar_non/glued) n_instants
  local contact="" excit="EXCIT = _F{ CHARGE = CH, FONC_MULT = F }" glue="" solveur=""
  if [ "$3" = glued ]; then
    glue=",
                   LIAISON_MAIL = _F{ GROUP_MA_MAIT = 'PLAQUE2', GROUP_MA_ESCL = 'AB' }"
    solveur=", SOLVEUR = _F{ ELIM_LAGR = 'OUI' }"
  fi
  if [ "$3" = mortar ] || [ "$3" = mortar_non ]; then
    local init=OUI; [ "$3" = mortar_non ] && init=NON
    contact="CONT = DEFI_CONT{ MODELE = MO, ZONE = _F{ APPARIEMENT = 'MORTAR', GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF',
             ALGO_CONT = 'LAGRANGIEN', CONTACT_INIT = '$init' } }"
    excit="CONTACT = CONT, EXCIT = _F{ CHARGE = CH, FONC_MULT = F }"
  fi
  if [ "$3" = 1 ]; then
    contact="CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'CONTINUE', REAC_GEOM = 'CONTROLE', NB_ITER_GEOM = 2,
  ZONE = _F{ GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', INTEGRATION = 'SIMPSON', ORDRE_INT = 4,
             COEF_CONT = 1000.0, CONTACT_INIT = 'NON' } }"
    excit="CONTACT = CONT, EXCIT = _F{ CHARGE = CH, FONC_MULT = F }"
  fi
  cat > "$work/$1.lua" <<LUA
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '$2.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 },
                                               _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } }$glue }
$contact
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = $4 } }
F = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, $excit,
                   COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L }$solveur }
TEST_RESU{ RESU = _F{ RESULTAT = R, NUME_ORDRE = $4, NOM_CHAM = 'DEPL', GROUP_NO = 'CD', NOM_CMP = 'DY', TYPE_TEST = 'MIN',
                      REFERENCE = 'ANALYTIQUE', VALE_REFE = -0.1, PRECISION = 1.0e-8 } }
FIN()
LUA
}
deck3d() {  # name contact(0/1/mortar/glued) [mesh, default mesh3d]
  local bc="" glue="" contact="" excit="EXCIT = _F{ CHARGE = CH }" mesh=${3:-mesh3d} solveur="" precision=1.0e-6
  if [ "$2" = glued ]; then
    glue=",
                   LIAISON_MAIL = _F{ GROUP_MA_MAIT = 'V2', GROUP_MA_ESCL = 'SURESC' }"
    solveur=", SOLVEUR = _F{ ELIM_LAGR = 'OUI' }"
    precision=2.0e-3  # measured 1.92e-3: ties of nodes to cells, not nested
  elif [ "$2" = mortar ]; then
    contact="CONT = DEFI_CONT{ MODELE = MO, ZONE = _F{ APPARIEMENT = 'MORTAR', GROUP_MA_ESCL = 'SURESC',
             GROUP_MA_MAIT = 'SURMAI', ALGO_CONT = 'LAGRANGIEN', CONTACT_INIT = 'OUI' } }"
    excit="CONTACT = CONT, EXCIT = _F{ CHARGE = CH }"
  elif [ "$2" = 1 ]; then
    contact="CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'CONTINUE',
  ZONE = _F{ GROUP_MA_ESCL = 'SURESC', GROUP_MA_MAIT = 'SURMAI', INTEGRATION = 'SIMPSON', ORDRE_INT = 4,
             CONTACT_INIT = 'INTERPENETRE', COEF_CONT = 1000.0 } }"
    excit="CONTACT = CONT, EXCIT = _F{ CHARGE = CH }"
  else
    bc=", _F{ GROUP_MA = { 'SURESC', 'SURMAI' }, DZ = -0.05 }"
  fi
  cat > "$work/$1.lua" <<LUA
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '$mesh.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'V1', 'V2' }, MATER = MAT } }
CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'ENCAST', DX = 0.0, DY = 0.0, DZ = 0.0 },
                                               _F{ GROUP_NO = 'SURCHA', DX = 0.0, DY = 0.0, DZ = -0.1 }$bc }$glue }
$contact
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, $excit,
                   COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L }$solveur }
TEST_RESU{ RESU = _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', GROUP_NO = 'SURESC', NOM_CMP = 'DZ', TYPE_TEST = 'MIN',
                      REFERENCE = 'ANALYTIQUE', VALE_REFE = -0.05, PRECISION = $precision } }
FIN()
LUA
}

IFS=, read -r -a list <<< "$cases"
for c in "${list[@]}"; do
  case $c in
    glued2d_k16) mesh2d g16 --upper quad4:184 --lower quad4:184 --glued; deck2d "$c" g16 0 1 ;;
    glued2d_k32) mesh2d g32 --upper quad4:368 --lower quad4:368 --glued; deck2d "$c" g32 0 1 ;;
    cont2d_k16) mesh2d c16 --upper quad4:12 --lower quad4:11 --refine 16; deck2d "$c" c16 1 1 ;;
    glued2d_c16) mesh2d c16 --upper quad4:12 --lower quad4:11 --refine 16; deck2d "$c" c16 glued 1 ;;
    cont2d_k32) mesh2d c32 --upper quad4:12 --lower quad4:11 --refine 32; deck2d "$c" c32 1 1 ;;
    elas2d_1inst) mesh2d g16 --upper quad4:184 --lower quad4:184 --glued; deck2d "$c" g16 0 1 ;;
    elas2d_10inst) mesh2d g16 --upper quad4:184 --lower quad4:184 --glued; deck2d "$c" g16 0 10 ;;
    elas3d) mesh2d mesh3d --v1 hexa8:5x5x1 --v2 hexa20:4x4x1 --refine 4; deck3d "$c" 0 ;;
    cont3d) mesh2d mesh3d --v1 hexa8:5x5x1 --v2 hexa20:4x4x1 --refine 4; deck3d "$c" 1 ;;
    mortar2d_k16) mesh2d c16 --upper quad4:12 --lower quad4:11 --refine 16; deck2d "$c" c16 mortar 1 ;;
    mortar2d_k16_init_non) mesh2d c16 --upper quad4:12 --lower quad4:11 --refine 16; deck2d "$c" c16 mortar_non 1 ;;
    mortar2d_k32) mesh2d c32 --upper quad4:12 --lower quad4:11 --refine 32; deck2d "$c" c32 mortar 1 ;;
    mortar3d) mesh2d mesh3d --v1 hexa8:5x5x1 --v2 hexa20:4x4x1 --refine 4; deck3d "$c" mortar ;;
    glued3d) mesh2d mesh3d --v1 hexa8:5x5x1 --v2 hexa20:4x4x1 --refine 4; deck3d "$c" glued ;;
    elas3d_r3) mesh2d mesh3d_r3 --v1 hexa8:5x5x1 --v2 hexa20:4x4x1 --refine 3; deck3d "$c" 0 mesh3d_r3 ;;
    cont3d_r3) mesh2d mesh3d_r3 --v1 hexa8:5x5x1 --v2 hexa20:4x4x1 --refine 3; deck3d "$c" 1 mesh3d_r3 ;;
    *) echo "$0: unknown case $c" >&2; exit 2 ;;
  esac
done

median() { sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
printf "%-14s %-4s %8s %8s %8s %8s %8s %8s  %s\n" case bin wall_s user_s sys_s peak_MB ctxsw faults status
for c in "${list[@]}"; do
  for i in "${!bins[@]}"; do : > "$work/t.$i"; done
  for _ in $(seq "$runs"); do
    for i in "${!bins[@]}"; do
      (cd "$work" && /usr/bin/time -f "%e %U %S %M %w %c %R %F" -o "$work/time" "${bins[$i]}" run "$c.lua" --out "$work/out_$i" -q \
        > "$work/log.$c.$i" 2>&1; echo $? > "$work/rc.$i") || true
      tail -n 1 "$work/time" | awk '{print $1, $2, $3, $4, $5 + $6, $7 + $8}' >> "$work/t.$i"
    done
  done
  for i in "${!bins[@]}"; do
    rc=$(cat "$work/rc.$i"); status=OK; [ "$rc" = 0 ] || status="exit $rc"
    printf "%-14s %-4s %8s %8s %8s %8d %8s %8s  %s\n" "$c" "$((i + 1))" \
      "$(awk '{print $1}' "$work/t.$i" | median)" "$(awk '{print $2}' "$work/t.$i" | median)" \
      "$(awk '{print $3}' "$work/t.$i" | median)" "$(( $(awk '{print $4}' "$work/t.$i" | median) / 1024 ))" \
      "$(awk '{print $5}' "$work/t.$i" | median)" "$(awk '{print $6}' "$work/t.$i" | median)" "$status"
  done
done
