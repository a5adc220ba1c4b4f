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
#include "engine/core/linalg.hpp"

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

/// A component of a unit normal at most this large is round-off and adds no term to a gap
/// or a mortar row: an isoparametric face whose nodes share z has dz/dxi = z sum_a
/// dN_a/dxi, about 1e-16 instead of 0, and the normal's x and y come out at up to 2e-14 on
/// the QUAD8 faces of the CONTINUE 3D benchmark (1e-13 after a solve). Keeping them would
/// make the pattern, and the cost, depend on round-off; a tilt below 1e-10 rad moves a gap
/// by less than 1e-10 of the cell size.
constexpr double kNormalRoundOff = 1e-10;

/// Builds the gap of the point x_s = sum_a ws[a] X(slave[a]) paired with
/// x_m = sum_b wm[b] X(master[b]) along `normal` (reference coordinates in
/// `coords`, 3 per node; displacement DOFs from `dofs`, first `dim` components). Normal
/// components up to kNormalRoundOff count as 0.
/// Nodes without a displacement DOF contribute to g0 only.
LinearGap make_linear_gap(const std::vector<double>& coords, const DofMap& dofs, int dim, const int* slave,
                          const double* ws, int n_slave, const int* master, const double* wm, int n_master,
                          const double* normal);

/// The tangents of a point's frame from its unit normal n (dim - 1 of them, unit, orthogonal
/// to n and to each other): in 2D n turned by +90 degrees; in 3D t1 along the axis least
/// aligned with n (the lower one of two within 1e-6), made orthogonal to n, and t2 = n x t1.
void tangent_frame(const double* normal, int dim, double tangents[2][3]);

/// tangent += factor * a b^T over the DOFs of two gaps (or of one, a = b).
void add_outer(const LinearGap& a, const LinearGap& b, double factor, std::vector<Triplet>& tangent);
/// residual += factor * grad(g).
void add_gradient(const LinearGap& g, double factor, Vector& residual);

/// Dense accumulator for the contact tangent of a group of points sharing their DOFs (the
/// points of one slave cell): their terms are summed here and each entry is emitted once by
/// flush(). One triplet per term would give (points per cell) times as many triplets: with
/// Simpson in 3D (81 points on a cell, 40 DOFs per gap) that was most of the contact time
/// and gigabytes of triplets on large meshes.
class LocalTangent {
 public:
  /// tangent(row, col) += v, equations numbered as in the assembled system.
  void add(int row, int col, double v) { add_at(index(row), index(col), v); }
  /// Local index of an equation (added on first use): add_at with indices looked up once
  /// per point instead of once per entry.
  int index(int eq);
  /// tangent(eqs[i], eqs[j]) += v for local indices from index().
  void add_at(int i, int j, double v) {
    const size_t k = static_cast<size_t>(i) * stride_ + j;
    dense_[k] += v;
    touched_[k] = 1;
  }
  /// tangent += factor * a b^T.
  void add_outer(const LinearGap& a, const LinearGap& b, double factor);
  /// Appends every entry that add/add_outer touched, zeros included (the pattern then
  /// depends on which terms were added, not on their values), and empties the accumulator.
  void flush(std::vector<Triplet>& tangent);

 private:
  std::vector<int> marked_;         ///< equations of the last a a^T added as a pattern only (factor 0)
  std::vector<int> eqs_;            ///< equations of the local rows/columns, in order of arrival
  std::vector<int> pos_;            ///< equation -> local index, -1 when absent (sized on demand)
  std::vector<double> dense_;  ///< stride_ x stride_, row-major
  std::vector<char> touched_;  ///< same layout: entry added to since the last flush
  int stride_ = 0;
};

}  // namespace lunaster::engine::contact
