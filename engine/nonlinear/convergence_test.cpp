#include "engine/nonlinear/convergence_test.hpp"

#include <algorithm>
#include <cmath>

namespace lunaster::engine {

ResidualNorms ConvergenceTest::measure(const Constraints& cons, const Vector& residual, const Vector& f_ext,
                                       const Vector& u, int owned_free, Vector& r_free) const {
  const int n = static_cast<int>(cons.free_index.size());
  const int owned_eqs = layout_.owned_equations(n);
  // Relative residual as code_aster's RESI_GLOB_RELA: free residual over the largest load or reaction.
  double denom = layout_.largest_entry(f_ext, owned_eqs);
  r_free.resize(cons.n_free);
  double reactions = 0.0;
  for (int eq = 0; eq < n; ++eq) {
    const int k = cons.free_index[eq];
    if (k >= 0) r_free[k] = residual[eq];
    else if (eq < owned_eqs) reactions = std::max(reactions, std::abs(residual[eq]));
  }
  reactions = layout_.largest_over_ranks(reactions);
  denom = std::max(denom, reactions);
  ResidualNorms norms;
  norms.absolute = layout_.largest_entry(r_free, owned_free);
  // A load step where loads and reactions vanish (a body moving rigidly before contact closes)
  // has no natural reference: fall back to the size of the terms that make up the internal
  // forces, so that round-off counts as converged.
  Vector displacements = u;  // the multipliers (Pa) left out
  for (int eq = 0; eq < static_cast<int>(displacement_.size()) && eq < displacements.size(); ++eq)
    if (!displacement_[eq]) displacements[eq] = 0.0;
  denom = std::max(denom, 1e-6 * stiffness_scale_ * layout_.largest_entry(displacements, owned_eqs));
  norms.relative = denom > 0.0 ? norms.absolute / denom : norms.absolute;
  return norms;
}

bool ConvergenceTest::converged(const ResidualNorms& norms, int iter, double previous_absolute,
                                bool contact_ok) const {
  // The residual may converge from the second iteration on, and in a pass after the first (a
  // new pairing or new statuses) already at its start.
  const bool may_converge = iter > 0 || previous_absolute >= 0.0;
  const bool rela_ok = options_.resi_glob_rela <= 0.0 || norms.relative <= options_.resi_glob_rela;
  const bool maxi_ok = options_.resi_glob_maxi <= 0.0 || norms.absolute <= options_.resi_glob_maxi;
  // A later pass needs no solve when the new pairing or statuses left the residual where the
  // previous pass converged (at most twice it: e.g. a flat interface translated), or three
  // orders below RESI_GLOB_RELA (an iterative solve's round-off moves a re-pairing by about its
  // tolerance); merely within RESI_GLOB_RELA would accept the looser state a changed pairing
  // leaves, and lose the accuracy Newton had reached.
  const bool unchanged = iter > 0 || norms.absolute <= 2.0 * previous_absolute ||
                         norms.relative <= 1e-3 * options_.resi_glob_rela;
  return may_converge && unchanged && rela_ok && maxi_ok && contact_ok;
}

}  // namespace lunaster::engine
