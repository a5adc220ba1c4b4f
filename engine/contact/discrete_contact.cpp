#include "engine/contact/discrete_contact.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "engine/contact/integration_rules.hpp"
#include "engine/contact/surface_element.hpp"
#include "engine/core/error.hpp"

namespace lunaster::engine::contact {

DiscreteContact::DiscreteContact(const ContactDefinition& definition, const Mesh& mesh, int dim)
    : ContactHookBase(definition, mesh, dim) {
  std::set<int> geometry, tied;
  for (size_t z = 0; z < def_.zones.size(); ++z) {
    const ContactZone& zone = def_.zones[z];
    if (!lagrange() && !(zone.coef_pena > 0.0))
      throw DeckError("contact zone " + std::to_string(z + 1) + ": the penalty coefficient E_N must be > 0");
    masters_.push_back(std::make_unique<MasterSurface>(mesh, zone.master_cells, true));
    min_edge_.push_back(smallest_edge(mesh, zone.slave_cells));
    for (int c : zone.master_cells)
      for (int a = 0; a < mesh.cell_n_nodes(c); ++a) geometry.insert(mesh.cell(c)[a]);
    // Tributary areas of the slave vertices: integral of the linear shape functions.
    std::map<int, double> area;
    for (int c : zone.slave_cells) {
      const CellType full = mesh.cell_types[c];
      if (!is_surface_type(full) || topological_dim(full) != dim - 1)
        throw DeckError("contact zone " + std::to_string(z + 1) + ": slave cell " + cell_label(mesh, c) +
                        " is not a boundary cell of dimension " + std::to_string(dim - 1));
      const CellType t = linear_type(full);
      const int nv = surface_n_nodes(t);
      double xyz[3 * kMaxSurfaceNodes], n[kMaxSurfaceNodes];
      for (int a = 0; a < nv; ++a)
        for (int i = 0; i < 3; ++i) xyz[3 * a + i] = mesh.node(mesh.cell(c)[a])[i];
      for (const auto& q : contact_integration_rule(t, IntegrationScheme::Gauss, 2)) {
        const SurfacePoint sp = surface_point(t, xyz, q.xi);
        surface_shape(t, q.xi, n, nullptr, nullptr);
        for (int a = 0; a < nv; ++a) area[mesh.cell(c)[a]] += q.weight * sp.jacobian * n[a];
      }
      for (int a = 0; a < mesh.cell_n_nodes(c); ++a) geometry.insert(mesh.cell(c)[a]);
    }
    // QUAD8 faces on either side: tie each mid-side node to its edge (code_aster CONTACT_8);
    // other quadratic faces keep free mid-side nodes (first_pairing_report warns).
    std::vector<int> faces = zone.slave_cells;
    faces.insert(faces.end(), zone.master_cells.begin(), zone.master_cells.end());
    for (int c : faces) {
      const CellType type = mesh.cell_types[c];
      free_mid_side_ |= linear_type(type) != type && type != CellType::Quad8;  // SEG3, TRIA6
      if (type != CellType::Quad8) continue;
      const auto nodes = mesh.cell(c);
      for (int e = 0; e < 4; ++e) {
        MidSideTie tie;
        tie.mid = nodes[4 + e];
        tie.a = nodes[e];
        tie.b = nodes[(e + 1) % 4];
        if (!tied.insert(tie.mid).second) continue;
        for (int i = 0; i < 3; ++i) {
          const double d = mesh.node(tie.a)[i] - mesh.node(tie.b)[i];
          tie.scale += d * d;
        }
        ties_.push_back(tie);
      }
    }
    for (const auto& [node, a] : area) {
      DiscreteNode dn;
      dn.zone = static_cast<int>(z);
      dn.node = node;
      dn.area = a;
      nodes_.push_back(dn);
    }
  }
  geometry_nodes_.assign(geometry.begin(), geometry.end());
}

void DiscreteContact::set_dirichlet(const std::vector<DirichletValue>& dirichlet) {
  for (const auto& d : dirichlet) fixed_.insert({d.node, d.component});
}

void DiscreteContact::add_dofs(DofMap& dofs) {
  if (lagrange())
    for (const auto& n : nodes_) dofs.add(n.node, LAGS_C);
  for (auto& tie : ties_)
    for (int k = 0; k < dim_; ++k) {
      const bool imposed = fixed_.count({tie.mid, k}) && fixed_.count({tie.a, k}) && fixed_.count({tie.b, k});
      tie.lagr[k] = imposed ? -1 : dofs.add(tie.mid, LAGR_DX + k);
    }
  store_dofs(dofs);
}

MatrixKind DiscreteContact::matrix_kind() const {
  return lagrange() || !ties_.empty() ? MatrixKind::SymmetricIndefinite : MatrixKind::SymmetricPositiveDefinite;
}

void DiscreteContact::set_all_active(bool active) {
  for (auto& n : nodes_) n.active = active && n.paired;
}

double DiscreteContact::multiplier(const Vector& u, const DiscreteNode& n) const {
  if (!lagrange()) return 0.0;
  return u[dofs_.dof(n.node, LAGS_C)];
}

double DiscreteContact::pressure(const Vector& u, const DiscreteNode& n) const {
  if (lagrange()) return multiplier(u, n);
  if (!n.active || n.area <= 0.0) return 0.0;
  return def_.zones[n.zone].coef_pena * n.gap.value(u) / n.area;
}

void DiscreteContact::pair(const Vector& u) {
  const std::vector<double> xyz = current_coordinates(u);
  for (auto& m : masters_) m->update(xyz);
  for (auto& n : nodes_) {
    const MasterSurface& master = *masters_[n.zone];
    const MasterProjection mp = master.project(&xyz[3 * static_cast<size_t>(n.node)], def_.zones[n.zone].tole_proj_ext);
    n.gap = LinearGap{};
    n.paired = mp.found;
    if (!mp.found) {
      n.active = false;
      n.master_cell = -1;
      continue;
    }
    n.master_cell = mp.cell;
    std::copy(mp.normal, mp.normal + 3, n.normal);
    const int k = master.local_index(mp.cell);
    double nm[kMaxSurfaceNodes];
    surface_shape(master.geometry_type(k), mp.xi, nm, nullptr, nullptr);
    const auto& mnodes = master.cell_nodes(k);
    const double one = 1.0;
    n.gap = make_linear_gap(mesh_.coords, dofs_, dim_, &n.node, &one, 1, mnodes.data(), nm,
                            static_cast<int>(mnodes.size()), n.normal);
  }
}

void DiscreteContact::init_statuses(const Vector& u, const Log& log) {
  int n_active = 0, n_unpaired = 0;
  for (auto& n : nodes_) {
    const double g = n.gap.value(u);
    if (!lagrange()) {
      n.active = n.paired && g < 0.0;
    } else {
      switch (def_.zones[n.zone].init) {
        case ContactInit::Yes: n.active = n.paired; break;
        case ContactInit::No: n.active = false; break;
        case ContactInit::Interpenetrated: n.active = n.paired && g <= 1e-6 * min_edge_[n.zone]; break;
      }
    }
    n_active += n.active;
    n_unpaired += !n.paired;
  }
  std::ostringstream msg;
  msg << "contact: " << nodes_.size() << " slave nodes, " << n_active << " initially in contact, " << n_unpaired
      << " not paired with the master surface";
  log.info(msg.str());
}

int DiscreteContact::update_statuses(const Vector& u, const Log& log) {
  int changed = 0;
  if (!lagrange()) {
    for (auto& n : nodes_) {
      const bool s = n.paired && n.gap.value(u) < 0.0;
      changed += s != n.active;
      n.active = s;
    }
    return changed;
  }
  // Active set (algoco): add every violated link; if none, drop the most tensile one.
  double lambda_max = 0.0;
  for (const auto& n : nodes_) lambda_max = std::max(lambda_max, std::abs(multiplier(u, n)));
  const double lambda_tol = 1e-10 * lambda_max;
  DiscreteNode* worst = nullptr;
  for (auto& n : nodes_) {
    if (!n.paired) {
      changed += n.active;
      n.active = false;
      continue;
    }
    if (!n.active && n.gap.value(u) < -1e-8 * min_edge_[n.zone]) n.active = true, ++changed;
    if (n.active && multiplier(u, n) > lambda_tol && (!worst || multiplier(u, n) > multiplier(u, *worst)))
      worst = &n;
  }
  if (changed == 0 && worst) worst->active = false, changed = 1;
  return changed;
}

void DiscreteContact::first_pairing_report(const Log& log) {
  for (size_t z = 0; z < masters_.size(); ++z)
    if (masters_[z]->n_flipped() > 0)
      log.warning("contact zone " + std::to_string(z + 1) + ": " + std::to_string(masters_[z]->n_flipped()) +
                  " master cell(s) oriented towards their own body; their normal was reversed "
                  "(orient the master surface outwards, e.g. ORIE_PEAU)");
  if (!ties_.empty())
    log.info("discrete contact on QUAD8 faces: " + std::to_string(ties_.size()) +
             " mid-side node(s) tied to the mean of their edge's vertices (linear relations, as code_aster's "
             "CONTACT_8); only vertex nodes are slave nodes");
  if (free_mid_side_)
    log.warning("discrete contact on quadratic SEG3/TRIA6 faces: only vertex nodes are slave nodes and master cells "
                "are linearised; their mid-side nodes are not constrained and may penetrate (use FORMULATION="
                "'CONTINUE' for quadratic faces)");
}

void DiscreteContact::add_to_system(const Vector& u, std::vector<Triplet>& tangent, Vector& residual) {
  if (def_.geometry_loop == FixedPointOrNewton::Newton) pair(u);
  // Mid-side ties: s (u_m - (u_a + u_b) / 2) = 0, always active.
  for (const auto& tie : ties_)
    for (int k = 0; k < dim_; ++k) {
      const int leq = tie.lagr[k];
      if (leq < 0) continue;
      const int eqs[3] = {dofs_.dof(tie.mid, k), dofs_.dof(tie.a, k), dofs_.dof(tie.b, k)};
      const double coef[3] = {tie.scale, -0.5 * tie.scale, -0.5 * tie.scale};
      const double lambda = u[leq];
      for (int j = 0; j < 3; ++j) {
        residual[leq] += coef[j] * u[eqs[j]];
        residual[eqs[j]] += coef[j] * lambda;
        tangent.emplace_back(leq, eqs[j], coef[j]);
        tangent.emplace_back(eqs[j], leq, coef[j]);
      }
    }
  for (const auto& n : nodes_) {
    if (!lagrange()) {
      if (!n.active) continue;
      const double en = def_.zones[n.zone].coef_pena;
      add_gradient(n.gap, en * n.gap.value(u), residual);
      add_outer(n.gap, n.gap, en, tangent);
      continue;
    }
    const int leq = dofs_.dof(n.node, LAGS_C);
    const double lambda = u[leq];
    if (!n.active) {
      const double c = def_.zones[n.zone].coef_cont;
      residual[leq] += -(n.area / c) * lambda;
      tangent.emplace_back(leq, leq, -(n.area / c));
      continue;
    }
    add_gradient(n.gap, n.area * lambda, residual);
    residual[leq] += n.area * n.gap.value(u);
    for (int k = 0; k < n.gap.n; ++k) {
      tangent.emplace_back(leq, n.gap.eq[k], n.area * n.gap.coef[k]);
      tangent.emplace_back(n.gap.eq[k], leq, n.area * n.gap.coef[k]);
    }
  }
}

void DiscreteContact::write_fields(const Vector& u, ResultStep& step) const {
  std::vector<std::string> cmps = {"CONT", "JEU", "RN", "RNX", "RNY"};
  if (dim_ == 3) cmps.push_back("RNZ");
  cmps.push_back("PRES");
  NodalField field(cmps, mesh_.n_nodes());
  const int pres = static_cast<int>(cmps.size()) - 1;
  for (const auto& n : nodes_) {
    const double g = n.paired ? n.gap.value(u) : 0.0;
    const double p = n.active ? pressure(u, n) : 0.0;
    // Force on the slave node: -a_i p n (p < 0 in compression pushes along n).
    double f[3];
    for (int k = 0; k < 3; ++k) f[k] = -n.area * p * n.normal[k];
    field.set(n.node, 0, n.active ? 1.0 : 0.0);
    field.set(n.node, 1, g);
    field.set(n.node, 2, std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]));
    for (int k = 0; k < dim_; ++k) field.set(n.node, 3 + k, f[k]);
    field.set(n.node, pres, p);
  }
  step.nodal["CONT_NOEU"] = std::move(field);
}

}  // namespace lunaster::engine::contact
