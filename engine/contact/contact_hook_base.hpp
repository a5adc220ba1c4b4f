#pragma once
/// Shared machinery of the contact hooks: DOF access, current coordinates,
/// and the fixed-point loops on statuses (ITER_CONT_MAXI) and geometry
/// (REAC_GEOM / ITER_GEOM_MAXI) driven by `settle`.
#include <string>
#include <vector>

#include "engine/contact/contact_definition.hpp"
#include "engine/core/error.hpp"
#include "engine/nonlinear/static_solver.hpp"

namespace lunaster::engine::contact {

/// Base of the continuous and discrete hooks.
class ContactHookBase : public ContactHook {
 public:
  ContactHookBase(const ContactDefinition& definition, const Mesh& mesh, int dim);

  void begin_step(const Vector& u, const Log& log) override;
  bool settle(const Vector& u, const Log& log) override;

  /// Number of status / geometry fixed-point iterations done in this instant.
  int n_status_iterations() const { return n_status_iter_; }
  int n_pairings() const { return n_pairings_; }

 protected:
  /// Pairs every contact point with the master surface in the configuration X + u.
  virtual void pair(const Vector& u) = 0;
  /// Sets the statuses of the first instant from CONTACT_INIT (after the first pairing).
  virtual void init_statuses(const Vector& u, const Log& log) = 0;
  /// Re-evaluates the statuses at u; returns how many changed.
  virtual int update_statuses(const Vector& u, const Log& log) = 0;
  /// Called once after the first pairing (diagnostics such as compatibility warnings).
  virtual void first_pairing_report(const Log& log) {}
  /// Nodes whose motion defines the geometric residual (slave and master nodes).
  virtual const std::vector<int>& geometry_nodes() const = 0;
  /// True when statuses are updated inside Newton (ALGO_RESO_CONT='NEWTON').
  virtual bool statuses_in_newton() const { return false; }

  /// Stores the final numbering (call at the end of add_dofs).
  void store_dofs(const DofMap& dofs) { dofs_ = dofs; }
  /// Displacement component of a node in u (0 where the node has no such DOF).
  double displacement(const Vector& u, int node, int component) const {
    const int eq = dofs_.dof(node, component);
    return eq < 0 ? 0.0 : u[eq];
  }
  /// Current coordinates X + u of every mesh node (3 per node).
  std::vector<double> current_coordinates(const Vector& u) const;
  /// Calls pair(u) and records u as the pairing configuration.
  void pair_and_record(const Vector& u);
  /// max |u - u_at_pairing| / max |u| over geometry_nodes() (0 if u = 0 there).
  double geometric_residual(const Vector& u) const;

  const ContactDefinition def_;
  const Mesh& mesh_;
  const int dim_;
  DofMap dofs_;

 private:
  Vector u_at_pairing_;
  bool first_step_ = true;
  int n_status_iter_ = 0;
  int n_geom_iter_ = 0;
  int n_pairings_ = 0;
};

/// "M12" or "#11" when the mesh has no names.
std::string cell_label(const Mesh& mesh, int cell);
/// Smallest vertex-to-vertex edge length of surface cells (m).
double smallest_edge(const Mesh& mesh, const std::vector<int>& cells);
/// "N5" or "#4".
std::string node_label(const Mesh& mesh, int node);

}  // namespace lunaster::engine::contact
