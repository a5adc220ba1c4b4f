#!/usr/bin/env bash
# Direct against iterative solvers on a 3D elastic block: the unit cube of N^3 HEXA8 (3 (N+1)^3
# unknowns), clamped at the bottom, pressed by a uniform pressure on the top (NU = 0: a uniaxial
# state, DZ = -p/E at the top, checked to 1e-6). Each run is a whole `lunaster run` (mesh reading,
# assembly, solve, start-up included) timed by /usr/bin/time: wall seconds, and the peak memory of
# each rank (each rank under its own /usr/bin/time): the largest and their sum.
# Usage: tests/bench/solver_scaling.sh [-n RANKS] [BUILD_DIR] SOLVER:N...   (BUILD_DIR: default build)
#   SOLVER: MUMPS | CHOLMOD | GAMG (PETSc CG + GAMG) | BOOMER (PETSc CG + BoomerAMG) | LDLT_SP
#   -n RANKS: run under `mpirun -np RANKS` (each rank its share of the PETSc matrix / MUMPS work).
# Example: tests/bench/solver_scaling.sh build MUMPS:30 GAMG:30 GAMG:99
set -euo pipefail
ranks=1
if [ "${1:-}" = "-n" ]; then ranks=$2; shift 2; fi
build=${1:-build}; shift || true
root=$(cd "$(dirname "$0")/../.." && pwd)
case $build in /*) bin=$build ;; *) bin=$root/$build ;; esac  # BUILD_DIR: relative to the checkout, or absolute
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
launch=()
if [ "$ranks" -gt 1 ]; then
  export OMPI_ALLOW_RUN_AS_ROOT=${OMPI_ALLOW_RUN_AS_ROOT:-1} OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=${OMPI_ALLOW_RUN_AS_ROOT_CONFIRM:-1}
  export OMPI_MCA_pml=${OMPI_MCA_pml:-ob1} OMPI_MCA_btl=${OMPI_MCA_btl:-self,vader}
  launch=(mpirun -np "$ranks")
fi
printf "%-8s %5s %6s %10s %9s %9s %9s %10s %10s\n" solver ranks N unknowns wall_s peak_MB total_MB us/unknown B/unknown
for run in "$@"; do
  solver=${run%%:*}; n=${run##*:}
  mesh="$work/block_$n.med"
  [ -f "$mesh" ] || "$bin/lunaster-meshgen" --block "hexa8:$n" -o "$mesh" >/dev/null
  case $solver in
    MUMPS|CHOLMOD) solveur="_F{ METHODE = '$solver' }" ;;
    GAMG|BOOMER|ML) solveur="_F{ METHODE = 'PETSC', ALGORITHME = 'CG', PRE_COND = '$solver', RESI_RELA = 1.0e-8 }" ;;
    LDLT_SP) solveur="_F{ METHODE = 'PETSC', ALGORITHME = 'FGMRES', PRE_COND = 'LDLT_SP', RESI_RELA = 1.0e-8 }" ;;
    *) echo "unknown solver $solver" >&2; exit 2 ;;
  esac
  deck="$work/block_${solver}_$n.lua"
  cat > "$deck" <<LUA
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'block_$n.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e11, NU = 0.0 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_MA = 'BOTTOM', DX = 0.0, DY = 0.0, DZ = 0.0 },
                     PRES_REP = _F{ GROUP_MA = 'TOP', PRES = 1.0e8 } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH }, SOLVEUR = $solveur,
                   COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L } }
TEST_RESU{ RESU = _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', NOM_CMP = 'DZ', GROUP_NO = 'C111',
                      REFERENCE = 'ANALYTIQUE', VALE_REFE = -5.0e-4, PRECISION = 1.0e-6 } }
FIN()
LUA
  unknowns=$(( 3 * (n + 1) * (n + 1) * (n + 1) ))
  # Each rank's peak memory from its own /usr/bin/time (OpenMPI numbers the ranks in
  # OMPI_COMM_WORLD_RANK); the wall time is the whole run's.
  rm -f "$work"/peak.*
  ranked=(sh -c '/usr/bin/time -f "%M" -o "$0/peak.${OMPI_COMM_WORLD_RANK:-0}" "$@"' "$work")
  if ! /usr/bin/time -f "%e" -o "$work/time" "${launch[@]}" "${ranked[@]}" "$bin/lunaster" run "$deck" \
       --out "$work/out" -q > "$work/log" 2>&1; then
    echo "$solver N=$n failed:"; tail -5 "$work/log"; continue
  fi
  read -r wall < "$work/time"
  # peak_MB: the largest rank's; total_MB: all ranks' together; B/unknown from the total.
  cat "$work"/peak.* | awk -v s="$solver" -v r="$ranks" -v n="$n" -v u="$unknowns" -v w="$wall" \
    '{ kb = $NF + 0; total += kb; if (kb > peak) peak = kb }
     END { printf "%-8s %5d %6d %10d %9.2f %9d %9d %10.2f %10.0f\n", s, r, n, u, w, peak / 1024, total / 1024,
           1e6 * w / u, 1024 * total / u }'
done
