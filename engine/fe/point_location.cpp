#include "engine/fe/point_location.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include <Eigen/Dense>

#include "engine/core/error.hpp"
#include "engine/fe/shape.hpp"

namespace lunaster::engine {

namespace {

constexpr double kInside = 1e-10;  // reference units

bool simplex_like(CellType type) {
  return type == CellType::Tria3 || type == CellType::Tria6 || type == CellType::Tetra4 ||
         type == CellType::Tetra10;
}

bool prism(CellType type) { return type == CellType::Penta6 || type == CellType::Penta15; }

/// Clamps the first `n` coordinates into the simplex xi >= 0, sum xi <= 1.
void clamp_simplex(double* xi, int n) {
  double sum = 0.0;
  for (int i = 0; i < n; ++i) sum += (xi[i] = std::max(xi[i], 0.0));
  if (sum > 1.0)
    for (int i = 0; i < n; ++i) xi[i] /= sum;
}

/// x(xi) for a cell of dimension `dim` (x, y for dim 2).
void map_point(CellType type, const double* xyz, const double* xi, double* x) {
  double n[kMaxCellNodes];
  shape_functions(type, xi, n, nullptr);
  const int nn = cell_info(type).n_nodes;
  x[0] = x[1] = x[2] = 0.0;
  for (int a = 0; a < nn; ++a)
    for (int i = 0; i < 3; ++i) x[i] += n[a] * xyz[3 * a + i];
}

}  // namespace

bool reference_coordinates(CellType type, const double* xyz, const double* point, double* xi) {
  const CellInfo& info = cell_info(type);
  const int dim = info.dim;
  LUNASTER_ASSERT(dim == 2 || dim == 3, "reference_coordinates: a face (2D) or volume (3D) cell");
  xi[0] = xi[1] = xi[2] = 0.0;
  for (int a = 0; a < info.n_vertices; ++a) {
    double r[3] = {0, 0, 0};
    reference_node(type, a, r);
    for (int i = 0; i < dim; ++i) xi[i] += r[i] / info.n_vertices;
  }
  double n[kMaxCellNodes], dn[3 * kMaxCellNodes];
  int polish = 0;
  for (int iteration = 0; iteration < 50; ++iteration) {
    shape_functions(type, xi, n, dn);
    Eigen::Matrix3d j = Eigen::Matrix3d::Identity();
    Eigen::Vector3d r = Eigen::Vector3d::Zero();
    for (int i = 0; i < dim; ++i) {
      double x = 0.0;
      for (int k = 0; k < dim; ++k) j(i, k) = 0.0;
      for (int a = 0; a < info.n_nodes; ++a) {
        x += n[a] * xyz[3 * a + i];
        for (int k = 0; k < dim; ++k) j(i, k) += xyz[3 * a + i] * dn[a * dim + k];
      }
      r[i] = point[i] - x;
    }
    const Eigen::FullPivLU<Eigen::Matrix3d> lu(j);
    if (!lu.isInvertible()) return false;
    const Eigen::Vector3d d = lu.solve(r);
    double step = 0.0;
    for (int i = 0; i < dim; ++i) {
      xi[i] += d[i];
      step = std::max(step, std::abs(d[i]));
      if (!std::isfinite(xi[i]) || std::abs(xi[i]) > 1e3) return false;
    }
    // Quadratic convergence: two steps after 1e-10 reach round-off, whose floor in xi grows with
    // the coordinates' size against the cell's (1e-13 on cells of 0.03 m at 0.7 m from the origin).
    if (step < 1e-10 && ++polish == 2) return true;
  }
  return false;
}

bool inside_reference(CellType type, const double* xi, double tolerance) {
  const int dim = cell_info(type).dim;
  if (simplex_like(type) || prism(type)) {
    const int n = prism(type) ? 2 : dim;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
      if (xi[i] < -tolerance) return false;
      sum += xi[i];
    }
    if (sum > 1.0 + tolerance) return false;
    return !prism(type) || std::abs(xi[2]) <= 1.0 + tolerance;
  }
  for (int i = 0; i < dim; ++i)
    if (std::abs(xi[i]) > 1.0 + tolerance) return false;
  return true;
}

void clamp_to_reference(CellType type, double* xi) {
  const int dim = cell_info(type).dim;
  if (simplex_like(type)) return clamp_simplex(xi, dim);
  if (prism(type)) {
    clamp_simplex(xi, 2);
    xi[2] = std::clamp(xi[2], -1.0, 1.0);
    return;
  }
  for (int i = 0; i < dim; ++i) xi[i] = std::clamp(xi[i], -1.0, 1.0);
}

CellLocator::CellLocator(const Mesh& mesh, std::vector<int> cells) : mesh_(mesh), cells_(std::move(cells)) {
  if (cells_.empty()) return;
  boxes_.resize(6 * cells_.size());
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  double size_sum = 0.0;
  for (size_t k = 0; k < cells_.size(); ++k) {
    double* b = &boxes_[6 * k];
    for (int i = 0; i < 3; ++i) b[i] = 1e300, b[3 + i] = -1e300;
    const int c = cells_[k];
    for (int a = 0; a < mesh.cell_n_nodes(c); ++a)
      for (int i = 0; i < 3; ++i) {
        const double x = mesh.node(mesh.cell(c)[a])[i];
        b[i] = std::min(b[i], x), b[3 + i] = std::max(b[3 + i], x);
      }
    double size = 0.0;
    for (int i = 0; i < 3; ++i) size = std::max(size, b[3 + i] - b[i]);
    for (int i = 0; i < 3; ++i) {  // quadratic cells may bulge past their nodes' box
      b[i] -= 0.1 * size, b[3 + i] += 0.1 * size;
      lo[i] = std::min(lo[i], b[i]), hi[i] = std::max(hi[i], b[3 + i]);
    }
    size_sum += size;
  }
  spacing_ = std::max(size_sum / static_cast<double>(cells_.size()), 1e-300);
  // At most about four buckets per cell: a few far-apart cells would otherwise ask for a huge grid.
  for (;;) {
    double buckets = 1.0;
    for (int i = 0; i < 3; ++i) {
      origin_[i] = lo[i];
      n_[i] = std::max(1, static_cast<int>(std::ceil((hi[i] - lo[i]) / spacing_)));
      buckets *= n_[i];
    }
    if (buckets <= 4.0 * static_cast<double>(cells_.size()) + 64.0) break;
    spacing_ *= 1.5;
  }
  for (size_t k = 0; k < cells_.size(); ++k) {
    const double* b = &boxes_[6 * k];
    int from[3], to[3];
    bucket_of(b, from);
    bucket_of(b + 3, to);
    for (int i = from[0]; i <= to[0]; ++i)
      for (int j = from[1]; j <= to[1]; ++j)
        for (int l = from[2]; l <= to[2]; ++l) {
          const int ijk[3] = {i, j, l};
          grid_[key(ijk)].push_back(static_cast<int>(k));
        }
  }
}

std::int64_t CellLocator::key(const int* ijk) const {
  return (static_cast<std::int64_t>(ijk[0]) * n_[1] + ijk[1]) * n_[2] + ijk[2];
}

void CellLocator::bucket_of(const double* point, int* ijk) const {
  for (int i = 0; i < 3; ++i)
    ijk[i] = std::clamp(static_cast<int>(std::floor((point[i] - origin_[i]) / spacing_)), 0, n_[i] - 1);
}

bool CellLocator::try_cell(int k, const double* point, PointLocation& out) const {
  const int c = cells_[k];
  const CellType type = mesh_.cell_types[c];
  const int nn = mesh_.cell_n_nodes(c);
  double xyz[3 * kMaxCellNodes];
  for (int a = 0; a < nn; ++a)
    for (int i = 0; i < 3; ++i) xyz[3 * a + i] = mesh_.node(mesh_.cell(c)[a])[i];
  const int dim = cell_info(type).dim;
  auto distance_to = [&](const double* x) {
    double d2 = 0.0;
    for (int i = 0; i < dim; ++i) d2 += (point[i] - x[i]) * (point[i] - x[i]);
    return std::sqrt(d2);
  };
  double xi[3] = {0, 0, 0};
  out.cell = c;
  if (!reference_coordinates(type, xyz, point, xi)) {
    // Newton gave up (a point hundreds of cells away, or a degenerate cell): the cell's nearest
    // node stands for its nearest point, so that a far point still finds its nearest cell.
    out.inside = false;
    out.distance = 1e300;
    for (int a = 0; a < nn; ++a) {
      const double d = distance_to(&xyz[3 * a]);
      if (d < out.distance) out.distance = d, reference_node(type, a, out.xi);
    }
    return true;
  }
  out.inside = inside_reference(type, xi, kInside);
  if (!out.inside) clamp_to_reference(type, xi);  // inside to 1e-10: xi as found, exact shape values
  double x[3];
  map_point(type, xyz, xi, x);
  out.distance = distance_to(x);
  for (int i = 0; i < 3; ++i) out.xi[i] = xi[i];
  return true;
}

PointLocation CellLocator::locate(const double* point) const {
  PointLocation best;
  if (cells_.empty()) return best;
  const double tie = 1e-12 * spacing_;
  int centre[3];
  bucket_of(point, centre);
  const int max_ring = std::max({n_[0], n_[1], n_[2]});
  std::set<int> seen;
  for (int r = 0; r <= max_ring; ++r) {
    for (int i = centre[0] - r; i <= centre[0] + r; ++i)
      for (int j = centre[1] - r; j <= centre[1] + r; ++j)
        for (int l = centre[2] - r; l <= centre[2] + r; ++l) {
          if (std::max({std::abs(i - centre[0]), std::abs(j - centre[1]), std::abs(l - centre[2])}) != r) continue;
          if (i < 0 || j < 0 || l < 0 || i >= n_[0] || j >= n_[1] || l >= n_[2]) continue;
          const int ijk[3] = {i, j, l};
          auto it = grid_.find(key(ijk));
          if (it == grid_.end()) continue;
          for (int k : it->second) {
            if (!seen.insert(k).second) continue;
            PointLocation p;
            if (!try_cell(k, point, p)) continue;
            bool better = best.cell < 0 || (p.inside && !best.inside);
            if (!better && p.inside == best.inside) {
              better = p.inside ? p.cell < best.cell
                                : p.distance < best.distance - tie ||
                                      (p.distance <= best.distance + tie && p.cell < best.cell);
            }
            if (better) best = p;
          }
        }
    // Rings beyond r hold boxes at least (r - 1) buckets away from the point (its bucket may
    // have been clamped into the grid): none can hold a nearer cell.
    if (best.cell >= 0 && (best.inside || (r - 1) * spacing_ > best.distance)) break;
  }
  if (best.inside) best.distance = 0.0;
  return best;
}

}  // namespace lunaster::engine
