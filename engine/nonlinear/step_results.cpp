#include "engine/nonlinear/step_results.hpp"

#include <string>

#include "engine/assembly/point_fields.hpp"

namespace lunaster::engine {

namespace {

/// The components a displacement result reports: the displacements of the model's dimension
/// and the contact multipliers the DOF map carries; the linear relations' multipliers stay out.
std::vector<int> reported_components(const DofMap& dofs) {
  std::vector<char> carried(N_COMPONENTS, 0);
  for (int eq = 0; eq < dofs.n_dofs(); ++eq) carried[dofs.component_of(eq)] = 1;
  std::vector<int> out;
  for (int c = 0; c < N_COMPONENTS; ++c) {
    const bool relation = c >= LAGR_DX && c <= LAGR_DZ;
    if (is_displacement(c) ? c < dofs.dim() : carried[c] && !relation) out.push_back(c);
  }
  return out;
}

void resize(NodalField& f, int nodes) {
  f.values.resize(static_cast<size_t>(nodes) * f.components.size(), 0.0);
  f.defined.resize(static_cast<size_t>(nodes) * f.components.size(), 0);
  f.n_nodes = nodes;
}

}  // namespace

StepResults::StepResults(const DofMap& dofs, int model_nodes, const ContactHook* hook, int hook_nodes)
    : dofs_(dofs), model_nodes_(model_nodes), hook_(hook), hook_nodes_(hook_nodes),
      components_(reported_components(dofs)) {}

NodalField StepResults::displacement(const Vector& u) const {
  std::vector<std::string> names;
  for (int c : components_) names.push_back(component_name(c));
  NodalField depl(names, model_nodes_);
  for (int node = 0; node < model_nodes_; ++node)
    for (size_t c = 0; c < components_.size(); ++c) {
      const int eq = dofs_.dof(node, components_[c]);
      if (eq >= 0) depl.set(node, static_cast<int>(c), u[eq]);
    }
  return depl;
}

ResultStep StepResults::step(int index, double inst, const Vector& u, bool initial) const {
  ResultStep step;
  step.nume_ordre = index;
  step.inst = inst;
  NodalField& depl = step.nodal["DEPL"] = displacement(u);
  if (points_) {
    step.elga["SIEF_ELGA"] = points_behaviours_ ? stresses_at_points(*points_behaviours_, dofs_, u, *points_)
                                                : stresses_at_points(*points_model_, *points_);
    step.elga["VARI_ELGA"] = variables_at_points(*points_model_, *points_);
  }
  if (!hook_) return step;
  // In parts the hook's nodes are the whole surfaces' part's: its fields are written on those
  // and kept on the part's nodes (the ones beyond are other ranks' and theirs to give).
  if (hook_nodes_ != model_nodes_) resize(depl, hook_nodes_);
  if (initial) hook_->write_initial_fields(step);
  else hook_->write_fields(u, step);
  if (hook_nodes_ != model_nodes_)
    for (auto& [name, field] : step.nodal) resize(field, model_nodes_);
  return step;
}

}  // namespace lunaster::engine
