#include "engine/contact/mortar_problem.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <unordered_map>

#include "engine/contact/contact_problem.hpp"
#include "engine/contact/integration_rules.hpp"
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

namespace {

/// "contact zone 2 (slave 'AB', master 'EF')".
std::string zone_label(const ContactZone& zone, int z) {
  std::string label = "contact zone " + std::to_string(z + 1);
  if (!zone.slave_group.empty() || !zone.master_group.empty())
    label += " (slave '" + zone.slave_group + "', master '" + zone.master_group + "')";
  return label;
}

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
      throw DeckError(zone + ": " + role + " cell " + cell_label(mesh, c) + " is a " + surface_type_name(oc.type) + ", expected a boundary cell of dimension " +
                      std::to_string(dim - 1));
    oc.n = surface_n_nodes(oc.type);
    const int* nodes = mesh.cell(c);
    const int nv = surface_n_vertices(oc.type);
    // Volume cells holding every vertex of the face.
    int owner = -1, n_owners = 0;
    for (int v : volumes_of_node[nodes[0]]) {
      const int* vn = mesh.cell(v);
      const int nn = mesh.cell_n_nodes(v);
      bool all = true;
      for (int a = 1; a < nv && all; ++a) all = std::find(vn, vn + nn, nodes[a]) != vn + nn;
      if (all) owner = v, ++n_owners;
    }
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

MortarProblem::MortarProblem(const ContactDefinition& definition, const Mesh& mesh, int dim)
    : def_(definition), mesh_(mesh), dim_(dim) {
  LUNASTER_ASSERT(dim == 2 || dim == 3, "contact: dimension must be 2 or 3");
  LUNASTER_ASSERT(lagrange() || def_.method == ContactMethod::MortarPenalty, "not a mortar method");
  // The volume cells around the nodes of the contact surfaces alone (the whole mesh's lists
  // took 1.8 % of the samples of the 2D k = 16 mortar benchmark, these 0.3 %).
  std::vector<char> on_surface(mesh.n_nodes(), 0);
  for (const ContactZone& zone : def_.zones)
    for (const auto* cells : {&zone.slave_cells, &zone.master_cells})
      for (int c : *cells)
        for (int a = 0; a < mesh.cell_n_nodes(c); ++a) on_surface[mesh.cell(c)[a]] = 1;
  std::vector<std::vector<int>> volumes_of_node(mesh.n_nodes());
  for (int c = 0; c < mesh.n_cells(); ++c)
    if (topological_dim(mesh.cell_types[c]) == dim)
      for (int a = 0; a < mesh.cell_n_nodes(c); ++a)
        if (on_surface[mesh.cell(c)[a]]) volumes_of_node[mesh.cell(c)[a]].push_back(c);
  std::vector<int> zone_of_slave(mesh.n_nodes(), -1);
  for (size_t z = 0; z < def_.zones.size(); ++z) {
    const ContactZone& zone = def_.zones[z];
    if (!(zone.coef_cont > 0.0) || !std::isfinite(zone.coef_cont))
      throw DeckError(zone_label(zone, static_cast<int>(z)) +
                      ": the complementarity coefficient must be a finite number > 0");
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
            mid_edges_.push_back({oc.nodes[a], std::min(oc.nodes[v1], oc.nodes[v2]), std::max(oc.nodes[v1], oc.nodes[v2])});
        }
    h_.push_back(smallest_edge(mesh, zone.slave_cells));
    for (const auto* group : {&slave_cells_.back(), &master_cells_.back()})
      for (const auto& oc : *group) geometry_nodes_.insert(geometry_nodes_.end(), oc.nodes, oc.nodes + oc.n);
  }
  std::sort(geometry_nodes_.begin(), geometry_nodes_.end());
  geometry_nodes_.erase(std::unique(geometry_nodes_.begin(), geometry_nodes_.end()), geometry_nodes_.end());
  std::sort(mid_edges_.begin(), mid_edges_.end());
  mid_edges_.erase(std::unique(mid_edges_.begin(), mid_edges_.end()), mid_edges_.end());
}

void MortarProblem::set_dirichlet(const std::vector<DirichletValue>& dirichlet) {
  for (const auto& d : dirichlet) imposed_.insert({d.node, d.component});
}

void MortarProblem::add_dofs(DofMap& dofs) { dofs_ = dofs; }

double MortarProblem::complementarity(int zone) const {
  const double e = def_.modulus > 0.0 ? def_.modulus : 1.0;
  return def_.zones[zone].coef_cont * e / h_[zone];
}

void MortarProblem::share_among_ranks(const std::vector<char>& /*owned_nodes*/) { shared_ = parallel::size() > 1; }

void MortarProblem::share_overlaps(std::vector<double>& d, std::vector<std::vector<std::pair<int, double>>>& m,
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

std::vector<MortarRow> MortarProblem::build_rows(const Vector& u,
                                                 std::vector<std::vector<std::pair<int, double>>>& masters,
                                                 int& n_whole_cell) const {
  const std::vector<double> xyz = current_coordinates(mesh_, dofs_, dim_, u);
  std::vector<MortarRow> rows;
  masters.clear();
  n_whole_cell = 0;
  std::unordered_map<int, int> mid_index;
  for (size_t i = 0; i < mid_edges_.size(); ++i) mid_index[mid_edges_[i][0]] = static_cast<int>(i);
  std::vector<OverlapPoint> pts;
  std::vector<int> owner;
  std::vector<OverlapPoint> whole;
  for (size_t z = 0; z < slave_cells_.size(); ++z) {
    const std::vector<OrientedCell>& slaves = slave_cells_[z];
    const std::vector<OrientedCell>& mcells = master_cells_[z];
    // Per slave node of the zone: D_j, sum of normals, M_jl.
    std::unordered_map<int, int> local;
    std::vector<int> nodes;
    std::vector<double> d, d_full, normal;
    std::vector<std::vector<std::pair<int, double>>> m;
    auto index = [&](int node) {
      auto [it, fresh] = local.try_emplace(node, static_cast<int>(nodes.size()));
      if (fresh) {
        nodes.push_back(node);
        d.push_back(0.0);
        d_full.push_back(0.0);
        normal.insert(normal.end(), {0.0, 0.0, 0.0});
        m.emplace_back();
      }
      return it->second;
    };
    auto coords = [&](const OrientedCell& oc, double* x) {
      for (int a = 0; a < oc.n; ++a)
        for (int k = 0; k < 3; ++k) x[3 * a + k] = xyz[3 * static_cast<size_t>(oc.nodes[a]) + k];
    };
    // Master bounding boxes on a uniform grid.
    const size_t nm = mcells.size();
    std::vector<double> box(6 * nm);
    double size = 0.0;
    for (size_t i = 0; i < nm; ++i) {
      double* b = &box[6 * i];
      b[0] = b[1] = b[2] = 1e300;
      b[3] = b[4] = b[5] = -1e300;
      for (int a = 0; a < mcells[i].n; ++a)
        for (int k = 0; k < 3; ++k) {
          const double x = xyz[3 * static_cast<size_t>(mcells[i].nodes[a]) + k];
          b[k] = std::min(b[k], x), b[3 + k] = std::max(b[3 + k], x);
        }
      size = std::max({size, b[3] - b[0], b[4] - b[1], b[5] - b[2]});
    }
    const double cell = size > 0.0 ? size : 1.0;
    auto key = [cell](double x, double y, double zz) {
      const long long i = static_cast<long long>(std::floor(x / cell)), j = static_cast<long long>(std::floor(y / cell)),
                      k = static_cast<long long>(std::floor(zz / cell));
      return (i * 73856093LL) ^ (j * 19349663LL) ^ (k * 83492791LL);
    };
    std::unordered_map<long long, std::vector<int>> grid;
    for (size_t i = 0; i < nm; ++i) {
      const double* b = &box[6 * i];
      for (double x = std::floor(b[0] / cell); x <= std::floor(b[3] / cell); x += 1.0)
        for (double y = std::floor(b[1] / cell); y <= std::floor(b[4] / cell); y += 1.0)
          for (double w = std::floor(b[2] / cell); w <= std::floor(b[5] / cell); w += 1.0)
            grid[key((x + 0.5) * cell, (y + 0.5) * cell, (w + 0.5) * cell)].push_back(static_cast<int>(i));
    }
    std::vector<int> stamp(nm, -1);
    double sx[3 * kMaxSurfaceNodes], mx[3 * kMaxSurfaceNodes];
    // A shared model: each rank integrates the overlaps of one consecutive block of the slave
    // cells (the costly part: search, clipping, dual basis) and the ranks then share D and M;
    // the nodes are numbered first, in the cells' order, so that every rank numbers them alike.
    const size_t n_slaves = slaves.size(), parts = shared_ ? static_cast<size_t>(parallel::size()) : 1;
    const size_t me = shared_ ? static_cast<size_t>(parallel::rank()) : 0;
    const size_t first_mine = me * n_slaves / parts, end_mine = (me + 1) * n_slaves / parts;
    for (const OrientedCell& sc : slaves)
      for (int a = 0; a < sc.n; ++a) index(sc.nodes[a]);
    const int whole_before = n_whole_cell;
    for (size_t s = 0; s < slaves.size(); ++s) {
      const OrientedCell& sc = slaves[s];
      coords(sc, sx);
      // The whole slave cell as integration points (the measure r dl on an AXIS model): the
      // integral of each N~_j over it (a node whose covered share is under half of it gets no
      // row, below), and the dual basis of a partly covered cell that cannot carry its own.
      whole.clear();
      for (const auto& q : contact_integration_rule(sc.type, IntegrationScheme::Gauss, 4)) {
        OverlapPoint op;
        op.xi_s[0] = q.xi[0], op.xi_s[1] = q.xi[1];
        const SurfacePoint sp = surface_point(sc.type, sx, q.xi);
        op.w = q.weight * sp.jacobian * (def_.axisymmetric ? std::max(sp.x[0], 0.0) : 1.0);
        double nt[kMaxSurfaceNodes];
        slave_shape(sc.type, q.xi, nt);
        for (int a = 0; a < sc.n; ++a) d_full[index(sc.nodes[a])] += op.w * nt[a];
        whole.push_back(op);
      }
      // Nodal normals: the cell's normal at each of its nodes.
      for (int a = 0; a < sc.n; ++a) {
        double xi[2];
        surface_reference_node(sc.type, a, xi);
        const SurfacePoint sp = surface_point(sc.type, sx, xi);
        const int j = index(sc.nodes[a]);
        for (int k = 0; k < 3; ++k) normal[3 * j + k] += sp.n[k];
      }
      if (s < first_mine || s >= end_mine) continue;  // another rank's overlaps
      double b[6] = {1e300, 1e300, 1e300, -1e300, -1e300, -1e300};
      for (int a = 0; a < sc.n; ++a)
        for (int k = 0; k < 3; ++k) b[k] = std::min(b[k], sx[3 * a + k]), b[3 + k] = std::max(b[3 + k], sx[3 * a + k]);
      const double reach = 0.5 * std::max({b[3] - b[0], b[4] - b[1], b[5] - b[2]});
      for (int k = 0; k < 3; ++k) b[k] -= reach, b[3 + k] += reach;
      pts.clear();
      owner.clear();
      for (double x = std::floor(b[0] / cell); x <= std::floor(b[3] / cell); x += 1.0)
        for (double y = std::floor(b[1] / cell); y <= std::floor(b[4] / cell); y += 1.0)
          for (double w = std::floor(b[2] / cell); w <= std::floor(b[5] / cell); w += 1.0) {
            auto it = grid.find(key((x + 0.5) * cell, (y + 0.5) * cell, (w + 0.5) * cell));
            if (it == grid.end()) continue;
            for (int mi : it->second) {
              if (stamp[mi] == static_cast<int>(s)) continue;
              stamp[mi] = static_cast<int>(s);
              const double* mb = &box[6 * mi];
              if (mb[0] > b[3] || mb[3] < b[0] || mb[1] > b[4] || mb[4] < b[1] || mb[2] > b[5] || mb[5] < b[2]) continue;
              const OrientedCell& mc = mcells[mi];
              coords(mc, mx);
              const size_t before = pts.size();
              const int degree = std::max(2 * shape_degree(sc.type), shape_degree(sc.type) + shape_degree(mc.type));
              overlap_points(sc.type, sx, mc.type, mx, degree, pts);
              if (def_.axisymmetric)  // AXIS: the measure r dl per radian, r at the slave point
                for (size_t k = before; k < pts.size(); ++k) pts[k].w *= axis_radius(sc.type, sx, pts[k].xi_s);
              owner.insert(owner.end(), pts.size() - before, mi);
            }
          }
      if (pts.empty()) continue;
      double a_dual[kMaxSurfaceNodes * kMaxSurfaceNodes];
      if (!dual_coefficients(sc.type, pts, a_dual)) {
        // A partly covered cell whose covered part cannot carry a dual basis (a QUAD8 or SEG3
        // corner function with a negative integral there): the dual basis of the whole cell.
        // D_j below is then the integral of Phi_j over the covered part (not biorthogonal
        // there), which keeps a rigid translation gap-free; such cells only occur where the
        // master surface ends.
        if (!dual_coefficients(sc.type, whole, a_dual)) continue;
        ++n_whole_cell;
      }
      int js[kMaxSurfaceNodes];
      for (int a = 0; a < sc.n; ++a) js[a] = index(sc.nodes[a]);
      double ns[kMaxSurfaceNodes], phi[kMaxSurfaceNodes], nmast[kMaxSurfaceNodes];
      for (size_t p = 0; p < pts.size(); ++p) {
        const OverlapPoint& q = pts[p];
        slave_shape(sc.type, q.xi_s, ns);
        for (int a = 0; a < sc.n; ++a) {
          phi[a] = 0.0;
          for (int c = 0; c < sc.n; ++c) phi[a] += a_dual[a * sc.n + c] * ns[c];
          d[js[a]] += q.w * phi[a];  // = the integral of N~_j where Phi is biorthogonal on the overlap
        }
        const OrientedCell& mc = mcells[owner[p]];
        surface_shape(mc.type, q.xi_m, nmast, nullptr, nullptr);
        for (int a = 0; a < sc.n; ++a) {
          auto& mj = m[js[a]];
          for (int l = 0; l < mc.n; ++l) {
            const double v = q.w * phi[a] * nmast[l];
            auto it = std::find_if(mj.begin(), mj.end(), [&](const auto& e) { return e.first == mc.nodes[l]; });
            if (it == mj.end()) mj.emplace_back(mc.nodes[l], v);
            else it->second += v;
          }
        }
      }
    }
    if (shared_) {
      int zone_whole = n_whole_cell - whole_before;
      share_overlaps(d, m, zone_whole);
      n_whole_cell = whole_before + zone_whole;
    }
    // Rows of the zone, vertices before mid-edge nodes (their relations name the vertices').
    const double d_min = 1e-10 * std::pow(h_[z], dim_ - 1);
    std::vector<int> order(nodes.size());
    for (size_t j = 0; j < nodes.size(); ++j) order[j] = static_cast<int>(j);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
      return (mid_index.count(nodes[a]) != 0) < (mid_index.count(nodes[b]) != 0);
    });
    const double dist = def_.zones[z].dist_mait + def_.zones[z].dist_escl;
    for (int j : order) {
      if (!(d[j] > d_min)) continue;
      // A slave node whose cells face the master surface on less than half of its share lies
      // past the master's edge: its weighted gap, an average over the little that is covered
      // (with the whole cell's dual basis where the covered part cannot carry one), says
      // nothing of its own position, and such a row could hold the bodies apart or together
      // far from any real contact. It is left out, like a node that projects nowhere.
      if (d[j] < 0.5 * d_full[j]) continue;
      MortarRow row;
      row.zone = static_cast<int>(z);
      row.node = nodes[j];
      row.d = d[j];
      double len = 0.0;
      for (int k = 0; k < 3; ++k) len += normal[3 * j + k] * normal[3 * j + k];
      len = std::sqrt(len);
      for (int k = 0; k < 3; ++k) row.normal[k] = len > 0.0 ? normal[3 * j + k] / len : 0.0;
      // g~_j = n . (sum_l M_jl x_l - D_j x~_j), node by node.
      std::vector<std::pair<int, double>> terms = m[j];
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
          const int eq = dofs_.dof(node, k);
          if (eq < 0 || row.normal[k] == 0.0) continue;
          row.eq.push_back(eq);
          row.coef.push_back(c * row.normal[k]);
        }
      }
      rows.push_back(std::move(row));
      masters.push_back(std::move(m[j]));
    }
  }
  return rows;
}

void MortarProblem::pair(const Vector& u, const Log* log) {
  std::vector<std::vector<std::pair<int, double>>> masters;
  int n_whole_cell = 0;
  std::vector<MortarRow> rows = build_rows(u, masters, n_whole_cell);
  ++n_row_builds_;
  adopt(u, std::move(rows), std::move(masters), n_whole_cell, log);
}

void MortarProblem::adopt(const Vector& u, std::vector<MortarRow> rows,
                          std::vector<std::vector<std::pair<int, double>>> masters, int n_whole_cell,
                          const Log* log) {
  // Statuses follow the nodes.
  for (auto& r : rows) {
    const int old = row_of_node_.empty() ? -1 : row_of_node_[r.node];
    r.active = old >= 0 && rows_[old].active;
  }
  rows_ = std::move(rows);
  master_terms_ = std::move(masters);
  u_at_pairing_ = u;
  row_of_node_.assign(mesh_.n_nodes(), -1);
  for (size_t i = 0; i < rows_.size(); ++i) row_of_node_[rows_[i].node] = static_cast<int>(i);
  lambda_.assign(rows_.size(), 0.0);
  ++pattern_version_;
  ++n_pairings_;
  // A slave node whose normal direction is imposed cannot also hold a contact condition.
  for (const auto& r : rows_) {
    int k_max = 0;
    for (int k = 1; k < dim_; ++k)
      if (std::abs(r.normal[k]) > std::abs(r.normal[k_max])) k_max = k;
    if (imposed_.count({r.node, k_max}))
      throw DeckError("slave node " + node_label(mesh_, r.node) + " of " + zone_label(def_.zones[r.zone], r.zone) +
                      " has an imposed displacement " + component_name(static_cast<Component>(k_max)) +
                      " along the normal to the contact surface: the contact condition and the imposed displacement "
                      "cannot both hold there; remove the node from the slave group (or from the imposed displacement)");
  }
  if (log && n_whole_cell > 0)
    log->info("mortar contact: " + std::to_string(n_whole_cell) +
              " partly covered slave cell(s) use the dual basis of the whole cell (their covered part cannot "
              "carry one): exact patch tests hold away from the edge of the master surface");
}

void MortarProblem::begin_step(const Vector& u, const Log& log) {
  first_iteration_ = true;
  n_geom_iter_ = 0;
  if (!first_step_) return;  // the pairing of the last converged state stands
  pair(u, &log);
  first_step_ = false;
  std::vector<int> rows_of_zone(def_.zones.size(), 0);
  for (const auto& r : rows_) ++rows_of_zone[r.zone];
  for (size_t z = 0; z < def_.zones.size(); ++z)
    if (rows_of_zone[z] == 0)
      throw DeckError(zone_label(def_.zones[z], static_cast<int>(z)) +
                      ": no slave cell overlaps a master cell facing it; give the slave and master groups as the two "
                      "sides of one interface, touching or nearly touching in the initial configuration");
  int n_active = 0;
  for (auto& r : rows_) {
    const ContactZone& zone = def_.zones[r.zone];
    const double g = r.weighted_gap(u) / r.d;
    r.active = zone.init == ContactInit::Yes || (zone.init == ContactInit::Interpenetrated && g < -1e-6 * h_[r.zone]);
    n_active += r.active;
  }
  // The slave surface the master surface covers (sum of D_j), against the whole slave surface.
  double covered = 0.0, total = 0.0;
  for (const auto& r : rows_) covered += r.d;
  for (const auto& cells : slave_cells_)
    for (const auto& oc : cells) {
      double x[3 * kMaxSurfaceNodes];
      for (int a = 0; a < oc.n; ++a)
        for (int k = 0; k < 3; ++k) x[3 * a + k] = mesh_.node(oc.nodes[a])[k];
      for (const auto& q : contact_integration_rule(oc.type, IntegrationScheme::Gauss, 4)) {
        const SurfacePoint sp = surface_point(oc.type, x, q.xi);
        total += q.weight * sp.jacobian * (def_.axisymmetric ? std::max(sp.x[0], 0.0) : 1.0);
      }
    }
  std::ostringstream msg;
  msg << "mortar contact: " << rows_.size() << " slave nodes paired, " << n_active << " initially in contact; "
      << "the master surface covers " << covered << " of the slave surface's " << total
      << (def_.axisymmetric ? " m^2 per radian (AXIS)" : dim_ == 2 ? " m" : " m^2");
  log.info(msg.str());
}

void MortarProblem::update_pressures(const Vector& residual) {
  // Residual transformed to the mortar slave basis: r~_v = r_v + alpha sum r_m over the
  // mid-edge nodes of the edges at v; r~_m = (1 - 2 alpha) r_m.
  auto r_at = [&](int node, double* r) {
    for (int k = 0; k < 3; ++k) r[k] = 0.0;
    for (int k = 0; k < dim_; ++k) {
      const int eq = dofs_.dof(node, k);
      if (eq >= 0) r[k] = residual[eq];
    }
  };
  std::vector<double> rt(3 * rows_.size(), 0.0);
  for (size_t i = 0; i < rows_.size(); ++i) r_at(rows_[i].node, &rt[3 * i]);
  if (!mid_edges_.empty()) {
    double rm[3];
    for (const auto& me : mid_edges_) {
      r_at(me[0], rm);
      for (int v = 1; v <= 2; ++v) {
        const int row = row_of_node_[me[v]];
        if (row >= 0)
          for (int k = 0; k < 3; ++k) rt[3 * row + k] += kQuadraticAlpha * rm[k];
      }
      const int row = row_of_node_[me[0]];
      if (row >= 0)
        for (int k = 0; k < 3; ++k) rt[3 * row + k] = (1.0 - 2.0 * kQuadraticAlpha) * rm[k];
    }
  }
  // Along an imposed component of the slave node the residual is the support's reaction,
  // not contact force (a node on a symmetry line whose normal is tilted from it): the
  // pressure comes from the free components, where the eliminated system makes the
  // residual parallel to the normal.
  for (size_t i = 0; i < rows_.size(); ++i) {
    double nr = 0.0, nn = 0.0;
    for (int k = 0; k < dim_; ++k) {
      if (imposed_.count({rows_[i].node, k})) continue;
      nr += rows_[i].normal[k] * rt[3 * i + k];
      nn += rows_[i].normal[k] * rows_[i].normal[k];
    }
    lambda_[i] = nn > 0.0 ? -nr / (rows_[i].d * nn) : 0.0;
  }
}

int MortarProblem::update_statuses(const Vector& u) {
  double lambda_max = 0.0;
  for (size_t i = 0; i < rows_.size(); ++i)
    if (rows_[i].active) lambda_max = std::max(lambda_max, std::abs(lambda_[i]));
  int changed = 0;
  for (size_t i = 0; i < rows_.size(); ++i) {
    MortarRow& r = rows_[i];
    const double g = r.weighted_gap(u) / r.d;
    const double lambda = r.active ? lambda_[i] : 0.0;
    // C_j = lambda - max(0, lambda - c g): active where lambda - c g > 0; round-off on either
    // side of zero (a pressure or a gap at the level of the solve's accuracy) keeps the status.
    const double c = complementarity(r.zone);
    const double tol = r.active ? 1e-9 * lambda_max + 1e-9 * c * h_[r.zone] : 1e-9 * c * h_[r.zone];
    const double value = lambda - c * g;
    const bool active = r.active ? value > -tol : value > tol;
    if (active != r.active) r.active = active, ++changed;
  }
  return changed;
}

void MortarProblem::build_eliminations(const Vector& u) {
  eliminations_.clear();
  std::unordered_map<int, int> relation_of;  // eliminated equation -> relation
  for (auto& r : rows_) {
    r.eliminated = -1;
    if (!r.active) continue;
    // The component along which the normal is largest, among the node's own free ones.
    int best = -1;
    double best_coef = 0.0;
    for (size_t k = 0; k < r.eq.size(); ++k)
      if (dofs_.node_of(r.eq[k]) == r.node && !imposed_.count({r.node, dofs_.component_of(r.eq[k])}) &&
          std::abs(r.coef[k]) > std::abs(best_coef))
        best = static_cast<int>(k), best_coef = r.coef[k];
    if (best < 0) continue;  // the node's displacement is imposed: the row cannot be eliminated
    Elimination e;
    e.eq = r.eq[best];
    e.value = -r.weighted_gap(u) / best_coef;
    for (size_t k = 0; k < r.eq.size(); ++k)
      if (static_cast<int>(k) != best) e.terms.emplace_back(r.eq[k], -r.coef[k] / best_coef);
    // Terms naming an equation eliminated before (a mid-edge node's vertices): substitute.
    std::vector<std::pair<int, double>> closed;
    for (const auto& [eq, a] : e.terms) {
      auto it = relation_of.find(eq);
      if (it == relation_of.end()) {
        closed.emplace_back(eq, a);
        continue;
      }
      const Elimination& prev = eliminations_[it->second];
      e.value += a * prev.value;
      for (const auto& t : prev.terms) closed.emplace_back(t.first, a * t.second);
    }
    std::sort(closed.begin(), closed.end());
    e.terms.clear();
    for (const auto& t : closed) {
      if (!e.terms.empty() && e.terms.back().first == t.first) e.terms.back().second += t.second;
      else e.terms.push_back(t);
    }
    LUNASTER_ASSERT(std::none_of(e.terms.begin(), e.terms.end(), [&](const auto& t) { return t.first == e.eq; }),
                    "mortar: an eliminated unknown names itself");
    r.eliminated = e.eq;
    relation_of[e.eq] = static_cast<int>(eliminations_.size());
    eliminations_.push_back(std::move(e));
  }
  // A relation built before a later one that names its equation (a master node that is the
  // slave node of another zone) would not be closed: refuse rather than solve the wrong system.
  for (const auto& e : eliminations_)
    for (const auto& t : e.terms)
      if (relation_of.count(t.first))
        throw DeckError("mortar contact: node " + node_label(mesh_, dofs_.node_of(t.first)) +
                        " is both a slave node in contact and a node of another zone's condition; give the zones "
                        "separate surfaces");
}

void MortarProblem::add_to_system(const Vector& u, std::vector<Triplet>& tangent, Vector& residual) {
  changed_in_newton_ = false;
  if (lagrange()) {
    update_pressures(residual);
    if (!first_iteration_) {
      const int changed = update_statuses(u);
      if (changed) {
        changed_in_newton_ = true;
        n_status_changes_ += changed;
        ++pattern_version_;  // the eliminated unknowns change the system's pattern
      }
    }
    for (size_t i = 0; i < rows_.size(); ++i) {
      if (!rows_[i].active) {
        lambda_[i] = 0.0;
        continue;
      }
      const MortarRow& r = rows_[i];
      for (size_t k = 0; k < r.eq.size(); ++k) residual[r.eq[k]] -= lambda_[i] * r.coef[k];
    }
    build_eliminations(u);
  } else {
    for (size_t i = 0; i < rows_.size(); ++i) {
      MortarRow& r = rows_[i];
      const double g = r.weighted_gap(u) / r.d;
      // The first iteration of an instant keeps the statuses it starts with (CONTACT_INIT='OUI',
      // or the last instant's): a body held only by contact is then held from the start.
      const bool active = g < 0.0 || (first_iteration_ && r.active);
      if (active != r.active) r.active = active, changed_in_newton_ = true, ++n_status_changes_;
      const double kappa = def_.zones[r.zone].coef_cont;
      lambda_[i] = active ? -kappa * g : 0.0;
      for (size_t k = 0; k < r.eq.size(); ++k) residual[r.eq[k]] -= lambda_[i] * r.coef[k];
      // Every row's block is emitted (zeros when open): the pattern follows the pairing only.
      const double f = active ? kappa / r.d : 0.0;
      for (size_t a = 0; a < r.eq.size(); ++a)
        for (size_t b = 0; b < r.eq.size(); ++b) tangent.emplace_back(r.eq[a], r.eq[b], f * r.coef[a] * r.coef[b]);
    }
  }
  first_iteration_ = false;
}

bool MortarProblem::newton_converged() const { return !changed_in_newton_; }

bool MortarProblem::settle(const Vector& u, const Log& log) {
  if (def_.reac_geom == GeometryUpdate::None) return true;
  // Converged when the nodes of the zones moved little since the last pairing.
  const double resi = geometric_residual(geometry_nodes_, dofs_, dim_, u, u_at_pairing_);
  if (resi <= def_.resi_geom) return true;
  // Otherwise pair again in the converged configuration; a pairing that gives the same rows
  // (a translation, small strain) leaves everything as it is. The rows of surfaces that all
  // moved by one vector (to 1e-10 of the smallest slave edge; on an AXIS model, along the
  // axis: r dl follows the radius) are those of the last pairing, without integrating them.
  if (moved_as_one(u)) return true;
  std::vector<std::vector<std::pair<int, double>>> masters;
  int n_whole_cell = 0;
  std::vector<MortarRow> rows = build_rows(u, masters, n_whole_cell);
  ++n_row_builds_;
  // Same rows: same nodes, and coefficients equal to 1e-10 of the row's largest (a term at
  // round-off level, e.g. a zero-length overlap at coincident nodes, counts as zero).
  bool same = rows.size() == rows_.size();
  for (size_t i = 0; same && i < rows.size(); ++i) {
    const MortarRow &a = rows[i], &b = rows_[i];
    same = a.node == b.node && std::abs(a.d - b.d) <= 1e-10 * b.d;
    double scale = 0.0;
    for (double c : b.coef) scale = std::max(scale, std::abs(c));
    auto value = [](const MortarRow& r, int eq) {
      for (size_t k = 0; k < r.eq.size(); ++k)
        if (r.eq[k] == eq) return r.coef[k];
      return 0.0;
    };
    for (size_t k = 0; same && k < a.eq.size(); ++k) same = std::abs(a.coef[k] - value(b, a.eq[k])) <= 1e-10 * scale;
    for (size_t k = 0; same && k < b.eq.size(); ++k) same = std::abs(b.coef[k] - value(a, b.eq[k])) <= 1e-10 * scale;
  }
  if (same) return true;
  if (def_.reac_geom == GeometryUpdate::Controlled && n_pairings_ >= def_.nb_iter_geom) return true;
  if (++n_geom_iter_ > def_.iter_geom_maxi) {
    ConvergenceError err("mortar contact: the pairing still changed after " + std::to_string(def_.iter_geom_maxi) +
                             " re-pairings",
                         {"smaller load increments may help"});
    err.failure().what = Failure::What::GeometryLoop;
    err.failure().limit = def_.iter_geom_maxi;
    throw err;
  }
  adopt(u, std::move(rows), std::move(masters), n_whole_cell, nullptr);
  log.info("mortar contact: new pairing (geometry iteration " + std::to_string(n_geom_iter_) + ")");
  return false;
}

bool MortarProblem::moved_as_one(const Vector& u) const {
  if (geometry_nodes_.empty() || u_at_pairing_.size() != u.size()) return false;
  const double tol = 1e-10 * *std::min_element(h_.begin(), h_.end());
  auto motion = [&](int node, int k) {
    const int eq = dofs_.dof(node, k);
    return eq >= 0 ? u[eq] - u_at_pairing_[eq] : 0.0;
  };
  double ref[3] = {0.0, 0.0, 0.0};
  for (int k = 0; k < dim_; ++k) ref[k] = motion(geometry_nodes_[0], k);
  if (def_.axisymmetric && !(std::abs(ref[0]) <= tol)) return false;
  for (int node : geometry_nodes_)
    for (int k = 0; k < dim_; ++k)
      if (!(std::abs(motion(node, k) - ref[k]) <= tol)) return false;
  return true;
}

unsigned long long MortarProblem::status_key() const {
  unsigned long long h = 1469598103934665603ULL;
  for (const auto& r : rows_) h = (h ^ static_cast<unsigned long long>(r.active)) * 1099511628211ULL;
  return h;
}

int MortarProblem::n_active() const {
  return static_cast<int>(std::count_if(rows_.begin(), rows_.end(), [](const auto& r) { return r.active; }));
}

namespace {

/// What a mortar pairing is made of, kept by a snapshot: the rows (their statuses included),
/// the master terms, the configuration paired and the pressures.
struct MortarPairing {
  std::vector<MortarRow> rows;
  std::vector<std::vector<std::pair<int, double>>> masters;
  Vector u_at_pairing;
  std::vector<int> row_of_node;
  std::vector<double> lambda;
};

}  // namespace

ContactSnapshot MortarProblem::snapshot() const {
  ContactSnapshot s;
  s.first_step = first_step_;
  for (const auto& r : rows_) s.active.push_back(r.active);
  // begin_step keeps the last pairing after the first step: a step split after a failure
  // must start from the pairing of the step's start, not from the failed attempt's last one.
  if (!first_step_)
    s.pairing = std::make_shared<const MortarPairing>(
        MortarPairing{rows_, master_terms_, u_at_pairing_, row_of_node_, lambda_});
  return s;
}

void MortarProblem::restore(const ContactSnapshot& state) {
  // Before the first step: the next begin_step pairs again and applies CONTACT_INIT.
  first_step_ = state.first_step;
  if (state.pairing) {
    const auto& p = *static_cast<const MortarPairing*>(state.pairing.get());
    rows_ = p.rows;
    master_terms_ = p.masters;
    u_at_pairing_ = p.u_at_pairing;
    row_of_node_ = p.row_of_node;
    lambda_ = p.lambda;
  }
  ++pattern_version_;
}

namespace {

/// The index of LAGS_C in DEPL, the component added (undefined everywhere) if DEPL has none.
int lags_c_of(NodalField& depl) {
  int lags = depl.component_index("LAGS_C");
  if (lags >= 0) return lags;
  std::vector<std::string> components = depl.components;
  components.push_back("LAGS_C");
  NodalField wider(components, depl.n_nodes);
  for (int node = 0; node < depl.n_nodes; ++node)
    for (int c = 0; c < depl.n_components(); ++c)
      if (depl.has(node, c)) wider.set(node, c, depl.value(node, c));
  depl = std::move(wider);
  return depl.component_index("LAGS_C");
}

}  // namespace

void MortarProblem::write_initial_fields(ResultStep& step) const {
  // Before contact: no pressure at the nodes of the slave surfaces, where LAGS_C will live.
  NodalField& depl = step.nodal.at("DEPL");
  const int lags = lags_c_of(depl);
  for (const auto& zone : slave_cells_)
    for (const OrientedCell& oc : zone)
      for (int k = 0; k < oc.n; ++k) depl.set(oc.nodes[k], lags, 0.0);
}

void MortarProblem::write_fields(const Vector& u, ResultStep& step) const {
  // LAGS_C in DEPL: the nodal pressure, negative in compression (no unknown carries it).
  NodalField& depl = step.nodal.at("DEPL");
  const int lags = lags_c_of(depl);
  std::vector<std::string> cmps = {"CONT", "JEU", "RN", "RNX", "RNY"};
  if (dim_ == 3) cmps.push_back("RNZ");
  cmps.push_back("PRES");
  NodalField field(cmps, mesh_.n_nodes());
  const int pres = static_cast<int>(cmps.size()) - 1;
  for (size_t i = 0; i < rows_.size(); ++i) {
    const MortarRow& r = rows_[i];
    const double lambda = r.active ? lambda_[i] : 0.0;
    depl.set(r.node, lags, -lambda);
    field.set(r.node, 0, r.active ? 1.0 : 0.0);
    field.set(r.node, 1, r.weighted_gap(u) / r.d);
    // Force on the slave node: -lambda D_j n_j.
    field.set(r.node, 2, lambda * r.d);
    for (int k = 0; k < dim_; ++k) field.set(r.node, 3 + k, -lambda * r.d * r.normal[k]);
    field.set(r.node, pres, -lambda);
  }
  step.nodal["CONT_NOEU"] = std::move(field);
}

}  // namespace lunaster::engine::contact
