#include "engine/nonlinear/rigid_body.hpp"

#include "engine/nonlinear/reduction.hpp"

#include <algorithm>
#include <cstdio>
#include <numeric>

namespace lunaster::engine {

namespace {

/// Connected component (by shared nodes) of the model's volume cells containing `node`.
std::vector<int> body_of_node(const FeModel& model, int node) {
  const Mesh& mesh = *model.mesh;
  const std::vector<int> cells = model.volume_cells();
  std::vector<int> parent(mesh.n_nodes());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  };
  for (int c : cells)
    for (int k = 1; k < mesh.cell_n_nodes(c); ++k) parent[find(mesh.cell(c)[k])] = find(mesh.cell(c)[0]);
  std::vector<int> body;
  const int root = find(node);
  for (int c : cells)
    if (find(mesh.cell(c)[0]) == root) body.push_back(c);
  return body;
}

/// Names of the cell groups that contain every cell of `body`, smallest first.
std::string body_name(const Mesh& mesh, const std::vector<int>& body) {
  std::vector<std::pair<size_t, std::string>> names;
  for (const auto& group : mesh.cell_groups) {
    const std::vector<int>& cells = group.second;  // not a structured binding: clang 14 cannot capture those
    if (cells.size() < body.size()) continue;
    bool all = std::all_of(body.begin(), body.end(),
                           [&](int c) { return std::binary_search(cells.begin(), cells.end(), c); });
    if (all) names.emplace_back(cells.size(), group.first);
  }
  std::sort(names.begin(), names.end());
  if (names.empty()) return "the body made of " + std::to_string(body.size()) + " cells";
  return "the body " + names.front().second + " (" + std::to_string(body.size()) + " cells)";
}

}  // namespace

std::optional<SolveError> find_rigid_body_mode(const FeModel& model, const DofMap& dofs,
                                               const std::vector<int>& free_index,
                                               const SparseMatrix& elastic, double t) {
  // Reduced elastic matrix on the free displacement equations only (`elastic` is on the
  // free equations, numbered by free_index).
  std::vector<int> reduced(elastic.cols(), -1), back;
  for (int eq = 0; eq < dofs.n_dofs(); ++eq)
    if (free_index[eq] >= 0 && is_displacement(dofs.component_of(eq))) {
      reduced[free_index[eq]] = static_cast<int>(back.size());
      back.push_back(eq);
    }
  SparseMatrix k = restrict_matrix(elastic, reduced, static_cast<int>(back.size()));
  auto chol = make_linear_solver(SolverKind::Cholmod);
  int column = -1;
  try {
    chol->factorize(k, MatrixKind::SymmetricPositiveDefinite);
  } catch (const SolveError&) {
    column = chol->failed_column();
  }
  char inst[32];
  std::snprintf(inst, sizeof inst, "%.6e", t);
  if (column < 0 || column >= static_cast<int>(back.size())) return std::nullopt;
  const int eq = back[column];
  const int node = dofs.node_of(eq);
  const Mesh& mesh = *model.mesh;
  const std::string who = body_name(mesh, body_of_node(model, node));
  SolveError err(
      "the stiffness matrix is singular at instant " + std::string(inst) + ": " + who +
          " has a rigid-body mode (free to move along " + component_name(dofs.component_of(eq)) + ", detected at node " +
          mesh.node_names[node] + ")",
      {"nothing holds this body in that direction: impose a displacement on it,",
       "or, if only contact holds it, make its contact active from the first iteration",
       "so that the contact pressure carries the load from the start"});
  err.failure().what = Failure::What::RigidBodyMode;
  return err;
}

SolveError diagnose_singular_system(const FeModel& model, const DofMap& dofs, const std::vector<int>& free_index,
                                    const SparseMatrix& elastic, const SolveError& original, double t) {
  if (auto rigid = find_rigid_body_mode(model, dofs, free_index, elastic, t)) return *rigid;
  char inst[32];
  std::snprintf(inst, sizeof inst, "%.6e", t);
  SolveError err("the system at instant " + std::string(inst) +
                     " is singular or too ill-conditioned for the linear solver: " + original.message(),
                 {"the elastic stiffness alone is regular, so the trouble comes from the contact terms",
                  "check that the contact surfaces face each other, and that the penalty or augmentation "
                  "coefficient is not many orders of magnitude above the material stiffness E / h: the condition "
                  "number grows with it until double precision cannot resolve the system"});
  err.failure().what = Failure::What::ContactConditioning;
  return err;
}

}  // namespace lunaster::engine
