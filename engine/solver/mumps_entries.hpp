#pragma once
/// MUMPS's assembled input, shared by the double-precision backend (mumps_solver.cpp) and
/// the single-precision preconditioner of the PETSc module (LDLT_SP): coordinate entries
/// (1-based) taken from a compressed matrix, and where MUMPS finds them.
#include <mumps_c_types.h>

#include <type_traits>
#include <vector>

#include "engine/solver/linear_solver.hpp"

namespace lunaster::engine {

/// Coordinate entries of A as MUMPS's precision `Real`: every entry, or for a symmetric
/// kind (sym != 0) the upper triangle only. The vectors are replaced.
template <class Real>
void mumps_entries(const SparseMatrix& a, int sym, std::vector<MUMPS_INT>& irn, std::vector<MUMPS_INT>& jcn,
                   std::vector<Real>& val) {
  irn.clear(), jcn.clear(), val.clear();
  irn.reserve(a.nonZeros());
  jcn.reserve(a.nonZeros());
  val.reserve(a.nonZeros());
  for (int c = 0; c < a.outerSize(); ++c)
    for (SparseMatrix::InnerIterator it(a, c); it; ++it) {
      if (sym != 0 && it.row() > c) continue;  // upper triangle only
      irn.push_back(static_cast<MUMPS_INT>(it.row() + 1));
      jcn.push_back(static_cast<MUMPS_INT>(c + 1));
      val.push_back(static_cast<Real>(it.value()));
    }
}

/// Block low-rank factors for the next analysis of a MUMPS instance (DMUMPS_STRUC_C,
/// SMUMPS_STRUC_C), as code_aster sets them with a public MUMPS: ICNTL(35) = 1 (MUMPS's
/// automatic BLR), CNTL(7) = |threshold|, and ICNTL(36) = 1 (UCFS) when the threshold is
/// negative. Nothing when off.
template <class Instance>
void set_low_rank(Instance& id, const LowRank& low_rank) {
  if (!low_rank.on) return;
  using Real = std::remove_reference_t<decltype(id.cntl[0])>;
  id.icntl[34] = 1;
  id.icntl[35] = low_rank.threshold < 0.0 ? 1 : 0;
  id.cntl[6] = static_cast<Real>(low_rank.threshold < 0.0 ? -low_rank.threshold : low_rank.threshold);
}

/// Points a MUMPS instance (DMUMPS_STRUC_C, SMUMPS_STRUC_C) at the entries: the host's
/// centralised arrays, or with `distributed` this rank's own (ICNTL(18) = 3, set by the caller).
template <class Instance, class Real>
void give_mumps_entries(Instance& id, bool distributed, std::vector<MUMPS_INT>& irn, std::vector<MUMPS_INT>& jcn,
                        std::vector<Real>& val) {
  if (distributed) {
    id.nnz_loc = static_cast<MUMPS_INT8>(val.size());
    id.nz_loc = static_cast<MUMPS_INT>(val.size());
    id.irn_loc = irn.data();
    id.jcn_loc = jcn.data();
    id.a_loc = val.data();
  } else {
    id.nnz = static_cast<MUMPS_INT8>(val.size());
    id.nz = static_cast<MUMPS_INT>(val.size());
    id.irn = irn.data();
    id.jcn = jcn.data();
    id.a = val.data();
  }
}

}  // namespace lunaster::engine
