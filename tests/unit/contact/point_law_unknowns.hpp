#pragma once
// A point law's local unknowns for the unit tests of point laws (point_law.hpp): unknown i is
// q_0..q_{n_q-1}, then z_0..; the residual row and the tangent entry of each.
#include "engine/contact/point_law.hpp"

namespace lunaster::engine::contact::point_law_unknowns {

/// Moves unknown i by h; perturbing q moves dq_step alike (the step's start is fixed).
inline void perturb(PointKinematics& in, int n_q, int i, double h) {
  if (i < n_q) {
    in.q[i] += h;
    in.dq_step[i] += h;
  } else {
    in.z[i - n_q] += h;
  }
}

inline double residual(const PointResponse& r, int n_q, int row) { return row < n_q ? r.r_q[row] : r.r_z[row - n_q]; }

inline double tangent(const PointResponse& r, int n_q, int row, int col) {
  if (row < n_q) return col < n_q ? r.k_qq[row][col] : r.k_qz[row][col - n_q];
  return col < n_q ? r.k_zq[row - n_q][col] : r.k_zz[row - n_q][col - n_q];
}

}  // namespace lunaster::engine::contact::point_law_unknowns
