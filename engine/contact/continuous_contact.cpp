#include "engine/contact/continuous_contact.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "engine/contact/integration_rules.hpp"
#include "engine/contact/surface_element.hpp"
#include "engine/core/error.hpp"

namespace lunaster::engine::contact {


ContinuousContact::ContinuousContact(const ContactDefinition& definition, const Mesh& mesh, int dim)
    : ContactHookBase(definition, mesh, dim) {
  std::set<int> slaves, geometry;
  for (size_t z = 0; z < def_.zones.size(); ++z) {
    const ContactZone& zone = def_.zones[z];
    masters_.push_back(std::make_unique<MasterSurface>(mesh, zone.master_cells, false));
    min_edge_.push_back(smallest_edge(mesh, zone.slave_cells));
    for (int c : zone.master_cells)
      for (int a = 0; a < mesh.cell_n_nodes(c); ++a) geometry.insert(mesh.cell(c)[a]);
    for (int c : zone.slave_cells) {
      const CellType t = mesh.cell_types[c];
      if (!is_surface_type(t) || topological_dim(t) != dim - 1)
        throw DeckError("contact zone " + std::to_string(z + 1) + ": slave cell " + cell_label(mesh, c) +
                        " is a " + surface_type_name(t) + ", expected a boundary cell of dimension " +
                        std::to_string(dim - 1));
      const auto rule = contact_integration_rule(t, zone.integration, zone.integration_order, zone.sub_elements);
      for (const auto& q : rule) {
        ContinuousPoint p;
        p.zone = static_cast<int>(z);
        p.slave_cell = c;
        p.xi[0] = q.xi[0], p.xi[1] = q.xi[1];
        p.weight = q.weight;
        p.n_slave = surface_n_nodes(t);
        std::copy(mesh.cell(c), mesh.cell(c) + p.n_slave, p.slave_nodes);
        surface_shape(t, p.xi, p.phi, nullptr, nullptr);
        points_.push_back(p);
      }
      for (int a = 0; a < mesh.cell_n_nodes(c); ++a) slaves.insert(mesh.cell(c)[a]), geometry.insert(mesh.cell(c)[a]);
    }
  }
  slave_nodes_.assign(slaves.begin(), slaves.end());
  geometry_nodes_.assign(geometry.begin(), geometry.end());
}

void ContinuousContact::add_dofs(DofMap& dofs) {
  for (int node : slave_nodes_) dofs.add(node, LAGS_C);
  store_dofs(dofs);
}

double ContinuousContact::rho(int zone) const {
  const ContactZone& z = def_.zones[zone];
  return penalty() ? z.coef_pena : z.coef_cont;
}

MatrixKind ContinuousContact::matrix_kind() const {
  return penalty() ? MatrixKind::General : MatrixKind::SymmetricIndefinite;
}

double ContinuousContact::multiplier(const Vector& u, const ContinuousPoint& p) const {
  double lambda = 0.0;
  for (int a = 0; a < p.n_slave; ++a) {
    const int eq = dofs_.dof(p.slave_nodes[a], LAGS_C);
    if (eq >= 0) lambda += p.phi[a] * u[eq];
  }
  return lambda;
}

void ContinuousContact::set_all_active(bool active) {
  for (auto& p : points_) p.active = active && p.paired;
}

void ContinuousContact::pair(const Vector& u) {
  const std::vector<double> xyz = current_coordinates(u);
  for (auto& m : masters_) m->update(xyz);
  double slave_xyz[3 * kMaxSurfaceNodes];
  for (auto& p : points_) {
    const CellType t = mesh_.cell_types[p.slave_cell];
    for (int a = 0; a < p.n_slave; ++a)
      for (int i = 0; i < 3; ++i) slave_xyz[3 * a + i] = xyz[3 * static_cast<size_t>(p.slave_nodes[a]) + i];
    const SurfacePoint sp = surface_point(t, slave_xyz, p.xi);
    const MasterSurface& master = *masters_[p.zone];
    const MasterProjection mp = master.project(sp.x, def_.zones[p.zone].tole_proj_ext);
    const bool regular = sp.jacobian > 0.0 && std::isfinite(sp.jacobian);
    p.paired = mp.found && regular;
    p.wjac = regular ? p.weight * sp.jacobian : 0.0;
    p.gap = LinearGap{};
    if (!p.paired) {
      p.active = false;
      p.master_cell = -1;
      continue;
    }
    p.master_cell = mp.cell;
    p.xi_master[0] = mp.xi[0], p.xi_master[1] = mp.xi[1];
    std::copy(mp.normal, mp.normal + 3, p.normal);
    const int k = master.local_index(mp.cell);
    double nm[kMaxSurfaceNodes];
    surface_shape(master.geometry_type(k), mp.xi, nm, nullptr, nullptr);
    const auto& mnodes = master.cell_nodes(k);
    p.gap = make_linear_gap(mesh_.coords, dofs_, dim_, p.slave_nodes, p.phi, p.n_slave, mnodes.data(), nm,
                            static_cast<int>(mnodes.size()), p.normal);
  }
}

void ContinuousContact::init_statuses(const Vector& u, const Log& log) {
  int n_active = 0, n_unpaired = 0;
  for (auto& p : points_) {
    const ContactZone& zone = def_.zones[p.zone];
    switch (zone.init) {
      case ContactInit::Yes: p.active = p.paired; break;
      case ContactInit::No: p.active = false; break;
      case ContactInit::Interpenetrated: p.active = p.paired && p.gap.value(u) <= 1e-6 * min_edge_[p.zone]; break;
    }
    n_active += p.active;
    n_unpaired += !p.paired;
  }
  std::ostringstream msg;
  msg << "contact: " << points_.size() << " contact points, " << n_active << " initially in contact, " << n_unpaired
      << " not paired with the master surface";
  log.info(msg.str());
}

bool ContinuousContact::status_of(const Vector& u, const ContinuousPoint& p) const {
  if (!p.paired) return false;
  const double g = p.gap.value(u);
  if (penalty()) return g < 0.0;
  return multiplier(u, p) + rho(p.zone) * g < 0.0;
}

int ContinuousContact::update_statuses(const Vector& u, const Log& log) {
  int changed = 0;
  for (auto& p : points_) {
    const bool s = status_of(u, p);
    changed += s != p.active;
    p.active = s;
  }
  return changed;
}

void ContinuousContact::first_pairing_report(const Log& log) {
  // Incompatible slave/master cell types (compatibility.hpp) are reported once, by the
  // command defining the zone (DEFI_CONTACT / AFFE_CHAR_MECA), not again here.
  for (size_t z = 0; z < masters_.size(); ++z)
    if (masters_[z]->n_flipped() > 0)
      log.warning("contact zone " + std::to_string(z + 1) + ": " + std::to_string(masters_[z]->n_flipped()) +
                  " master cell(s) oriented towards their own body; their normal was reversed "
                  "(orient the master surface outwards, e.g. ORIE_PEAU)");
}

void ContinuousContact::add_point(const Vector& u, const ContinuousPoint& p, LocalTangent& tangent,
                                  Vector& residual) const {
  const double r = rho(p.zone), wj = p.wjac, wm = wj;
  if (wj == 0.0) return;
  const double lambda = multiplier(u, p);
  int leq[8];
  for (int a = 0; a < p.n_slave; ++a) leq[a] = dofs_.dof(p.slave_nodes[a], LAGS_C);
  if (!p.active) {
    for (int a = 0; a < p.n_slave; ++a) {
      residual[leq[a]] += -(wm / r) * p.phi[a] * lambda;
      for (int b = 0; b < p.n_slave; ++b) tangent.add(leq[a], leq[b], -(wm / r) * p.phi[a] * p.phi[b]);
    }
    return;
  }
  const double g = p.gap.value(u);
  if (penalty()) {
    add_gradient(p.gap, wj * r * g, residual);
    tangent.add_outer(p.gap, p.gap, wj * r);
    for (int a = 0; a < p.n_slave; ++a) {
      residual[leq[a]] += wj * p.phi[a] * (g - lambda / r);
      for (int k = 0; k < p.gap.n; ++k) tangent.add(leq[a], p.gap.eq[k], wj * p.phi[a] * p.gap.coef[k]);
      for (int b = 0; b < p.n_slave; ++b) tangent.add(leq[a], leq[b], -(wj / r) * p.phi[a] * p.phi[b]);
    }
    return;
  }
  add_gradient(p.gap, wj * (lambda + r * g), residual);
  tangent.add_outer(p.gap, p.gap, wj * r);
  for (int a = 0; a < p.n_slave; ++a) {
    residual[leq[a]] += wj * p.phi[a] * g;
    for (int k = 0; k < p.gap.n; ++k) {
      const double v = wj * p.phi[a] * p.gap.coef[k];
      tangent.add(leq[a], p.gap.eq[k], v);
      tangent.add(p.gap.eq[k], leq[a], v);
    }
  }
}

void ContinuousContact::add_to_system(const Vector& u, std::vector<Triplet>& tangent, Vector& residual) {
  if (def_.geometry_loop == FixedPointOrNewton::Newton) pair(u);
  if (statuses_in_newton())
    for (auto& p : points_) p.active = status_of(u, p);
  // The points of a slave cell are consecutive and share their DOFs: their terms are
  // summed per cell and emitted once.
  LocalTangent local;
  int cell = -1;
  for (const auto& p : points_) {
    if (p.slave_cell != cell) local.flush(tangent), cell = p.slave_cell;
    add_point(u, p, local, residual);
  }
  local.flush(tangent);
}

void ContinuousContact::write_fields(const Vector& u, ResultStep& step) const {
  std::vector<std::string> cmps = {"CONT", "JEU", "RN", "RNX", "RNY"};
  if (dim_ == 3) cmps.push_back("RNZ");
  NodalField field(cmps, mesh_.n_nodes());
  // Nodal contact forces on the slave nodes: f_a = -sum w J (lambda + rho g) phi_a n.
  std::vector<double> force(3 * static_cast<size_t>(mesh_.n_nodes()), 0.0);
  for (const auto& p : points_) {
    if (!p.active) continue;
    const double g = p.gap.value(u);
    const double traction = penalty() ? rho(p.zone) * g : multiplier(u, p) + rho(p.zone) * g;
    for (int a = 0; a < p.n_slave; ++a)
      for (int k = 0; k < 3; ++k)
        force[3 * static_cast<size_t>(p.slave_nodes[a]) + k] -= p.wjac * traction * p.phi[a] * p.normal[k];
  }
  // Nodal gap: each slave node projected on the master surface in the current configuration.
  const std::vector<double> xyz = current_coordinates(u);
  std::vector<std::unique_ptr<MasterSurface>> current;
  for (const auto& m : masters_) {
    current.push_back(std::make_unique<MasterSurface>(*m));
    current.back()->update(xyz);
  }
  std::vector<int> zone_of(mesh_.n_nodes(), -1);
  for (const auto& p : points_)
    for (int a = 0; a < p.n_slave; ++a) zone_of[p.slave_nodes[a]] = p.zone;
  for (int node : slave_nodes_) {
    const int z = zone_of[node];
    const MasterProjection mp = current[z]->project(&xyz[3 * static_cast<size_t>(node)], def_.zones[z].tole_proj_ext);
    double gap = 0.0;
    if (mp.found)
      for (int k = 0; k < 3; ++k) gap += (xyz[3 * static_cast<size_t>(node) + k] - mp.x[k]) * mp.normal[k];
    const double lambda = u[dofs_.dof(node, LAGS_C)];
    const bool in_contact = mp.found && (penalty() ? gap < 0.0 : lambda + rho(z) * gap < 0.0);
    const double* f = &force[3 * static_cast<size_t>(node)];
    field.set(node, 0, in_contact ? 1.0 : 0.0);
    field.set(node, 1, gap);
    field.set(node, 2, std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]));
    for (int k = 0; k < dim_; ++k) field.set(node, 3 + k, f[k]);
  }
  step.nodal["CONT_NOEU"] = std::move(field);
}

}  // namespace lunaster::engine::contact
