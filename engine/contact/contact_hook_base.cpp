#include "engine/contact/contact_hook_base.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "engine/contact/surface_element.hpp"
#include "engine/core/error.hpp"

namespace lunaster::engine::contact {

std::string cell_label(const Mesh& mesh, int cell) {
  if (cell >= 0 && cell < static_cast<int>(mesh.cell_names.size())) return mesh.cell_names[cell];
  return "#" + std::to_string(cell);
}

std::string node_label(const Mesh& mesh, int node) {
  if (node >= 0 && node < static_cast<int>(mesh.node_names.size())) return mesh.node_names[node];
  return "#" + std::to_string(node);
}

double smallest_edge(const Mesh& mesh, const std::vector<int>& cells) {
  double h = 1e300;
  for (int c : cells) {
    const CellType t = mesh.cell_types[c];
    const int nv = surface_n_vertices(t);
    const int n_edges = nv == 2 ? 1 : nv;
    for (int e = 0; e < n_edges; ++e) {
      const double* a = mesh.node(mesh.cell(c)[e]);
      const double* b = mesh.node(mesh.cell(c)[(e + 1) % nv]);
      h = std::min(h, std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                                (a[2] - b[2]) * (a[2] - b[2])));
    }
  }
  return h;
}

ContactHookBase::ContactHookBase(const ContactDefinition& definition, const Mesh& mesh, int dim)
    : def_(definition), mesh_(mesh), dim_(dim) {
  LUNASTER_ASSERT(dim == 2 || dim == 3, "contact: dimension must be 2 or 3");
}

std::vector<double> ContactHookBase::current_coordinates(const Vector& u) const {
  std::vector<double> xyz(mesh_.coords);
  const int n = static_cast<int>(xyz.size() / 3);
  const int nmap = dofs_.n_nodes();
  for (int node = 0; node < std::min(n, nmap); ++node)
    for (int k = 0; k < dim_; ++k) {
      const int eq = dofs_.dof(node, k);
      if (eq >= 0 && eq < u.size()) xyz[3 * static_cast<size_t>(node) + k] += u[eq];
    }
  return xyz;
}

void ContactHookBase::pair_and_record(const Vector& u) {
  pair(u);
  u_at_pairing_ = u;
  ++n_pairings_;
}

double ContactHookBase::geometric_residual(const Vector& u) const {
  double du_max = 0.0, u_max = 0.0;
  for (int node : geometry_nodes()) {
    double du2 = 0.0, u2 = 0.0;
    for (int k = 0; k < dim_; ++k) {
      const int eq = dofs_.dof(node, k);
      if (eq < 0) continue;
      const double prev = eq < u_at_pairing_.size() ? u_at_pairing_[eq] : 0.0;
      du2 += (u[eq] - prev) * (u[eq] - prev);
      u2 += u[eq] * u[eq];
    }
    du_max = std::max(du_max, std::sqrt(du2));
    u_max = std::max(u_max, std::sqrt(u2));
  }
  return u_max > 0.0 ? du_max / u_max : 0.0;
}

void ContactHookBase::begin_step(const Vector& u, const Log& log) {
  n_status_iter_ = 0;
  n_geom_iter_ = 0;
  n_pairings_ = 0;
  pair_and_record(u);
  if (first_step_) {
    first_pairing_report(log);
    init_statuses(u, log);
    first_step_ = false;
  }
}

bool ContactHookBase::settle(const Vector& u, const Log& log) {
  // Status loop (inside the geometry loop, as code_aster's fixed points).
  const int changed = update_statuses(u, log);
  if (changed > 0) {
    ++n_status_iter_;
    std::ostringstream msg;
    msg << "contact: " << changed << " status change(s), status iteration " << n_status_iter_;
    log.info(msg.str());
    if (n_status_iter_ > def_.iter_cont_maxi)
      throw ConvergenceError("contact status loop did not settle after " + std::to_string(def_.iter_cont_maxi) +
                           " iterations (ITER_CONT_MAXI): " + std::to_string(changed) +
                           " contact point(s) still change status",
                       {"points cycling between contact and no contact: try ALGO_RESO_CONT='NEWTON', "
                        "a different COEF_CONT, or a finer/compatible mesh"});
    return false;
  }
  if (def_.geometry_loop == FixedPointOrNewton::Newton) return true;  // paired at every iteration
  switch (def_.reac_geom) {
    case GeometryUpdate::None: return true;
    case GeometryUpdate::Controlled:
      if (n_pairings_ >= def_.nb_iter_geom) return true;
      break;
    case GeometryUpdate::Automatic: {
      const double resi = geometric_residual(u);
      std::ostringstream msg;
      msg << "contact: geometric residual " << resi << " (RESI_GEOM " << def_.resi_geom << ")";
      log.info(msg.str());
      if (resi <= def_.resi_geom) return true;
      if (n_geom_iter_ >= def_.iter_geom_maxi)
        throw ConvergenceError("contact geometry loop did not converge after " + std::to_string(def_.iter_geom_maxi) +
                             " iterations (ITER_GEOM_MAXI): geometric residual " + std::to_string(resi) +
                             " > RESI_GEOM " + std::to_string(def_.resi_geom),
                         {"increase ITER_GEOM_MAXI, use smaller load increments or ALGO_RESO_GEOM='NEWTON'"});
      break;
    }
  }
  ++n_geom_iter_;
  n_status_iter_ = 0;
  pair_and_record(u);
  log.info("contact: new pairing (geometry iteration " + std::to_string(n_geom_iter_) + ")");
  return false;
}

}  // namespace lunaster::engine::contact
