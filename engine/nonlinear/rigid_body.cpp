#include "engine/nonlinear/rigid_body.hpp"

#include "engine/nonlinear/reduction.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

namespace lunaster::engine {

namespace {

/// Bodies: per mesh node, a representative node of the connected set (by shared nodes) of
/// `cells` that holds it (union-find).
std::vector<int> body_roots(const Mesh& mesh, const std::vector<int>& cells) {
  std::vector<int> parent(mesh.n_nodes());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  };
  for (int c : cells)
    for (int k = 1; k < mesh.cell_n_nodes(c); ++k) parent[find(mesh.cell(c)[k])] = find(mesh.cell(c)[0]);
  for (int v = 0; v < mesh.n_nodes(); ++v) parent[v] = find(v);
  return parent;
}

/// Connected component (by shared nodes) of the model's volume cells containing `node`.
std::vector<int> body_of_node(const FeModel& model, int node) {
  const Mesh& mesh = *model.mesh;
  const std::vector<int> cells = model.volume_cells();
  const std::vector<int> root = body_roots(mesh, cells);
  std::vector<int> body;
  for (int c : cells)
    if (root[mesh.cell(c)[0]] == root[node]) body.push_back(c);
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

/// Smallest eigenvalue of the modes' Gram matrix (modes O(1), one row per held equation)
/// below which a motion is unheld: a held motion gives at least (distance between the
/// holding nodes / body size)^2, a free one round-off.
constexpr double kUnheldEigenvalue = 1e-12;

/// `pivot`: the factorisation's failure; a weak pivot (one that lost more digits than
/// allowed, not a zero or negative one) carries the digits lost (value) and allowed (limit).
SolveError rigid_body_error(const FeModel& model, const std::vector<int>& body, int node, int component, double t,
                            const Failure& pivot = {}) {
  char inst[32];
  std::snprintf(inst, sizeof inst, "%.6e", t);
  const Mesh& mesh = *model.mesh;
  std::string weak;
  std::vector<std::string> hints = {"nothing holds this body in that direction: impose a displacement on it,",
                                    "or, if only contact holds it, make its contact active from the first iteration",
                                    "so that the contact pressure carries the load from the start"};
  if (pivot.value > 0.0) {
    char digits[96];
    std::snprintf(digits, sizeof digits, "; a pivot lost %.1f significant digits, more than the %d allowed",
                  pivot.value, pivot.limit);
    weak = digits;
    hints.push_back("if a much softer part holds it (a stiffness ratio near 1e-" + std::to_string(pivot.limit) +
                    "), allow more digits or go on past singular pivots");
  }
  SolveError err("the stiffness matrix is singular at instant " + std::string(inst) + ": " + body_name(mesh, body) +
                     " has a rigid-body mode (free to move along " + component_name(component) +
                     ", detected at node " + mesh.node_names[node] + weak + ")",
                 std::move(hints));
  err.failure().what = Failure::What::RigidBodyMode;
  err.failure().value = pivot.value;
  err.failure().limit = pivot.limit;
  return err;
}

}  // namespace

std::optional<SolveError> find_rigid_body_mode(const FeModel& model, const DofMap& dofs,
                                               const std::vector<int>& free_index,
                                               const SparseMatrix& elastic, double t, SingularityTest test) {
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
  test.stop = true;
  FactorSettings settings;
  settings.singularity = test;
  chol->configure(settings);
  int column = -1;
  Failure pivot;
  try {
    chol->factorize(k, MatrixKind::SymmetricPositiveDefinite);
  } catch (const SolveError& err) {
    column = chol->failed_column();
    pivot = err.failure();
  }
  if (column < 0 || column >= static_cast<int>(back.size())) return std::nullopt;
  const int eq = back[column];
  return rigid_body_error(model, body_of_node(model, dofs.node_of(eq)), dofs.node_of(eq), dofs.component_of(eq), t,
                          pivot);
}

std::optional<SolveError> find_unheld_body(const FeModel& model, const DofMap& dofs,
                                           const std::vector<int>& free_index, const std::vector<int>& held,
                                           double t) {
  const Mesh& mesh = *model.mesh;
  const std::vector<int> cells = model.volume_cells();
  if (cells.empty()) return std::nullopt;
  std::vector<char> holds(dofs.n_dofs(), 0);
  for (int eq = 0; eq < dofs.n_dofs(); ++eq) holds[eq] = free_index[eq] < 0;
  for (int eq : held) holds[eq] = 1;
  // Bodies: connected sets of cells (by shared nodes), in the order of their first cell.
  const std::vector<int> root = body_roots(mesh, cells);
  std::vector<std::vector<int>> body_cells;
  std::vector<int> body_index(mesh.n_nodes(), -1);
  for (int c : cells) {
    const int r = root[mesh.cell(c)[0]];
    if (body_index[r] < 0) body_index[r] = static_cast<int>(body_cells.size()), body_cells.emplace_back();
    body_cells[body_index[r]].push_back(c);
  }
  // Each body's nodes in increasing order, from one pass over the nodes (the bodies share
  // none); sorting every cell's nodes instead took 4 % of a glued 2D run of 68,000 cells.
  std::vector<char> in_model(mesh.n_nodes(), 0);
  for (int c : cells)
    for (int k = 0; k < mesh.cell_n_nodes(c); ++k) in_model[mesh.cell(c)[k]] = 1;
  std::vector<std::vector<int>> body_nodes(body_cells.size());
  for (int v = 0; v < mesh.n_nodes(); ++v)
    if (in_model[v]) body_nodes[body_index[root[v]]].push_back(v);
  const int dim = dofs.dim();
  for (size_t b = 0; b < body_cells.size(); ++b) {
    const std::vector<int>& body = body_cells[b];
    const std::vector<int>& nodes = body_nodes[b];
    // The body's rigid-body motions: translations and rotations (AXIS: the axial translation
    // only), about the body's centre, lengths scaled by its size so that every mode is O(1).
    double centre[3] = {0, 0, 0}, size = 0.0;
    for (int n : nodes)
      for (int k = 0; k < 3; ++k) centre[k] += mesh.node(n)[k] / static_cast<double>(nodes.size());
    for (int n : nodes)
      for (int k = 0; k < 3; ++k) size = std::max(size, std::abs(mesh.node(n)[k] - centre[k]));
    if (!(size > 0.0)) size = 1.0;
    const Modelisation kind = model.modelisation[body.front()];
    const int n_modes = kind == Modelisation::Axisymmetric ? 1 : dim == 3 ? 6 : 3;
    // mode(n, k, j): component k of rigid motion j at node n.
    auto mode = [&](int n, int k, int j) -> double {
      if (kind == Modelisation::Axisymmetric) return k == DY ? 1.0 : 0.0;
      if (j < dim) return k == j ? 1.0 : 0.0;
      double x[3];
      for (int i = 0; i < 3; ++i) x[i] = (mesh.node(n)[i] - centre[i]) / size;
      if (dim == 2) return k == DX ? -x[1] : k == DY ? x[0] : 0.0;
      // rotations about X, Y, Z: omega x (x - centre)
      const int axis = j - 3;
      double w[3] = {0, 0, 0};
      w[axis] = 1.0;
      const double r[3] = {w[1] * x[2] - w[2] * x[1], w[2] * x[0] - w[0] * x[2], w[0] * x[1] - w[1] * x[0]};
      return r[k];
    };
    // Gram matrix of the modes on the held equations: a (near) zero eigenvalue is a motion
    // that no condition opposes.
    Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(n_modes, n_modes);
    for (int n : nodes)
      for (int k = 0; k < dim; ++k) {
        const int eq = dofs.dof(n, k);
        if (eq < 0 || !holds[eq]) continue;
        Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 6, 1> row(n_modes);  // no heap
        for (int j = 0; j < n_modes; ++j) row[j] = mode(n, k, j);
        gram.noalias() += row * row.transpose();
      }
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(gram);
    if (eig.info() != Eigen::Success || eig.eigenvalues()[0] > kUnheldEigenvalue) continue;
    // The free motion; name the node and component where it moves most (the first such).
    const Eigen::VectorXd alpha = eig.eigenvectors().col(0);
    std::vector<double> motion(nodes.size() * static_cast<size_t>(dim));
    for (size_t i = 0; i < nodes.size(); ++i)
      for (int k = 0; k < dim; ++k) {
        double v = 0.0;
        for (int j = 0; j < n_modes; ++j) v += alpha[j] * mode(nodes[i], k, j);
        motion[i * dim + k] = std::abs(v);
      }
    const double largest = *std::max_element(motion.begin(), motion.end());
    for (size_t i = 0; i < nodes.size(); ++i)
      for (int k = 0; k < dim; ++k)
        if (motion[i * dim + k] >= (1.0 - 1e-9) * largest && dofs.dof(nodes[i], k) >= 0)
          return rigid_body_error(model, body, nodes[i], k, t);
  }
  return std::nullopt;
}

namespace {

/// Per free equation: a displacement whose column in `system` is a unit diagonal alone (an
/// equation eliminated by a relation), while K_ff's column has more.
std::vector<char> eliminated_displacements(const std::vector<char>& displacement, const SparseMatrix& k_ff,
                                           const SparseMatrix& system) {
  std::vector<char> out(displacement.size(), 0);
  for (int j = 0; j < static_cast<int>(displacement.size()); ++j) {
    if (!displacement[j]) continue;
    int entries = 0;
    bool unit = false;
    for (SparseMatrix::InnerIterator it(system, j); it; ++it)
      if (it.value() != 0.0) ++entries, unit = it.row() == j && it.value() == 1.0;
    int stiffness = 0;
    for (SparseMatrix::InnerIterator it(k_ff, j); it; ++it) stiffness += it.value() != 0.0;
    out[j] = entries == 1 && unit && stiffness > 1;
  }
  return out;
}

}  // namespace

SparseMatrix contact_hold_stiffness(const DofMap& dofs, const std::vector<int>& free_index, const SparseMatrix& k_ff,
                                    const SparseMatrix& system, bool increment) {
  const int n = static_cast<int>(k_ff.cols());
  LUNASTER_ASSERT(system.rows() == n && system.cols() == n, "contact hold: the system and K_ff differ in size");
  std::vector<char> displacement(n, 0);
  for (int eq = 0; eq < dofs.n_dofs(); ++eq)
    if (free_index[eq] >= 0) displacement[free_index[eq]] = is_displacement(dofs.component_of(eq));
  const std::vector<char> eliminated = eliminated_displacements(displacement, k_ff, system);
  const auto kept = [&](int j) { return displacement[j] && !eliminated[j]; };
  // The contact terms on the displacements, and each multiplier column's couplings to them.
  const SparseMatrix terms = increment ? system : SparseMatrix(system - k_ff);
  std::vector<Triplet> on_displacements, couplings;
  for (int j = 0; j < n; ++j)
    for (SparseMatrix::InnerIterator it(terms, j); it; ++it) {
      const int i = static_cast<int>(it.row());
      if (it.value() == 0.0 || !kept(i)) continue;
      if (kept(j)) on_displacements.emplace_back(i, j, it.value());
      else if (!displacement[j]) couplings.emplace_back(j, i, it.value());  // row: the multiplier
    }
  SparseMatrix contact(n, n), b(n, n);
  contact.setFromTriplets(on_displacements.begin(), on_displacements.end());
  b.setFromTriplets(couplings.begin(), couplings.end());
  contact += SparseMatrix(b.transpose() * b);
  double k_largest = 0.0, contact_largest = 0.0;
  for (int j = 0; j < n; ++j)
    if (displacement[j]) k_largest = std::max(k_largest, std::abs(k_ff.coeff(j, j)));
  for (int j = 0; j < n; ++j) contact_largest = std::max(contact_largest, std::abs(contact.coeff(j, j)));
  SparseMatrix held = k_ff;
  if (contact_largest > 0.0) held += (k_largest / contact_largest) * contact;
  std::vector<Triplet> pinned;
  for (int j = 0; j < n; ++j)
    if (eliminated[j]) pinned.emplace_back(j, j, k_largest);
  SparseMatrix pins(n, n);
  pins.setFromTriplets(pinned.begin(), pinned.end());
  held += pins;
  held.makeCompressed();
  return held;
}

std::string rigid_body_mode_of(const SolveError& rigid) {
  // rigid_body_error's message: "the stiffness matrix is singular at instant T: <the mode>".
  const std::string& message = rigid.message();
  const size_t colon = message.find(": ");
  return colon == std::string::npos ? message : message.substr(colon + 2);
}

SolveError diagnose_singular_system(const FeModel& model, const DofMap& dofs, const std::vector<int>& free_index,
                                    const SparseMatrix& elastic, const SolveError& original, double t,
                                    SingularityTest test, bool contact_terms, const std::string& approximations) {
  if (auto rigid = find_rigid_body_mode(model, dofs, free_index, elastic, t, test)) return *rigid;
  char inst[32];
  std::snprintf(inst, sizeof inst, "%.6e", t);
  // Factors approximate by request: the approximation is named, not the system's conditioning.
  const std::string approximate = approximations.empty() ? std::string()
                                  : "the system at instant " + std::string(inst) + ", factorised approximately as "
                                        "asked (" + approximations + "), could not be solved to the accuracy asked: ";
  if (!contact_terms) {
    SolveError err((approximate.empty() ? "the system at instant " + std::string(inst) +
                                              " is too ill-conditioned for the accuracy asked of its solve: "
                                        : approximate) +
                       original.message(),
                   {"the stiffness is regular (no rigid-body mode) but its solve did not reach the accuracy asked: "
                    "a part far softer than another, or an accuracy below round-off"});
    err.failure().what = Failure::What::SolveAccuracy;
    return err;
  }
  SolveError err((approximate.empty() ? "the system at instant " + std::string(inst) +
                                            " is singular or too ill-conditioned for the linear solver: "
                                      : approximate) +
                     original.message(),
                 {"the elastic stiffness alone is regular, so the trouble comes from the contact terms",
                  "check that the contact surfaces face each other, and that the penalty or augmentation "
                  "coefficient is not many orders of magnitude above the material stiffness E / h: the condition "
                  "number grows with it until double precision cannot resolve the system"});
  err.failure().what = Failure::What::ContactConditioning;
  // A pivot that lost more digits than allowed, not one the factorisation could not take:
  // allowing more digits may go on (the solve's own accuracy is still checked).
  if (original.failure().value > 0.0) {
    err.failure().value = original.failure().value;
    err.failure().limit = original.failure().limit;
    err.add_hint("or allow more than " + std::to_string(original.failure().limit) +
                 " lost digits: the solve's accuracy is still checked");
  }
  return err;
}

}  // namespace lunaster::engine
