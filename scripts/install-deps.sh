#!/usr/bin/env bash
# Installs every Debian package lunaster needs to build, test and verify.
# Idempotent: installs only what is missing. Needs root (or sudo) on Debian 12.
set -euo pipefail

PACKAGES=(
  build-essential cmake make pkg-config git
  liblua5.4-dev               # deck interpreter (Lua 5.4 C API, built as C++)
  libeigen3-dev               # dense/sparse linear algebra containers
  libsuitesparse-dev          # CHOLMOD (SPD), UMFPACK (general)
  libmumps-dev                # MUMPS, MPI build: one process or the ranks of mpirun
  libpetsc-real-dev           # PETSc (Krylov solvers, algebraic multigrid: GAMG, hypre BoomerAMG, ML)
  libhypre-dev                # hypre: BoomerAMG's matrix built directly (PETSC, PRE_COND='BOOMER')
  openmpi-bin                 # mpirun, for decks run on several processes
  libscotch-dev               # Scotch: a model's cells shared among the ranks of an MPI run
  libopenblas-pthread-dev     # OpenBLAS: the BLAS/LAPACK under CHOLMOD, UMFPACK and MUMPS
  libmedc-dev libhdf5-openmpi-dev libopenmpi-dev  # MED-file 4.1 (built on the OpenMPI HDF5): meshes, results
  libgtest-dev libgmock-dev   # unit tests
  libbenchmark-dev time       # tests/bench kernels and timings
  python3 python3-numpy python3-h5py python3-meshio  # MED interoperability checks (independent reader/writer)
)

# `install-deps.sh study` (used by `make study` only, never by CI): the speed/accuracy
# study's charts and its peer solver.
if [ "${1:-}" = "study" ]; then
  PACKAGES+=(
    python3-matplotlib          # docs/study charts (SVG, PNG)
    calculix-ccx                # CalculiX, the peer on the same meshes (tests/bench/study)
  )
fi

# Optional: `install-deps.sh fuzz` adds what `make fuzz` needs (clang 14 and its
# runtime libraries, which on Debian 12 include libFuzzer: libclang_rt.fuzzer).
if [ "${1:-}" = "fuzz" ]; then
  PACKAGES+=(clang libclang-rt-14-dev)
fi

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PACKAGES[@]} packages present"
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
