#include "engine/mesh/transform.hpp"

#include <cmath>

#include "engine/core/error.hpp"

namespace lunaster::engine {

void rotate_mesh(Mesh& mesh, const std::array<double, 3>& point, const std::array<double, 3>& axis, double angle) {
  const double length = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  if (!(length > 0.0) || !std::isfinite(length)) throw InternalError("rotate_mesh: the axis must be a non-zero vector");
  const double k[3] = {axis[0] / length, axis[1] / length, axis[2] / length};
  const double c = std::cos(angle), s = std::sin(angle);
  // R = c I + s [k]x + (1 - c) k k^T
  double r[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r[i][j] = (i == j ? c : 0.0) + (1.0 - c) * k[i] * k[j];
  r[0][1] -= s * k[2]; r[1][0] += s * k[2];
  r[0][2] += s * k[1]; r[2][0] -= s * k[1];
  r[1][2] -= s * k[0]; r[2][1] += s * k[0];
  // About an axis along z the exact matrix keeps z untouched (a 2D mesh stays at z = 0).
  if (k[0] == 0.0 && k[1] == 0.0) { r[0][2] = r[1][2] = r[2][0] = r[2][1] = 0.0; r[2][2] = 1.0; }
  for (int n = 0; n < mesh.n_nodes(); ++n) {
    double* x = &mesh.coords[3 * static_cast<size_t>(n)];
    const double d[3] = {x[0] - point[0], x[1] - point[1], x[2] - point[2]};
    for (int i = 0; i < 3; ++i) x[i] = point[i] + r[i][0] * d[0] + r[i][1] * d[1] + r[i][2] * d[2];
  }
}

}  // namespace lunaster::engine
