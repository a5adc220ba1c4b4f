#pragma once
/// Normal gap of one contact point with its pairing frozen (projection
/// coordinates and normal fixed between two pairings, as code_aster's
/// fixed-point geometry loop): g(u) = g0 + sum_i c_i u_i, exact in u, so the
/// contact residual is linear at fixed statuses and its tangent is exact.
///
/// Sign convention (used by all lunaster contact code): g > 0 open,
/// g < 0 penetration; g = (x_slave - x_master) . n with n the outward normal
/// of the master body.
#include <array>
#include <vector>

#include "engine/assembly/dof_map.hpp"
#include "engine/solver/linear_solver.hpp"

namespace lunaster::engine::contact {

/// Linearised gap: value and gradient with respect to the displacement DOFs.
struct LinearGap {
  static constexpr int kMaxTerms = 2 * 8 * 3;
  int n = 0;
  std::array<int, kMaxTerms> eq{};
  std::array<double, kMaxTerms> coef{};
  double g0 = 0.0;  ///< gap for u = 0 (reference coordinates), m

  /// g(u) in metres.
  double value(const Vector& u) const {
    double g = g0;
    for (int k = 0; k < n; ++k) g += coef[k] * u[eq[k]];
    return g;
  }
};

/// Builds the gap of the point x_s = sum_a ws[a] X(slave[a]) paired with
/// x_m = sum_b wm[b] X(master[b]) along `normal` (reference coordinates in
/// `coords`, 3 per node; displacement DOFs from `dofs`, first `dim` components).
/// Nodes without a displacement DOF contribute to g0 only.
LinearGap make_linear_gap(const std::vector<double>& coords, const DofMap& dofs, int dim, const int* slave,
                          const double* ws, int n_slave, const int* master, const double* wm, int n_master,
                          const double* normal);

/// tangent += factor * a b^T over the DOFs of two gaps (or of one, a = b).
void add_outer(const LinearGap& a, const LinearGap& b, double factor, std::vector<Triplet>& tangent);
/// residual += factor * grad(g).
void add_gradient(const LinearGap& g, double factor, Vector& residual);

}  // namespace lunaster::engine::contact
