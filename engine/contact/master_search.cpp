#include "engine/contact/master_search.hpp"

#include <algorithm>
#include <cmath>

#include "engine/contact/surface_element.hpp"
#include "engine/core/error.hpp"

namespace lunaster::engine::contact {

namespace {

double dot3(const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// Newton iterations from `xi`; returns true when the step became negligible.
bool newton_project(CellType type, const double* xyz, const double* point, double* xi) {
  const int nn = surface_n_nodes(type), rdim = surface_ref_dim(type);
  double n[kMaxSurfaceNodes], dn[2 * kMaxSurfaceNodes], d2n[3 * kMaxSurfaceNodes];
  int on_bound = 0;  // consecutive iterations stuck on the |xi| = 3 box: the minimiser is far outside
  for (int it = 0; it < 50; ++it) {
    surface_shape(type, xi, n, dn, d2n);
    double x[3] = {0, 0, 0}, t[2][3] = {{0, 0, 0}, {0, 0, 0}}, h[3][3] = {};
    for (int a = 0; a < nn; ++a)
      for (int i = 0; i < 3; ++i) {
        const double c = xyz[3 * a + i];
        x[i] += n[a] * c, t[0][i] += dn[2 * a] * c, t[1][i] += dn[2 * a + 1] * c;
        for (int m = 0; m < 3; ++m) h[m][i] += d2n[3 * a + m] * c;
      }
    const double r[3] = {x[0] - point[0], x[1] - point[1], x[2] - point[2]};
    double step[2] = {0.0, 0.0};
    if (rdim == 1) {
      double jac = dot3(t[0], t[0]) + dot3(h[0], r);
      if (jac <= 1e-14 * dot3(t[0], t[0])) jac = dot3(t[0], t[0]);  // Gauss-Newton if not convex
      if (!(jac > 0.0)) return false;
      step[0] = -dot3(t[0], r) / jac;
    } else {
      double a11 = dot3(t[0], t[0]) + dot3(h[0], r), a12 = dot3(t[0], t[1]) + dot3(h[1], r);
      double a22 = dot3(t[1], t[1]) + dot3(h[2], r);
      double det = a11 * a22 - a12 * a12;
      if (!(a11 > 0 && det > 1e-14 * a11 * a22)) {  // Gauss-Newton fallback
        a11 = dot3(t[0], t[0]), a12 = dot3(t[0], t[1]), a22 = dot3(t[1], t[1]);
        det = a11 * a22 - a12 * a12;
      }
      if (!(det > 0.0)) return false;
      const double g1 = dot3(t[0], r), g2 = dot3(t[1], r);
      step[0] = -(a22 * g1 - a12 * g2) / det;
      step[1] = -(a11 * g2 - a12 * g1) / det;
    }
    // Damp long steps so that iterates stay near the reference cell.
    const double len = std::sqrt(step[0] * step[0] + step[1] * step[1]);
    if (len > 1.0) step[0] /= len, step[1] /= len;
    xi[0] += step[0], xi[1] += step[1];
    if (!std::isfinite(xi[0]) || !std::isfinite(xi[1])) return false;
    bool clamped = false;
    for (int k = 0; k < 2; ++k)
      if (std::abs(xi[k]) > 3.0) xi[k] = std::clamp(xi[k], -3.0, 3.0), clamped = true;
    on_bound = clamped ? on_bound + 1 : 0;
    if (on_bound >= 3) return false;
    if (len < 1e-13) return true;
  }
  return false;
}

double distance_at(CellType type, const double* xyz, const double* point, const double* xi) {
  const SurfacePoint p = surface_point(type, xyz, xi);
  const double d[3] = {p.x[0] - point[0], p.x[1] - point[1], p.x[2] - point[2]};
  return std::sqrt(dot3(d, d));
}

/// True when x(xi) is affine on the cell: straight-sided triangles and segments,
/// parallelograms, with every mid-side node at the middle of its edge. The distance to a
/// point then has one stationary point in the whole reference plane, so the Newton
/// iteration from the centre needs no other start.
bool affine_geometry(CellType type, const double* xyz) {
  const int nv = surface_n_vertices(type), nn = surface_n_nodes(type);
  double scale = 0.0;
  for (int a = 1; a < nv; ++a)
    for (int i = 0; i < 3; ++i) scale = std::max(scale, std::abs(xyz[3 * a + i] - xyz[i]));
  const double tol = 1e-12 * scale;
  if (nv == 4)  // parallelogram: x1 + x3 = x2 + x4
    for (int i = 0; i < 3; ++i)
      if (std::abs(xyz[i] + xyz[6 + i] - xyz[3 + i] - xyz[9 + i]) > tol) return false;
  const int n_edges = nv == 2 ? 1 : nv;
  for (int e = 0; e < n_edges && nv + e < nn; ++e) {
    const int a = e, b = (e + 1) % nv, m = nv + e;
    for (int i = 0; i < 3; ++i)
      if (std::abs(xyz[3 * m + i] - 0.5 * (xyz[3 * a + i] + xyz[3 * b + i])) > tol) return false;
  }
  return true;
}

}  // namespace

CellProjection project_on_cell(CellType type, const double* xyz, const double* point) {
  CellProjection best;
  double best_score = 1e300;
  const int nn = surface_n_nodes(type);
  // Start at the centre, then at every node: keep the converged result closest to
  // the cell (outside distance first, then distance to the point).
  for (int start = -1; start < nn; ++start) {
    double xi[2] = {0.0, 0.0};
    if (start < 0) {
      if (is_triangle(type)) xi[0] = xi[1] = 1.0 / 3;
    } else {
      surface_reference_node(type, start, xi);
    }
    if (!newton_project(type, xyz, point, xi)) continue;
    const double out = outside_distance(type, xi);
    const double score = out * 1e6 + distance_at(type, xyz, point, xi);
    if (score < best_score) {
      best_score = score;
      best.xi[0] = xi[0], best.xi[1] = xi[1], best.outside = out, best.converged = true;
    }
    // From the centre: inside is unique for the cell types used; more than one reference
    // units outside, a start at a node cannot bring the foot back into the cell; on an
    // affine cell the stationary point is unique wherever it lies.
    if (start < 0 && (out == 0.0 || out > 2.0 || affine_geometry(type, xyz))) break;
  }
  return best;
}

MasterSurface::MasterSurface(const Mesh& mesh, std::vector<int> cells, bool linearise)
    : mesh_(mesh), cells_(std::move(cells)) {
  const double* x0 = mesh.coords.data();
  // Node -> volume cells adjacency for the orientation check (only master nodes).
  std::unordered_map<int, std::vector<int>> node_volumes;
  for (int c : cells_)
    for (int a = 0; a < mesh.cell_n_nodes(c); ++a) node_volumes[mesh.cell(c)[a]];
  int surf_dim = -1;
  for (size_t k = 0; k < cells_.size(); ++k) {
    const CellType t = mesh.cell_types[cells_[k]];
    LUNASTER_ASSERT(is_surface_type(t), "master cell " + mesh.cell_names[cells_[k]] + " is not a surface cell");
    surf_dim = topological_dim(t);
  }
  for (int c = 0; c < mesh.n_cells(); ++c) {
    if (topological_dim(mesh.cell_types[c]) != surf_dim + 1) continue;
    for (int a = 0; a < mesh.cell_n_nodes(c); ++a) {
      auto it = node_volumes.find(mesh.cell(c)[a]);
      if (it != node_volumes.end()) it->second.push_back(c);
    }
  }
  for (size_t k = 0; k < cells_.size(); ++k) {
    const int c = cells_[k];
    const CellType full = mesh.cell_types[c];
    types_.push_back(linearise ? linear_type(full) : full);
    nodes_.emplace_back(mesh.cell(c), mesh.cell(c) + surface_n_nodes(types_.back()));
    local_[c] = static_cast<int>(k);
    // Orientation: a volume cell holding every vertex of the face.
    double sign = 1.0;
    const int nv = surface_n_vertices(full);
    for (int vol : node_volumes[mesh.cell(c)[0]]) {
      if (!mesh.cell_holds(vol, mesh.cell(c), nv)) continue;
      const int* vn = mesh.cell(vol);
      const int vnn = mesh.cell_n_nodes(vol);
      double xyz[3 * kMaxSurfaceNodes], cv[3] = {0, 0, 0};
      for (int a = 0; a < surface_n_nodes(full); ++a)
        for (int i = 0; i < 3; ++i) xyz[3 * a + i] = x0[3 * mesh.cell(c)[a] + i];
      for (int a = 0; a < vnn; ++a)
        for (int i = 0; i < 3; ++i) cv[i] += x0[3 * vn[a] + i] / vnn;
      const double centre[2] = {is_triangle(full) ? 1.0 / 3 : 0.0, is_triangle(full) ? 1.0 / 3 : 0.0};
      const SurfacePoint p = surface_point(full, xyz, centre);
      const double d[3] = {p.x[0] - cv[0], p.x[1] - cv[1], p.x[2] - cv[2]};
      if (dot3(d, p.n) < 0.0) sign = -1.0, ++n_flipped_;
      break;
    }
    sign_.push_back(sign);
  }
}

int MasterSurface::local_index(int cell) const {
  auto it = local_.find(cell);
  return it == local_.end() ? -1 : it->second;
}

void MasterSurface::gather(const double* xyz, int k, double* out) const {
  const auto& nodes = nodes_[k];
  for (size_t a = 0; a < nodes.size(); ++a)
    for (int i = 0; i < 3; ++i) out[3 * a + i] = xyz[3 * static_cast<size_t>(nodes[a]) + i];
}

std::int64_t MasterSurface::key(int i, int j, int l) const {
  return (static_cast<std::int64_t>(l) * n_grid_[1] + j) * n_grid_[0] + i;
}

void MasterSurface::update(const std::vector<double>& xyz) {
  xyz_ = &xyz;
  grid_.clear();
  if (cells_.empty()) return;
  std::vector<double>& box = boxes_;
  box.assign(6 * cells_.size(), 0.0);
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300}, size_sum = 0.0;
  for (size_t k = 0; k < cells_.size(); ++k) {
    double* b = &box[6 * k];
    for (int i = 0; i < 3; ++i) b[i] = 1e300, b[3 + i] = -1e300;
    for (int node : nodes_[k])
      for (int i = 0; i < 3; ++i) {
        b[i] = std::min(b[i], xyz[3 * static_cast<size_t>(node) + i]);
        b[3 + i] = std::max(b[3 + i], xyz[3 * static_cast<size_t>(node) + i]);
      }
    double ext = 0.0;
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], b[i]), hi[i] = std::max(hi[i], b[3 + i]);
      ext = std::max(ext, b[3 + i] - b[i]);
    }
    size_sum += ext;
    // A curved quadratic cell may bulge out of its nodes' box. With d_e the offset of edge e's
    // mid-side node from the middle of its vertices, x(xi) = x_linear(xi) + sum_e N_e(xi) d_e,
    // where x_linear is the (bi)linear interpolation of the vertices and the mid-side functions
    // N_e are non-negative on the cell with a sum of at most 1 (SEG3), 4/3 (TRIA6) or 2 (QUAD8):
    // widening each coordinate by 2 max_e |d_e| bounds the bulge. A flat cell keeps its tight box,
    // so a point is only projected on the cells it is near.
    const int nv = surface_n_vertices(types_[k]), nn = surface_n_nodes(types_[k]);
    const auto& nodes = nodes_[k];
    double bulge[3] = {0.0, 0.0, 0.0};
    for (int m = nv; m < nn; ++m) {
      const size_t a = nodes[m - nv], c = nodes[(m - nv + 1) % nv], mid_node = nodes[m];
      for (int i = 0; i < 3; ++i)
        bulge[i] = std::max(bulge[i], 2.0 * std::abs(xyz[3 * mid_node + i] - 0.5 * (xyz[3 * a + i] + xyz[3 * c + i])));
    }
    for (int i = 0; i < 3; ++i) b[i] -= bulge[i], b[3 + i] += bulge[i];
  }
  spacing_ = std::max(size_sum / cells_.size(), 1e-12);
  for (int i = 0; i < 3; ++i) {
    origin_[i] = lo[i];
    n_grid_[i] = std::min(1 + static_cast<int>((hi[i] - lo[i]) / spacing_), 1 << 20);
  }
  auto bucket = [&](double v, int i) {
    return std::clamp(static_cast<int>(std::floor((v - origin_[i]) / spacing_)), 0, n_grid_[i] - 1);
  };
  for (size_t k = 0; k < cells_.size(); ++k) {
    const double* b = &box[6 * k];
    int lo_b[3], hi_b[3];
    for (int i = 0; i < 3; ++i) lo_b[i] = bucket(b[i], i), hi_b[i] = bucket(b[3 + i], i);
    for (int l = lo_b[2]; l <= hi_b[2]; ++l)
      for (int j = lo_b[1]; j <= hi_b[1]; ++j)
        for (int i = lo_b[0]; i <= hi_b[0]; ++i) grid_[key(i, j, l)].push_back(static_cast<int>(k));
  }
}

std::vector<int> MasterSurface::candidates(const double* point) const {
  // Rings of buckets around the point's bucket until cells are found, plus one
  // more ring (a closer cell may sit in the next ring).
  int centre[3];
  for (int i = 0; i < 3; ++i)
    centre[i] = std::clamp(static_cast<int>(std::floor((point[i] - origin_[i]) / spacing_)), 0, n_grid_[i] - 1);
  std::vector<int> out;
  const int max_ring = std::max({n_grid_[0], n_grid_[1], n_grid_[2]});
  int found_ring = -1;
  for (int r = 0; r <= max_ring; ++r) {
    for (int l = std::max(0, centre[2] - r); l <= std::min(n_grid_[2] - 1, centre[2] + r); ++l)
      for (int j = std::max(0, centre[1] - r); j <= std::min(n_grid_[1] - 1, centre[1] + r); ++j)
        for (int i = std::max(0, centre[0] - r); i <= std::min(n_grid_[0] - 1, centre[0] + r); ++i) {
          if (std::max({std::abs(i - centre[0]), std::abs(j - centre[1]), std::abs(l - centre[2])}) != r) continue;
          auto it = grid_.find(key(i, j, l));
          if (it == grid_.end()) continue;
          out.insert(out.end(), it->second.begin(), it->second.end());
        }
    if (!out.empty() && found_ring < 0) found_ring = r;
    if (found_ring >= 0 && r >= found_ring + 1) break;
  }
  // A cell spanning several buckets is listed once per bucket: `project` drops the repeats
  // after its sort (marks kept in the surface would stop threads projecting at once).
  return out;
}

MasterProjection MasterSurface::project(const double* point, double tolerance) const {
  LUNASTER_ASSERT(xyz_ != nullptr, "MasterSurface::update must be called before project");
  MasterProjection best;
  double xyz[3 * kMaxSurfaceNodes];
  // Candidates by increasing distance to their box: a cell whose box is farther than the
  // best projection found so far cannot hold a closer point (boxes contain the cells).
  std::vector<std::pair<double, int>> order;
  for (int k : candidates(point)) {
    const double* b = &boxes_[6 * static_cast<size_t>(k)];
    double d2 = 0.0;
    for (int i = 0; i < 3; ++i) {
      const double d = std::max({b[i] - point[i], 0.0, point[i] - b[3 + i]});
      d2 += d * d;
    }
    order.emplace_back(std::sqrt(d2), k);
  }
  std::sort(order.begin(), order.end());
  order.erase(std::unique(order.begin(), order.end()), order.end());
  // Ties (a point on a node or edge shared by several master cells) are decided
  // geometrically, not by round-off: within `tie` of the best distance, an inside
  // projection beats a clamped one, then the lowest mesh cell index wins. The
  // pairing is then reproducible even where the cells' normals differ (kinks).
  const double tie = 1e-10 * spacing_;
  // "Inside" within 1e-8 of the reference cell: a slave node over a master node, displaced by
  // the round-off of a solve, is inside both neighbouring cells (with 1e-12 the sign of that
  // round-off chose the cell, and two solve paths of one deck paired it differently).
  constexpr double kInsideTie = 1e-8;
  for (const auto& [box_distance, k] : order) {
    if (best.found && box_distance > best.distance + tie) break;
    gather(xyz_->data(), k, xyz);
    const CellProjection cp = project_on_cell(types_[k], xyz, point);
    if (!cp.converged || cp.outside > tolerance) continue;
    double xi[2] = {cp.xi[0], cp.xi[1]};
    clamp_to_cell(types_[k], xi);
    const SurfacePoint p = surface_point(types_[k], xyz, xi);
    if (p.jacobian <= 0.0) continue;
    const double d[3] = {point[0] - p.x[0], point[1] - p.x[1], point[2] - p.x[2]};
    const double dist = std::sqrt(dot3(d, d));
    bool better = !best.found || dist < best.distance - tie;
    if (!better && dist <= best.distance + tie) {
      const bool inside = cp.outside <= kInsideTie, best_inside = best.outside <= kInsideTie;
      better = inside != best_inside ? inside
                                     : (inside ? cells_[k] < best.cell
                                               : cp.outside < best.outside - kInsideTie ||
                                                     (cp.outside <= best.outside + kInsideTie && cells_[k] < best.cell));
    }
    if (better) {
      best.found = true, best.cell = cells_[k], best.distance = dist, best.outside = cp.outside;
      best.xi[0] = xi[0], best.xi[1] = xi[1];
      for (int i = 0; i < 3; ++i) best.x[i] = p.x[i], best.normal[i] = sign_[k] * p.n[i];
    }
  }
  return best;
}

}  // namespace lunaster::engine::contact
