#pragma once
// A hand Newton loop over assembly's Tangent, for the tests of behaviours: it sees only the
// internal force and the tangent (as a driver does), eliminates the fixed equations (their
// values are set in u by the caller before the loop) and solves with a sparse LU.
#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

#include <Eigen/SparseLU>

#include "engine/assembly/tangent.hpp"
#include "engine/core/linalg.hpp"

namespace lunaster::engine::test {

struct NewtonLog {
  std::vector<double> residuals;  ///< |f_ext - f_int| on the free equations / scale, per iteration
  bool converged = false;
};

/// Newton on one step: the free equations `free` of u from their values at the step's start to
/// equilibrium with `f_ext` (n_dofs), the fixed ones kept as u holds them. Converged when the
/// residual over `scale` (a force of the problem) is below `tolerance`; at most 20 iterations.
inline NewtonLog newton_step(Tangent& tangent, const std::vector<int>& free, const Vector& f_ext, double scale,
                             Vector& u, double tolerance = 1e-12) {
  NewtonLog log;
  const int nf = static_cast<int>(free.size());
  std::vector<int> index(u.size(), -1);
  for (int i = 0; i < nf; ++i) index[free[i]] = i;
  for (int it = 0; it < 20; ++it) {
    SparseMatrix k;
    Vector f_int;
    if (!tangent.assemble(u, &k, &f_int)) return log;
    Vector r(nf);
    for (int i = 0; i < nf; ++i) r(i) = f_ext(free[i]) - f_int(free[i]);
    log.residuals.push_back(r.norm() / scale);
    std::printf("  iteration %d: relative residual %.3e\n", it, log.residuals.back());
    if (log.residuals.back() < tolerance) {
      log.converged = true;
      return log;
    }
    std::vector<Triplet> entries;
    for (int c = 0; c < k.outerSize(); ++c)
      for (SparseMatrix::InnerIterator e(k, c); e; ++e)
        if (index[e.row()] >= 0 && index[c] >= 0) entries.emplace_back(index[e.row()], index[c], e.value());
    SparseMatrix kff(nf, nf);
    kff.setFromTriplets(entries.begin(), entries.end());
    Eigen::SparseLU<SparseMatrix> lu(kff);
    EXPECT_EQ(lu.info(), Eigen::Success);
    const Vector du = lu.solve(r);
    for (int i = 0; i < nf; ++i) u(free[i]) += du(i);
  }
  return log;
}

/// The equations not marked in `fixed` (one flag per equation).
inline std::vector<int> free_equations(const std::vector<char>& fixed) {
  std::vector<int> free;
  for (int i = 0; i < static_cast<int>(fixed.size()); ++i)
    if (!fixed[i]) free.push_back(i);
  return free;
}

}  // namespace lunaster::engine::test
