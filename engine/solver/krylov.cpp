#include "engine/solver/krylov.hpp"

#include <cmath>
#include <vector>

#include <Eigen/Dense>

namespace lunaster::engine {

KrylovResult preconditioned_gmres(const SparseMatrix& a, const LinearSolver& preconditioner, const Vector& b,
                                  Vector& x, int max_iterations, double tolerance) {
  return preconditioned_gmres([&a](const Vector& v) -> Vector { return a * v; }, preconditioner, b, x,
                              max_iterations, tolerance);
}

KrylovResult preconditioned_gmres(const MatrixProduct& a, const LinearSolver& preconditioner, const Vector& b,
                                  Vector& x, int max_iterations, double tolerance) {
  KrylovResult result;
  const int n = static_cast<int>(b.size());
  x = Vector::Zero(n);
  const double b_norm = b.norm();
  if (b_norm == 0.0) {
    result.converged = true;
    return result;
  }
  const int m = max_iterations;
  std::vector<Vector> v;  // Arnoldi basis
  v.reserve(m + 1);
  Eigen::MatrixXd h = Eigen::MatrixXd::Zero(m + 1, m);
  Vector cs = Vector::Zero(m), sn = Vector::Zero(m), g = Vector::Zero(m + 1);
  v.push_back(b / b_norm);
  g[0] = b_norm;
  int k = 0;
  for (; k < m; ++k) {
    Vector w = a(preconditioner.solve(v[k]));
    for (int i = 0; i <= k; ++i) {  // modified Gram-Schmidt
      h(i, k) = w.dot(v[i]);
      w -= h(i, k) * v[i];
    }
    h(k + 1, k) = w.norm();
    for (int i = 0; i < k; ++i) {  // previous Givens rotations
      const double t = cs[i] * h(i, k) + sn[i] * h(i + 1, k);
      h(i + 1, k) = -sn[i] * h(i, k) + cs[i] * h(i + 1, k);
      h(i, k) = t;
    }
    const double r = std::hypot(h(k, k), h(k + 1, k));
    cs[k] = r > 0.0 ? h(k, k) / r : 1.0;
    sn[k] = r > 0.0 ? h(k + 1, k) / r : 0.0;
    h(k, k) = r;
    h(k + 1, k) = 0.0;
    g[k + 1] = -sn[k] * g[k];
    g[k] = cs[k] * g[k];
    result.iterations = k + 1;
    if (std::abs(g[k + 1]) <= tolerance * b_norm || !(r > 0.0)) {
      ++k;
      break;
    }
    if (h.rows() > k + 1 && w.norm() > 0.0) v.push_back(w / w.norm());
  }
  // y = H^-1 g on the k x k upper triangle; x = M^-1 V y.
  const Vector y = h.topLeftCorner(k, k).triangularView<Eigen::Upper>().solve(g.head(k));
  Vector z = Vector::Zero(n);
  for (int i = 0; i < k; ++i) z += y[i] * v[i];
  x = preconditioner.solve(z);
  result.residual = (a(x) - b).norm() / b_norm;
  result.converged = std::isfinite(result.residual) && result.residual <= tolerance;
  return result;
}

}  // namespace lunaster::engine
