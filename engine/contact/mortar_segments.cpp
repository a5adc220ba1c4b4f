#include "engine/contact/mortar_segments.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <unordered_map>

#include "engine/contact/contact_common.hpp"
#include "engine/contact/integration_rules.hpp"
#include "engine/contact/linear_gap.hpp"
#include "engine/contact/mortar_integration.hpp"
#include "engine/contact/surface_element.hpp"
#include "engine/core/error.hpp"
#include "engine/parallel/mpi_runtime.hpp"

namespace lunaster::engine::contact {

using namespace mortar;

namespace {

/// Polynomial degree of a surface type's shape functions (QUAD8 holds xi^2 eta).
int shape_degree(CellType t) {
  switch (t) {
    case CellType::Seg2: case CellType::Tria3: return 1;
    case CellType::Seg3: case CellType::Tria6: case CellType::Quad4: return 2;
    default: return 3;
  }
}

/// Node order of a surface cell with its orientation reversed (normal flipped).
void reversed_order(CellType t, int* perm) {
  static const int seg2[] = {1, 0}, seg3[] = {1, 0, 2}, tria3[] = {0, 2, 1}, tria6[] = {0, 2, 1, 5, 4, 3},
                   quad4[] = {0, 3, 2, 1}, quad8[] = {0, 3, 2, 1, 7, 6, 5, 4};
  const int* p = seg2;
  switch (t) {
    case CellType::Seg2: p = seg2; break;
    case CellType::Seg3: p = seg3; break;
    case CellType::Tria3: p = tria3; break;
    case CellType::Tria6: p = tria6; break;
    case CellType::Quad4: p = quad4; break;
    default: p = quad8; break;
  }
  std::copy(p, p + surface_n_nodes(t), perm);
}

}  // namespace

std::string zone_label(const ContactZone& zone, int z) {
  std::string label = "contact zone " + std::to_string(z + 1);
  if (!zone.slave_group.empty() || !zone.master_group.empty())
    label += " (slave '" + zone.slave_group + "', master '" + zone.master_group + "')";
  return label;
}

namespace {

/// Orients the cells of a contact surface outwards, from the volume cell each one bounds.
std::vector<OrientedCell> orient_surface(const Mesh& mesh, int dim, const std::vector<int>& cells,
                                         const std::vector<std::vector<int>>& volumes_of_node,
                                         const std::string& zone, const char* role) {
  std::vector<OrientedCell> out;
  out.reserve(cells.size());
  for (int c : cells) {
    OrientedCell oc;
    oc.cell = c;
    oc.type = mesh.cell_types[c];
    if (!is_surface_type(oc.type) || topological_dim(oc.type) != dim - 1)
      throw DeckError(zone + ": " + role + " cell " + cell_label(mesh, c) + " is a " + surface_type_name(oc.type) +
                      ", expected a boundary cell of dimension " + std::to_string(dim - 1));
    oc.n = surface_n_nodes(oc.type);
    const int* nodes = mesh.cell(c);
    const int nv = surface_n_vertices(oc.type);
    // Volume cells holding every vertex of the face.
    int owner = -1, n_owners = 0;
    for (int v : volumes_of_node[nodes[0]])
      if (mesh.cell_holds(v, nodes + 1, nv - 1)) owner = v, ++n_owners;
    if (n_owners != 1)
      throw DeckError(zone + ": " + role + " cell " + cell_label(mesh, c) +
                      (n_owners == 0 ? " bounds no cell of the model" : " lies between two cells of the model") +
                      ": a " + role + " surface must be a boundary of the model (check the group and the model's "
                      "cells)");
    double centre[3] = {0, 0, 0}, face[3] = {0, 0, 0}, xyz[3 * kMaxSurfaceNodes];
    const int nn = mesh.cell_n_nodes(owner);
    for (int a = 0; a < nn; ++a)
      for (int k = 0; k < 3; ++k) centre[k] += mesh.node(mesh.cell(owner)[a])[k] / nn;
    for (int a = 0; a < oc.n; ++a)
      for (int k = 0; k < 3; ++k) xyz[3 * a + k] = mesh.node(nodes[a])[k];
    for (int a = 0; a < nv; ++a)
      for (int k = 0; k < 3; ++k) face[k] += xyz[3 * a + k] / nv;
    double xi[2] = {0.0, 0.0};
    if (is_triangle(oc.type)) xi[0] = xi[1] = 1.0 / 3.0;
    const SurfacePoint sp = surface_point(oc.type, xyz, xi);
    double dot = 0.0;
    for (int k = 0; k < 3; ++k) dot += sp.n[k] * (face[k] - centre[k]);
    if (dot >= 0.0) {
      std::copy(nodes, nodes + oc.n, oc.nodes);
    } else {
      int perm[kMaxSurfaceNodes];
      reversed_order(oc.type, perm);
      for (int a = 0; a < oc.n; ++a) oc.nodes[a] = nodes[perm[a]];
    }
    out.push_back(oc);
  }
  return out;
}

/// Radius (x) of a point of a slave cell, for the AXIS measure r dl; 0 on the axis and,
/// should a deformed cell cross it, beyond (no negative measure).
double axis_radius(CellType type, const double* xyz, const double* xi) {
  return std::max(surface_point(type, xyz, xi).x[0], 0.0);
}

}  // namespace

MortarSegments::MortarSegments(const ContactDefinition& definition, const Mesh& mesh, int dim)
    : mesh_(mesh), dim_(dim), axisymmetric_(definition.axisymmetric), zones_(definition.zones) {
  LUNASTER_ASSERT(dim == 2 || dim == 3, "contact: dimension must be 2 or 3");
  // The volume cells around the nodes of the contact surfaces alone (the whole mesh's lists
  // took 1.8 % of the samples of the 2D k = 16 mortar benchmark, these 0.3 %).
  std::vector<char> on_surface(mesh.n_nodes(), 0);
  for (const ContactZone& zone : zones_)
    for (const auto* cells : {&zone.slave_cells, &zone.master_cells})
      for (int c : *cells)
        for (int a = 0; a < mesh.cell_n_nodes(c); ++a) on_surface[mesh.cell(c)[a]] = 1;
  std::vector<std::vector<int>> volumes_of_node(mesh.n_nodes());
  for (int c = 0; c < mesh.n_cells(); ++c)
    if (topological_dim(mesh.cell_types[c]) == dim)
      for (int a = 0; a < mesh.cell_n_nodes(c); ++a)
        if (on_surface[mesh.cell(c)[a]]) volumes_of_node[mesh.cell(c)[a]].push_back(c);
  std::vector<int> zone_of_slave(mesh.n_nodes(), -1);
  for (size_t z = 0; z < zones_.size(); ++z) {
    const ContactZone& zone = zones_[z];
    const std::string label = zone_label(zone, static_cast<int>(z));
    slave_cells_.push_back(orient_surface(mesh, dim, zone.slave_cells, volumes_of_node, label, "slave"));
    master_cells_.push_back(orient_surface(mesh, dim, zone.master_cells, volumes_of_node, label, "master"));
    for (const auto& oc : slave_cells_.back())
      for (int a = 0; a < oc.n; ++a) {
        int& owner = zone_of_slave[oc.nodes[a]];
        if (owner >= 0 && owner != static_cast<int>(z))
          throw DeckError("slave node " + node_label(mesh, oc.nodes[a]) + " belongs to contact zones " +
                          std::to_string(owner + 1) + " and " + std::to_string(z + 1) +
                          ": a slave node carries one mortar condition; give the zones disjoint slave surfaces");
        owner = static_cast<int>(z);
      }
    for (const auto& oc : slave_cells_.back())
      if (transformed_slave(oc.type))
        for (int a = surface_n_vertices(oc.type); a < oc.n; ++a) {
          int v1, v2;
          // An edge shared by two cells is listed once (its vertices in a fixed order).
          if (edge_vertices(oc.type, a, &v1, &v2))
            mid_edges_.push_back(
                {oc.nodes[a], std::min(oc.nodes[v1], oc.nodes[v2]), std::max(oc.nodes[v1], oc.nodes[v2])});
        }
    h_.push_back(contact::smallest_edge(mesh, zone.slave_cells));
    for (const auto* group : {&slave_cells_.back(), &master_cells_.back()})
      for (const auto& oc : *group) geometry_nodes_.insert(geometry_nodes_.end(), oc.nodes, oc.nodes + oc.n);
  }
  std::sort(geometry_nodes_.begin(), geometry_nodes_.end());
  geometry_nodes_.erase(std::unique(geometry_nodes_.begin(), geometry_nodes_.end()), geometry_nodes_.end());
  std::sort(mid_edges_.begin(), mid_edges_.end());
  mid_edges_.erase(std::unique(mid_edges_.begin(), mid_edges_.end()), mid_edges_.end());
}

void MortarSegments::share_overlaps(std::vector<double>& d, std::vector<std::vector<std::pair<int, double>>>& m,
                                   int& n_whole_cell) {  // of one zone
  // D sums over the ranks (each holds its cells' part); M goes round as (row, master node,
  // value) triples, added in rank order, so that a row's master nodes come in the order of
  // the cells that name them, as in one process.
  parallel::sum_over_ranks(d.data(), static_cast<long long>(d.size()));
  double whole = n_whole_cell;
  parallel::sum_over_ranks(&whole, 1);
  n_whole_cell = static_cast<int>(whole);
  std::vector<double> mine;
  for (size_t j = 0; j < m.size(); ++j)
    for (const auto& [node, v] : m[j]) mine.insert(mine.end(), {static_cast<double>(j), static_cast<double>(node), v});
  const std::vector<double> all = parallel::gather_all(mine);
  for (auto& mj : m) mj.clear();
  for (size_t k = 0; k + 2 < all.size(); k += 3) {
    auto& mj = m[static_cast<size_t>(all[k])];
    const int node = static_cast<int>(all[k + 1]);
    auto it = std::find_if(mj.begin(), mj.end(), [&](const auto& e) { return e.first == node; });
    if (it == mj.end()) mj.emplace_back(node, all[k + 2]);
    else it->second += all[k + 2];
  }
}


namespace detail {

/// The master cells of a zone on a uniform grid of their largest bounding box: the candidates a
/// slave cell's box can overlap.
class MasterGrid {
 public:
  MasterGrid(const std::vector<OrientedCell>& mcells, const std::vector<double>& xyz) : box_(6 * mcells.size()) {
    double size = 0.0;
    for (size_t i = 0; i < mcells.size(); ++i) {
      double* b = &box_[6 * i];
      b[0] = b[1] = b[2] = 1e300;
      b[3] = b[4] = b[5] = -1e300;
      for (int a = 0; a < mcells[i].n; ++a)
        for (int k = 0; k < 3; ++k) {
          const double x = xyz[3 * static_cast<size_t>(mcells[i].nodes[a]) + k];
          b[k] = std::min(b[k], x), b[3 + k] = std::max(b[3 + k], x);
        }
      size = std::max({size, b[3] - b[0], b[4] - b[1], b[5] - b[2]});
    }
    cell_ = size > 0.0 ? size : 1.0;
    for (size_t i = 0; i < mcells.size(); ++i)
      for_cells_of(&box_[6 * i], [&](long long key) { grid_[key].push_back(static_cast<int>(i)); });
    stamp_.assign(mcells.size(), -1);
  }

  /// Calls `visit(master)` once for each master cell whose box meets `b` (xmin, ymin, zmin,
  /// xmax, ymax, zmax); `query` numbers the call (a slave cell's index).
  template <class Visit>
  void overlapping(const double* b, int query, Visit visit) {
    for_cells_of(b, [&](long long key) {
      auto it = grid_.find(key);
      if (it == grid_.end()) return;
      for (int mi : it->second) {
        if (stamp_[mi] == query) continue;
        stamp_[mi] = query;
        const double* mb = &box_[6 * mi];
        if (mb[0] > b[3] || mb[3] < b[0] || mb[1] > b[4] || mb[4] < b[1] || mb[2] > b[5] || mb[5] < b[2]) continue;
        visit(mi);
      }
    });
  }

 private:
  long long key(double x, double y, double z) const {
    const long long i = static_cast<long long>(std::floor(x / cell_)), j = static_cast<long long>(std::floor(y / cell_)),
                    k = static_cast<long long>(std::floor(z / cell_));
    return (i * 73856093LL) ^ (j * 19349663LL) ^ (k * 83492791LL);
  }
  template <class F>
  void for_cells_of(const double* b, F f) const {
    for (double x = std::floor(b[0] / cell_); x <= std::floor(b[3] / cell_); x += 1.0)
      for (double y = std::floor(b[1] / cell_); y <= std::floor(b[4] / cell_); y += 1.0)
        for (double w = std::floor(b[2] / cell_); w <= std::floor(b[5] / cell_); w += 1.0)
          f(key((x + 0.5) * cell_, (y + 0.5) * cell_, (w + 0.5) * cell_));
  }

  std::vector<double> box_;
  double cell_ = 1.0;
  std::unordered_map<long long, std::vector<int>> grid_;
  std::vector<int> stamp_;
};

/// Per slave node of a zone, numbered in the slave cells' order: D_j, the integral of N~_j over
/// the whole cells, the sum of the cells' normals, M_jl.
struct ZoneIntegrals {
  std::unordered_map<int, int> local;
  std::vector<int> nodes;
  std::vector<double> d, d_full, normal;
  std::vector<std::vector<std::pair<int, double>>> m;

  int index(int node) {
    auto [it, fresh] = local.try_emplace(node, static_cast<int>(nodes.size()));
    if (fresh) {
      nodes.push_back(node);
      d.push_back(0.0);
      d_full.push_back(0.0);
      normal.insert(normal.end(), {0.0, 0.0, 0.0});
      m.emplace_back();
    }
    return it->second;
  }
};

/// Reused buffers of one pairing: a slave cell's overlap points and their master cells, and the
/// whole slave cell's points.
struct OverlapScratch {
  std::vector<OverlapPoint> pts, whole;
  std::vector<int> owner;
};

}  // namespace detail

namespace {

using detail::MasterGrid;
using detail::OverlapScratch;
using detail::ZoneIntegrals;

void cell_coordinates(const OrientedCell& oc, const std::vector<double>& xyz, double* x) {
  for (int a = 0; a < oc.n; ++a)
    for (int k = 0; k < 3; ++k) x[3 * a + k] = xyz[3 * static_cast<size_t>(oc.nodes[a]) + k];
}

/// The whole slave cell as integration points (the measure r dl on an AXIS model) into `whole`:
/// the integral of each N~_j over it (a node whose covered share is under half of it gets no
/// row), the dual basis of a partly covered cell that cannot carry its own; and the cell's
/// normal at each of its nodes.
void whole_slave_cell(const OrientedCell& sc, const double* sx, bool axisymmetric, ZoneIntegrals& zi,
                      std::vector<OverlapPoint>& whole) {
  whole.clear();
  for (const auto& q : contact_integration_rule(sc.type, IntegrationScheme::Gauss, 4)) {
    OverlapPoint op;
    op.xi_s[0] = q.xi[0], op.xi_s[1] = q.xi[1];
    const SurfacePoint sp = surface_point(sc.type, sx, q.xi);
    op.w = q.weight * sp.jacobian * (axisymmetric ? std::max(sp.x[0], 0.0) : 1.0);
    double nt[kMaxSurfaceNodes];
    slave_shape(sc.type, q.xi, nt);
    for (int a = 0; a < sc.n; ++a) zi.d_full[zi.index(sc.nodes[a])] += op.w * nt[a];
    whole.push_back(op);
  }
  for (int a = 0; a < sc.n; ++a) {
    double xi[2];
    surface_reference_node(sc.type, a, xi);
    const SurfacePoint sp = surface_point(sc.type, sx, xi);
    const int j = zi.index(sc.nodes[a]);
    for (int k = 0; k < 3; ++k) zi.normal[3 * j + k] += sp.n[k];
  }
}

/// Adds the overlap points' D_j and M_jl of one slave cell to `zi`: Phi_j from the dual basis
/// `a_dual`, the master shape functions at each point's master coordinates.
void add_overlaps(const OrientedCell& sc, const std::vector<OrientedCell>& mcells, const std::vector<OverlapPoint>& pts,
                  const std::vector<int>& owner, const double* a_dual, ZoneIntegrals& zi) {
  int js[kMaxSurfaceNodes];
  for (int a = 0; a < sc.n; ++a) js[a] = zi.index(sc.nodes[a]);
  double ns[kMaxSurfaceNodes], phi[kMaxSurfaceNodes], nmast[kMaxSurfaceNodes];
  for (size_t p = 0; p < pts.size(); ++p) {
    const OverlapPoint& q = pts[p];
    slave_shape(sc.type, q.xi_s, ns);
    for (int a = 0; a < sc.n; ++a) {
      phi[a] = 0.0;
      for (int c = 0; c < sc.n; ++c) phi[a] += a_dual[a * sc.n + c] * ns[c];
      zi.d[js[a]] += q.w * phi[a];  // = the integral of N~_j where Phi is biorthogonal on the overlap
    }
    const OrientedCell& mc = mcells[owner[p]];
    surface_shape(mc.type, q.xi_m, nmast, nullptr, nullptr);
    for (int a = 0; a < sc.n; ++a) {
      auto& mj = zi.m[js[a]];
      for (int l = 0; l < mc.n; ++l) {
        const double v = q.w * phi[a] * nmast[l];
        auto it = std::find_if(mj.begin(), mj.end(), [&](const auto& e) { return e.first == mc.nodes[l]; });
        if (it == mj.end()) mj.emplace_back(mc.nodes[l], v);
        else it->second += v;
      }
    }
  }
}

}  // namespace

bool MortarSegments::integrate_slave_cell(size_t z, size_t s, const std::vector<double>& xyz, MasterGrid& grid,
                                          ZoneIntegrals& zi, OverlapScratch& scratch) const {
  const OrientedCell& sc = slave_cells_[z][s];
  const std::vector<OrientedCell>& mcells = master_cells_[z];
  double sx[3 * kMaxSurfaceNodes], mx[3 * kMaxSurfaceNodes];
  cell_coordinates(sc, xyz, sx);
  // The search box: the slave cell's, grown by half its size.
  double b[6] = {1e300, 1e300, 1e300, -1e300, -1e300, -1e300};
  for (int a = 0; a < sc.n; ++a)
    for (int k = 0; k < 3; ++k) b[k] = std::min(b[k], sx[3 * a + k]), b[3 + k] = std::max(b[3 + k], sx[3 * a + k]);
  const double reach = 0.5 * std::max({b[3] - b[0], b[4] - b[1], b[5] - b[2]});
  for (int k = 0; k < 3; ++k) b[k] -= reach, b[3 + k] += reach;
  std::vector<OverlapPoint>& pts = scratch.pts;
  std::vector<int>& owner = scratch.owner;
  pts.clear();
  owner.clear();
  grid.overlapping(b, static_cast<int>(s), [&](int mi) {
    const OrientedCell& mc = mcells[mi];
    cell_coordinates(mc, xyz, mx);
    const size_t before = pts.size();
    const int degree = std::max(2 * shape_degree(sc.type), shape_degree(sc.type) + shape_degree(mc.type));
    overlap_points(sc.type, sx, mc.type, mx, degree, pts);
    if (axisymmetric_)  // AXIS: the measure r dl per radian, r at the slave point
      for (size_t k = before; k < pts.size(); ++k) pts[k].w *= axis_radius(sc.type, sx, pts[k].xi_s);
    owner.insert(owner.end(), pts.size() - before, mi);
  });
  if (pts.empty()) return false;
  double a_dual[kMaxSurfaceNodes * kMaxSurfaceNodes];
  bool whole_cell = false;
  if (!dual_coefficients(sc.type, pts, a_dual)) {
    // A partly covered cell whose covered part cannot carry a dual basis (a QUAD8 or SEG3
    // corner function with a negative integral there): the dual basis of the whole cell.
    // D_j below is then the integral of Phi_j over the covered part (not biorthogonal
    // there), which keeps a rigid translation gap-free; such cells only occur where the
    // master surface ends.
    if (!dual_coefficients(sc.type, scratch.whole, a_dual)) return false;
    whole_cell = true;
  }
  add_overlaps(sc, mcells, pts, owner, a_dual, zi);
  return whole_cell;
}

void MortarSegments::zone_rows(size_t z, ZoneIntegrals& zi, const DofMap& dofs,
                               const std::unordered_map<int, int>& mid_index, MortarPairingRows& out) const {
  // Rows of the zone, vertices before mid-edge nodes (their relations name the vertices').
  const std::vector<int>& nodes = zi.nodes;
  const std::vector<double>& d = zi.d;
  const double d_min = 1e-10 * std::pow(h_[z], dim_ - 1);
  std::vector<int> order(nodes.size());
  for (size_t j = 0; j < nodes.size(); ++j) order[j] = static_cast<int>(j);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return (mid_index.count(nodes[a]) != 0) < (mid_index.count(nodes[b]) != 0);
  });
  const double dist = zones_[z].dist_mait + zones_[z].dist_escl;
  for (int j : order) {
    if (!(d[j] > d_min)) continue;
    // A slave node whose cells face the master surface on less than half of its share lies
    // past the master's edge: its weighted gap, an average over the little that is covered
    // (with the whole cell's dual basis where the covered part cannot carry one), says
    // nothing of its own position, and such a row could hold the bodies apart or together
    // far from any real contact. It is left out, like a node that projects nowhere.
    if (d[j] < 0.5 * zi.d_full[j]) continue;
    MortarRow row;
    row.zone = static_cast<int>(z);
    row.node = nodes[j];
    row.d = d[j];
    double len = 0.0;
    for (int k = 0; k < 3; ++k) len += zi.normal[3 * j + k] * zi.normal[3 * j + k];
    len = std::sqrt(len);
    for (int k = 0; k < 3; ++k) row.normal[k] = len > 0.0 ? zi.normal[3 * j + k] / len : 0.0;
    // g~_j = n . (sum_l M_jl x_l - D_j x~_j), node by node.
    std::vector<std::pair<int, double>> terms = zi.m[j];
    auto mid = mid_index.find(nodes[j]);
    if (mid == mid_index.end()) {
      terms.emplace_back(nodes[j], -d[j]);
    } else {
      const double s = 1.0 - 2.0 * kQuadraticAlpha;
      terms.emplace_back(nodes[j], -d[j] / s);
      terms.emplace_back(mid_edges_[mid->second][1], kQuadraticAlpha * d[j] / s);
      terms.emplace_back(mid_edges_[mid->second][2], kQuadraticAlpha * d[j] / s);
    }
    // A normal component at round-off level is no coupling (kNormalRoundOff).
    for (int k = 0; k < 3; ++k)
      if (std::abs(row.normal[k]) <= kNormalRoundOff) row.normal[k] = 0.0;
    row.g0 = -dist * d[j];
    for (const auto& [node, c] : terms) {
      for (int k = 0; k < dim_; ++k) {
        row.g0 += c * row.normal[k] * mesh_.coords[3 * static_cast<size_t>(node) + k];
        const int eq = dofs.dof(node, k);
        if (eq < 0 || row.normal[k] == 0.0) continue;
        row.eq.push_back(eq);
        row.coef.push_back(c * row.normal[k]);
      }
    }
    out.rows.push_back(std::move(row));
    out.masters.push_back(std::move(zi.m[j]));
  }
}

MortarPairingRows MortarSegments::pair(const DofMap& dofs, const Vector& u, bool shared) const {
  const std::vector<double> xyz = current_coordinates(mesh_, dofs, dim_, u);
  MortarPairingRows out;
  std::unordered_map<int, int> mid_index;
  for (size_t i = 0; i < mid_edges_.size(); ++i) mid_index[mid_edges_[i][0]] = static_cast<int>(i);
  OverlapScratch scratch;
  for (size_t z = 0; z < slave_cells_.size(); ++z) {
    const std::vector<OrientedCell>& slaves = slave_cells_[z];
    MasterGrid grid(master_cells_[z], xyz);
    ZoneIntegrals zi;
    // A shared model: each rank integrates the overlaps of one consecutive block of the slave
    // cells (the costly part: search, clipping, dual basis) and the ranks then share D and M;
    // the nodes are numbered first, in the cells' order, so that every rank numbers them alike.
    const size_t n_slaves = slaves.size(), parts = shared ? static_cast<size_t>(parallel::size()) : 1;
    const size_t me = shared ? static_cast<size_t>(parallel::rank()) : 0;
    const size_t first_mine = me * n_slaves / parts, end_mine = (me + 1) * n_slaves / parts;
    for (const OrientedCell& sc : slaves)
      for (int a = 0; a < sc.n; ++a) zi.index(sc.nodes[a]);
    const int whole_before = out.n_whole_cell;
    double sx[3 * kMaxSurfaceNodes];
    for (size_t s = 0; s < slaves.size(); ++s) {
      cell_coordinates(slaves[s], xyz, sx);
      whole_slave_cell(slaves[s], sx, axisymmetric_, zi, scratch.whole);
      if (s < first_mine || s >= end_mine) continue;  // another rank's overlaps
      if (integrate_slave_cell(z, s, xyz, grid, zi, scratch)) ++out.n_whole_cell;
    }
    if (shared) {
      int zone_whole = out.n_whole_cell - whole_before;
      share_overlaps(zi.d, zi.m, zone_whole);
      out.n_whole_cell = whole_before + zone_whole;
    }
    zone_rows(z, zi, dofs, mid_index, out);
  }
  return out;
}

std::vector<double> MortarSegments::slave_basis_residual(const std::vector<MortarRow>& rows,
                                                         const std::vector<int>& row_of_node, const DofMap& dofs,
                                                         const Vector& residual) const {
  auto r_at = [&](int node, double* r) {
    for (int k = 0; k < 3; ++k) r[k] = 0.0;
    for (int k = 0; k < dim_; ++k) {
      const int eq = dofs.dof(node, k);
      if (eq >= 0) r[k] = residual[eq];
    }
  };
  std::vector<double> rt(3 * rows.size(), 0.0);
  for (size_t i = 0; i < rows.size(); ++i) r_at(rows[i].node, &rt[3 * i]);
  if (!mid_edges_.empty()) {
    double rm[3];
    for (const auto& me : mid_edges_) {
      r_at(me[0], rm);
      for (int v = 1; v <= 2; ++v) {
        const int row = row_of_node[me[v]];
        if (row >= 0)
          for (int k = 0; k < 3; ++k) rt[3 * row + k] += kQuadraticAlpha * rm[k];
      }
      const int row = row_of_node[me[0]];
      if (row >= 0)
        for (int k = 0; k < 3; ++k) rt[3 * row + k] = (1.0 - 2.0 * kQuadraticAlpha) * rm[k];
    }
  }
  return rt;
}

void MortarSegments::report(const std::vector<MortarRow>& rows, int n_active, const Log& log) const {
  // The slave surface the master surface covers (sum of D_j), against the whole slave surface.
  double covered = 0.0, total = 0.0;
  for (const auto& r : rows) covered += r.d;
  for (const auto& cells : slave_cells_)
    for (const auto& oc : cells) {
      double x[3 * kMaxSurfaceNodes];
      for (int a = 0; a < oc.n; ++a)
        for (int k = 0; k < 3; ++k) x[3 * a + k] = mesh_.node(oc.nodes[a])[k];
      for (const auto& q : contact_integration_rule(oc.type, IntegrationScheme::Gauss, 4)) {
        const SurfacePoint sp = surface_point(oc.type, x, q.xi);
        total += q.weight * sp.jacobian * (axisymmetric_ ? std::max(sp.x[0], 0.0) : 1.0);
      }
    }
  std::ostringstream msg;
  msg << "mortar contact: " << rows.size() << " slave nodes paired, " << n_active << " initially in contact; "
      << "the master surface covers " << covered << " of the slave surface's " << total
      << (axisymmetric_ ? " m^2 per radian (axisymmetric)" : dim_ == 2 ? " m" : " m^2");
  log.info(msg.str());
}

}  // namespace lunaster::engine::contact
