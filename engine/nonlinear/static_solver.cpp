#include "engine/nonlinear/static_solver.hpp"

#include <cmath>
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <unordered_map>
#include <map>
#include <memory>
#include <optional>

#include "engine/assembly/assembly.hpp"
#include "engine/assembly/partition.hpp"
#include "engine/core/error.hpp"
#include "engine/core/memory.hpp"
#include "engine/core/two_workers.hpp"
#include "engine/nonlinear/constraints.hpp"
#include "engine/nonlinear/failure_diagnosis.hpp"
#include "engine/nonlinear/nodal_forces.hpp"
#include "engine/nonlinear/renumbered_hook.hpp"
#include "engine/nonlinear/rigid_body.hpp"
#include "engine/nonlinear/stopwatch.hpp"
#include "engine/nonlinear/system_matrix.hpp"
#include "engine/nonlinear/time_stepper.hpp"
#include "engine/parallel/mpi_runtime.hpp"
#include "engine/solver/backends.hpp"
#include "engine/solver/krylov.hpp"
#include "engine/solver/saddle_solver.hpp"
#include "engine/solver/singularity.hpp"

namespace lunaster::engine {

namespace {

std::string sci(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6e", v);
  return buf;
}

}  // namespace

StaticSolver::StaticSolver(const FeModel& model, const MechanicalLoads& loads, NewtonOptions options,
                           ContactHook* contact, const Log& log)
    : model_(model), loads_(loads), options_(options), contact_(contact), given_contact_(contact), log_(log) {
  LUNASTER_ASSERT(options_.reac_iter >= 0, "reac_iter must be >= 0");
  // The elastic matrix has no contact terms: the multiplier equations would be empty.
  LUNASTER_ASSERT(!(options_.elastic_matrix && contact_), "the elastic matrix is not for runs with contact");
}

void StaticSolver::number_unknowns(std::optional<NodeHalo>& node_halo) {
  in_parts_ = part_ != nullptr;
  contact_ = given_contact_;
  renumbered_contact_.reset();
  dofs_ = DofMap(*model_.mesh, model_.volume_cells(), model_.dim);
  if (in_parts_ && hook_part_) {
    // The hook's nodes beyond the part (contact surfaces, relations): ghosts with their
    // displacement unknowns.
    LUNASTER_ASSERT(contact_ && hook_part_->n_owned_nodes == part_->n_owned_nodes &&
                        hook_part_->mesh.n_nodes() >= part_->mesh.n_nodes(),
                    "the hook's nodes are the part's and more, for a run with a hook");
    dofs_.add_nodes(hook_part_->mesh.n_nodes());
    for (int v = part_->mesh.n_nodes(); v < hook_part_->mesh.n_nodes(); ++v)
      for (int c = 0; c < model_.dim; ++c) dofs_.add(v, c);
  }
  const int displacement_dofs = dofs_.n_dofs();
  // In parts, the exchanges of the part's nodes (the owners' Dirichlet conditions for the hook,
  // then the numbering across the ranks).
  if (in_parts_) node_halo.emplace(numbered_part());
  if (contact_) {
    contact_->set_dirichlet(in_parts_ && hook_part_ ? owners_dirichlet(*hook_part_, *node_halo, loads_.dirichlet)
                                                   : loads_.dirichlet);
    contact_->add_dofs(dofs_);
  }
  if (!in_parts_) return;
  const int n = dofs_.n_dofs();
  // What a mesh in parts does not do yet (docs/distributed-model.md): said alike on every rank.
  LUNASTER_ASSERT(model_.mesh == &part_->mesh && part_->parts == parallel::size(),
                  "a run in parts takes the model of this rank's part, one part per rank");
  LUNASTER_ASSERT(!contact_ || hook_part_, "a hook on a mesh in parts takes the part with the hook's nodes");
  if (n != displacement_dofs) {
    // The hook's multipliers came after every node's displacements: the owned unknowns go
    // first (global_dofs.hpp), each class in its order, and the hook keeps its numbering.
    if (options_.solver == SolverKind::Petsc) {
      DeckError refused("the multipliers of contact or linear relations on a mesh in parts are solved by the "
                        "MUMPS backend, not PETSc");
      refused.failure().what = Failure::What::PartsMultipliers;
      throw refused;
    }
    std::vector<int> new_of_old(n);
    int next = 0;
    for (int owned_class : {1, 0})
      for (int eq = 0; eq < n; ++eq)
        if (part_->owns(dofs_.node_of(eq)) == (owned_class == 1)) new_of_old[eq] = next++;
    dofs_ = dofs_.renumbered(new_of_old);
    renumbered_contact_ = std::make_unique<RenumberedHook>(*contact_, std::move(new_of_old));
    contact_ = renumbered_contact_.get();
  }
  if (options_.auto_solver || (options_.solver != SolverKind::Mumps && options_.solver != SolverKind::Petsc)) {
    DeckError refused("on a mesh in parts the MUMPS or PETSc backend solves, not " +
                      std::string(options_.auto_solver ? "the automatic choice" : "a backend of one process"));
    refused.failure().what = Failure::What::PartsBackend;
    refused.failure().count = options_.auto_solver ? 1 : 0;
    throw refused;
  }
}

void StaticSolver::lay_out_parts(std::vector<int>& constrained, const NodeHalo& node_halo) {
  const int n = dofs_.n_dofs();
  const MeshPart& numbered = numbered_part();
  node_owner_ = numbered.node_owner;
  cell_rank_ = part_->cell_part;
  owned_nodes_.assign(numbered.mesh.n_nodes(), 0);
  std::fill(owned_nodes_.begin(), owned_nodes_.begin() + part_->n_owned_nodes, 1);
  unknown_numbers_ = number_across_ranks(numbered, dofs_, node_halo);
  const GlobalDofs& numbers = unknown_numbers_;
  stats_.n_dofs = static_cast<int>(numbers.n_global);
  layout_ = RankLayout(std::make_unique<Halo>(equation_halo(numbered, dofs_, numbers)), numbers.n_owned);
  // The constrained set the owners decide; the free unknowns, numbered across the ranks in
  // the order of the system's equations (free_index: ascending, the owned ones first).
  {
    Constraints owners = Constraints::holding(n, constrained);
    owners.take_from_owners(layout_.equation_halo());
    constrained = owners.constrained;
  }
  std::vector<char> free(n, 1);
  for (int eq : constrained) free[eq] = 0;
  free_numbers_ = number_across_ranks(numbered, dofs_, node_halo, &free);
  free_halo_ = std::make_unique<Halo>(equation_halo(numbered, dofs_, free_numbers_));
  std::string counts;
  for (int owned : parallel::gather_all(std::vector<int>{part_->n_owned_nodes}))
    counts += (counts.empty() ? "" : ", ") + std::to_string(owned);
  std::string hook_said;
  if (contact_ && contact_->has_contact())
    hook_said += "; the contact surfaces are whole on every rank, which pairs every point and keeps the contact "
                 "terms of its own nodes' columns";
  if (contact_ && !contact_->related_equations().empty())
    hook_said += "; every rank builds every linear relation (their nodes beyond its part are its ghosts) and "
                 "keeps the terms of its own nodes' columns";
  log_.info("mesh in parts on " + std::to_string(part_->parts) + " ranks: owned nodes per rank " + counts + ", " +
            std::to_string(numbers.n_global) + " unknowns; each rank assembles the stiffness of its own nodes and "
            "holds its part's vectors" + hook_said);
}

void StaticSolver::lay_out_shared() {
  const Mesh& mesh = *model_.mesh;
  const std::vector<int> cells = model_.volume_cells();
  const CellPartition part = partition_cells(mesh, cells, model_.dim);
  layout_ = RankLayout(RankLayout::Kind::Shared);
  node_owner_ = part.node_owner;
  cell_rank_.assign(mesh.n_cells(), -1);
  for (size_t i = 0; i < cells.size(); ++i) cell_rank_[cells[i]] = part.cell_part[i];
  owned_nodes_.assign(mesh.n_nodes(), 0);
  std::vector<int> nodes_of(part.parts, 0), cells_of(part.parts, 0);
  for (int v = 0; v < mesh.n_nodes(); ++v)
    if (node_owner_[v] >= 0) ++nodes_of[node_owner_[v]], owned_nodes_[v] = node_owner_[v] == parallel::rank();
  if (contact_) contact_->share_among_ranks(owned_nodes_);
  for (int p : part.cell_part) ++cells_of[p];
  std::string counts;
  for (int r = 0; r < part.parts; ++r)
    counts += (r ? ", " : "") + std::to_string(cells_of[r]) + " / " + std::to_string(nodes_of[r]);
  log_.info("model shared among " + std::to_string(part.parts) + " ranks, " +
            std::to_string(parallel::ranks_on_this_machine()) + " on this machine (Scotch): cells / nodes per rank " +
            counts + "; " + std::to_string(part.interface_nodes) +
            " nodes on interfaces; each rank assembles the stiffness of its own nodes" +
            (contact_ ? std::string(", pairs its share of the contact points and builds the contact terms "
                                    "of its own columns")
                      : std::string()));
}

std::vector<ResultStep> StaticSolver::run(const std::vector<double>& instants) {
  LUNASTER_ASSERT(!instants.empty(), "no instants");
  std::optional<NodeHalo> node_halo;
  number_unknowns(node_halo);
  const int n = dofs_.n_dofs();
  stats_ = SolverStats{};
  matrix_.clear();
  linear_ = std::make_unique<LinearSolve>(options_, stats_, log_);
  stats_.n_dofs = n;
  distributed_ = in_parts_ || shares_model();
  cell_rank_.clear();
  ghost_ = SparseMatrix();
  ghost_nodes_.clear();
  {
    Stopwatch watch(stats_.assemble_seconds);
    std::vector<int> constrained = Constraints::held_equations(dofs_, loads_, *model_.mesh);
    layout_ = RankLayout();
    free_halo_.reset();
    if (in_parts_) {
      lay_out_parts(constrained, *node_halo);
    } else if (distributed_) {
      lay_out_shared();
    } else if (parallel::size() > 1 && !options_.auto_solver && options_.solver == SolverKind::Mumps) {
      log_.info("model whole on each of the " + std::to_string(parallel::size()) +
                " ranks, as asked: each rank assembles the whole system; MUMPS reads rank 0's copy and "
                "factorises it across the ranks");
    }
    elastic_tangent_ = make_elastic_tangent(model_, dofs_, distributed_ ? &owned_nodes_ : nullptr);
    tangent_ = given_tangent_ ? given_tangent_ : elastic_tangent_.get();
    matrix_.assemble(*tangent_, Vector::Zero(n), constrained, distributed_);
  }
  k_scale_ = std::max(matrix_.elastic().ff.nonZeros() ? matrix_.elastic().ff.coeffs().cwiseAbs().maxCoeff() : 0.0,
                      matrix_.elastic().c.nonZeros() ? matrix_.elastic().c.coeffs().cwiseAbs().maxCoeff() : 0.0);
  if (distributed_) k_scale_ = parallel::max_over_ranks(k_scale_);
  convergence_ = std::make_unique<ConvergenceTest>(options_, layout_, k_scale_);
  return step_through(instants);
}

std::vector<ResultStep> StaticSolver::step_through(const std::vector<double>& instants) {
  Vector u = Vector::Zero(dofs_.n_dofs());
  steps_.clear();
  results_ = std::make_unique<StepResults>(dofs_, model_.mesh->n_nodes(), contact_,
                                          in_parts_ && hook_part_ ? hook_part_->mesh.n_nodes() : model_.mesh->n_nodes());
  steps_.push_back(results_->step(0, instants[0], u, true));
  const TimeStepper stepper(options_.subdivide_levels, options_.subdivide_parts, contact_, tangent_, log_);
  const TimeStepper::Solve solve = [this](double t, Vector& v) { solve_instant(t, v); };
  const TimeStepper::Commit commit = [this](double t, const Vector& v) {
    ++stats_.instants;
    tangent_->commit();
    steps_.push_back(results_->step(static_cast<int>(steps_.size()), t, v, false));
  };
  for (size_t i = 1; i < instants.size(); ++i) {
    try {
      stepper.advance(instants[i - 1], instants[i], u, solve, commit);
    } catch (SolveError& err) {
      // Say how far the run got: the converged steps stay available (converged_steps()).
      const ResultStep& last = steps_.back();
      err.add_hint("failed in step " + std::to_string(i) + " of " + std::to_string(instants.size() - 1) + " [" +
                   sci(instants[i - 1]) + ", " + sci(instants[i]) + "]; " + std::to_string(steps_.size() - 1) +
                   " step(s) converged before, the last at instant " + sci(last.inst) + " (stored step " +
                   std::to_string(last.nume_ordre) + ")");
      throw;
    }
  }
  return steps_;
}

std::vector<DirichletValue> owners_dirichlet(const MeshPart& numbered, const NodeHalo& node_halo,
                                             const std::vector<DirichletValue>& dirichlet) {
  // The part's loads miss the conditions of the hook's nodes beyond it (and of ghosts whose
  // constrained faces it lacks): each node takes its owner's, who holds every one of its own.
  // Per node and component: imposed or not, the value, the load (the last condition wins).
  constexpr int kPer = 9;
  std::vector<double> imposed(kPer * static_cast<size_t>(numbered.mesh.n_nodes()), 0.0);
  for (const DirichletValue& d : dirichlet)
    if (d.component >= 0 && d.component < 3) {
      double* at = &imposed[kPer * static_cast<size_t>(d.node) + 3 * d.component];
      at[0] = 1.0, at[1] = d.value, at[2] = d.load;
    }
  node_halo.copy_to_ghosts(imposed, kPer);
  std::vector<DirichletValue> out;
  for (int v = 0; v < numbered.mesh.n_nodes(); ++v)
    for (int c = 0; c < 3; ++c) {
      const double* at = &imposed[kPer * static_cast<size_t>(v) + 3 * c];
      if (at[0] != 0.0) out.push_back({v, c, at[1], static_cast<int>(at[2])});
    }
  return out;
}

SystemLayout StaticSolver::system_layout(const Constraints& cons, const std::vector<int>& condensed,
                                         const std::vector<int>& eliminated) const {
  const Mesh& mesh = *model_.mesh;
  SystemLayout layout;
  layout.dim = model_.dim;
  for (int c : model_.volume_cells()) layout.quadratic = layout.quadratic || cell_info(mesh.cell_types[c]).order > 1;
  layout.block.assign(cons.n_free, -1);
  layout.component.assign(cons.n_free, 0);
  std::vector<char> outside(cons.n_free, 0);
  for (const std::vector<int>* rows : {&condensed, &eliminated})
    for (int eq : *rows)
      if (cons.free_index[eq] >= 0) outside[cons.free_index[eq]] = 1;
  // In parts with whole contact surfaces the unknowns' nodes are the surfaces' part's.
  const Mesh& nodes = in_parts_ ? numbered_part().mesh : mesh;
  std::vector<int> block_of_node(nodes.n_nodes(), -1);
  for (int eq = 0; eq < dofs_.n_dofs(); ++eq) {
    const int k = cons.free_index[eq], c = dofs_.component_of(eq);
    if (k < 0 || outside[k] || !is_displacement(c) || c >= layout.dim) continue;
    const int node = dofs_.node_of(eq);
    if (block_of_node[node] < 0) {
      block_of_node[node] = layout.n_blocks();
      for (int d = 0; d < layout.dim; ++d) layout.coords.push_back(nodes.node(node)[d]);
    }
    layout.block[k] = block_of_node[node];
    layout.component[k] = c;
  }
  if (in_parts_) {
    for (int eq = 0; eq < dofs_.n_dofs(); ++eq)
      if (cons.free_index[eq] >= 0) layout.global.push_back(free_numbers_.global[eq]);
    layout.first = free_numbers_.first;
    layout.n_global = free_numbers_.n_global;
    layout.n_owned = free_numbers_.n_owned;
    // Node blocks for PETSc: every unknown's number (the owned nodes' dim unknowns in a row).
    // Not with a hook's multipliers, which MUMPS alone solves in parts (run() refuses PETSc).
    if (renumbered_contact_ == nullptr) {
      for (int eq = 0; eq < dofs_.n_dofs(); ++eq)
        if (cons.free_index[eq] >= 0) layout.row.push_back(unknown_numbers_.global[eq]);
      layout.first_row = unknown_numbers_.first;
      layout.n_rows = unknown_numbers_.n_global;
      layout.n_owned_rows = unknown_numbers_.n_owned;
      layout.row_coords.resize(unknown_numbers_.n_owned);
      for (int eq = 0; eq < unknown_numbers_.n_owned; ++eq) {
        LUNASTER_ASSERT(dofs_.component_of(eq) == eq % layout.dim, "in parts every node carries dim unknowns in order");
        layout.row_coords[eq] = mesh.node(dofs_.node_of(eq))[dofs_.component_of(eq)];
      }
    }
  } else if (distributed_) {
    layout.owner.assign(cons.n_free, -1);
    for (int eq = 0; eq < dofs_.n_dofs(); ++eq)
      if (cons.free_index[eq] >= 0) layout.owner[cons.free_index[eq]] = node_owner_[dofs_.node_of(eq)];
  }
  return layout;
}

bool StaticSolver::shares_model() const {
  // Only when the deck names such a backend: METHODE='AUTO' keeps its choice (CHOLMOD on
  // every rank for an SPD system), so a deck gives the same values under mpirun.
  if (parallel::size() < 2 || options_.auto_solver) return false;
  return (options_.solver == SolverKind::Mumps && options_.share_model) || options_.solver == SolverKind::Petsc;
}

Vector StaticSolver::internal_forces(const Vector& u) const {
  if (matrix_.constant()) return stiffness_times(u);
  Vector f = matrix_.internal_forces(u);
  layout_.complete(f);
  return f;
}

Vector StaticSolver::stiffness_times(const Vector& u) const {
  const LinearSolver* holder = k_ff_holder();
  // With K_ff in the backend, matrix_.elastic().times() gives the constrained columns' part only.
  Vector ku = matrix_.elastic().times(u);
  // In parts with K_ff in the backend, its product gives the owned rows whole: the ghosts'
  // shares of the rest go to the owners first, the owners' sums to the ghosts last.
  if (in_parts_ && holder) layout_.equation_halo().add_to_owners(ku.data(), 1);
  else layout_.complete(ku);
  if (holder) {
    const int nf = static_cast<int>(matrix_.elastic().equation.size());
    Vector u_free(nf), k_u_free;
    for (int j = 0; j < nf; ++j) u_free[j] = u[matrix_.elastic().equation[j]];
    const bool done = holder->multiply(u_free, k_u_free);
    LUNASTER_ASSERT(done, "the backend holding K_ff gave no product");
    for (int j = 0; j < nf; ++j) ku[matrix_.elastic().equation[j]] += k_u_free[j];
    if (in_parts_) layout_.equation_halo().copy_to_ghosts(ku.data(), 1);
  }
  return ku;
}

SolveError StaticSolver::diagnose(const Constraints& cons, const SolveError& err, double t) {
  matrix_.restore();  // K_ff itself, without this iteration's terms
  FailureDiagnosis::Stiffness stiffness;
  stiffness.on_no_rank = in_parts_;
  // matrix_.elastic().ff is the whole K_ff unless the model is shared or K_ff went to the backend
  // (also when the backend failed after taking it).
  const bool whole_here =
      !distributed_ && !k_ff_holder() && (matrix_.elastic().ff.nonZeros() > 0 || matrix_.elastic().equation.empty());
  if (whole_here) stiffness.k_ff = &matrix_.elastic().ff;
  else stiffness.constrained = matrix_.elastic().constrained;
  return FailureDiagnosis(model_, options_, contact_ != nullptr).explain(err, t, dofs_, cons.free_index, stiffness);
}

/// The system of one Newton iteration, K_ff + contact terms restricted to the free
/// equations. Without a contact hook it is matrix_.elastic().ff itself. Otherwise its pattern (K_ff's,
/// contact, a diagonal on every free equation) is built once per contact pattern version,
/// with the position of every contact triplet in it, and becomes K_ff's own; each iteration
/// writes its terms into that one storage and restore_elastic() puts K_ff's values back.
/// Elimination of unknowns by linear relations du_E = A du_R + b (contact_hook.hpp):
/// K' = K_RR + K_RE A + A^T K_ER + A^T K_EE A and r' = (r + K b)_R + A^T (r + K b)_E. Only
/// the columns of K at E are read (K is symmetric), so the cost follows the relations, not
/// the model. The terms of K' beyond K_RR are appended to `triplets` (as contact terms);
/// `r_free` becomes r'. Returns the eliminated equations, whose rows and columns
/// update_system replaces by a unit diagonal.
SparseMatrix StaticSolver::gathered_columns(const std::vector<int>& nodes) const {
  const int n = dofs_.n_dofs();
  std::vector<char> mask(model_.mesh->n_nodes(), 0);
  for (int v : nodes)
    if (part_->owns(v)) mask[v] = 1;
  const SparseMatrix mine = assemble_stiffness_matrix(model_, dofs_, &mask);
  // Each column as its number across the ranks, its count, then (row's number, value) pairs
  // (numbers below 2^53 travel exactly as doubles).
  std::vector<double> packed;
  for (int j = 0; j < static_cast<int>(mine.outerSize()); ++j) {
    const Eigen::Index count = mine.outerIndexPtr()[j + 1] - mine.outerIndexPtr()[j];
    if (count == 0) continue;
    packed.push_back(static_cast<double>(unknown_numbers_.global[j]));
    packed.push_back(static_cast<double>(count));
    for (SparseMatrix::InnerIterator it(mine, j); it; ++it) {
      packed.push_back(static_cast<double>(unknown_numbers_.global[it.row()]));
      packed.push_back(it.value());
    }
  }
  const std::vector<double> all = parallel::gather_all(packed);
  std::unordered_map<long long, int> local;
  local.reserve(static_cast<size_t>(n));
  for (int eq = 0; eq < n; ++eq) local.emplace(unknown_numbers_.global[eq], eq);
  std::vector<Triplet> t;
  for (size_t at = 0; at < all.size();) {
    const auto col = local.find(static_cast<long long>(all[at]));
    const long long count = static_cast<long long>(all[at + 1]);
    at += 2;
    for (long long k = 0; k < count; ++k, at += 2) {
      const auto row = local.find(static_cast<long long>(all[at]));
      LUNASTER_ASSERT(col != local.end() && row != local.end(),
                      "an eliminated unknown's stiffness column reaches an unknown this rank does not hold");
      t.emplace_back(row->second, col->second, all[at + 1]);
    }
  }
  SparseMatrix out(n, n);
  out.setFromTriplets(t.begin(), t.end());
  return out;
}

Constraints::ColumnSource StaticSolver::stiffness_columns(const Constraints& cons,
                                                         const std::vector<Elimination>& relations) {
  if (!distributed_) {
    // Its constrained rows are left out: their residual is not solved for and no term of K'
    // lies on them. So are zeros (the contact positions update_system added to K_ff's
    // pattern): the fill, and with it the system's pattern, follows the relations.
    return [this, &cons](int e, Constraints::Column& column) {
      for (SparseMatrix::InnerIterator it(matrix_.elastic().ff, cons.free_index[e]); it; ++it)
        if (it.value() != 0.0) column.emplace_back(matrix_.elastic().equation[it.row()], it.value());
    };
  }
  // This rank holds only its own nodes' columns: the whole columns of the eliminated
  // equations' nodes are computed (kept while the set of nodes holds), so that each rank gets
  // the whole fill and keeps its own columns of it. A shared model: every rank assembles them.
  // In parts: the owner of an eliminated unknown's node holds every cell around it, assembles
  // the node's columns whole and every rank gets them; their rows are on every rank (the slave
  // surfaces came with the cells around their nodes: with_whole_surfaces, layered).
  std::vector<int> nodes;
  for (const Elimination& e : relations) nodes.push_back(dofs_.node_of(e.eq));
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  if (nodes != ghost_nodes_) {
    if (in_parts_) {
      ghost_ = gathered_columns(nodes);
    } else {
      std::vector<char> mask(model_.mesh->n_nodes(), 0);
      for (int v : nodes) mask[v] = 1;
      ghost_ = SparseMatrix();
      ghost_ = assemble_stiffness_matrix(model_, dofs_, &mask);
    }
    ghost_nodes_ = std::move(nodes);
  }
  return [this, &cons](int e, Constraints::Column& column) {
    for (SparseMatrix::InnerIterator it(ghost_, e); it; ++it)
      if (cons.free_index[it.row()] >= 0) column.emplace_back(static_cast<int>(it.row()), it.value());
  };
}

void StaticSolver::choose_interface(const Constraints& cons, const std::vector<Triplet>& contact) {
  interface_use_ = -1;
  // METHODE='AUTO' only: a deck that names its solver gets it. The dense Schur complement
  // costs m^2 doubles and m^3/3 operations per contact pass: a small interface only, against
  // a large interior (the 2D SSNP121 geometries).
  constexpr int kMaxInterface = 2500, kInteriorPerInterface = 20;
  if (!contact_ || !options_.auto_solver || options_.solver != SolverKind::Cholmod || distributed_ ||
      !matrix_.constant())
    return;
  const std::vector<int> surface = contact_->surface_equations();
  std::vector<int> eqs;
  for (int eq : surface)
    if (cons.free_index[eq] >= 0) eqs.push_back(cons.free_index[eq]);
  interface_floor_ = 0.0;
  interface_dense_share_ = 0.0;
  if (eqs.size() > static_cast<std::size_t>(kMaxInterface) ||
      static_cast<long>(eqs.size()) * kInteriorPerInterface > cons.n_free) {
    // Too many for the whole surfaces (a 3D surface of a few hundred nodes: 4,263 equations
    // on the CONTINUE 3D benchmark). The contact terms may reach fewer displacement
    // components: one on an interface square to an axis (SSNP121's), whose other components
    // then stay with the interior (1,715 equations on that benchmark): those that the
    // pairing's normals reach, active or not (so also before any point is active), as the
    // hook says. Terms below kNegligibleTerm of the largest count for nothing: a normal's
    // round-off that the gaps do not already leave out (make_linear_gap drops components up
    // to kNormalRoundOff). The dense factorisation must then cost at most kDenseShare of the
    // reference's (factorize_interface_reference), and a term outside the interface, in this
    // solve or a later one (a pairing that reaches another component), makes solve_instant
    // give the interface solver up.
    constexpr double kDenseShare = 0.5;
    double largest = 0.0;
    for (const Triplet& tr : contact) largest = std::max(largest, std::abs(tr.value()));
    interface_floor_ = kNegligibleTerm * largest;
    const std::array<bool, 3> reached = contact_->displacement_components();
    if (!reached[0] && !reached[1] && !reached[2]) return;  // nothing paired
    eqs.clear();
    for (int eq : surface) {
      const int c = dofs_.component_of(eq);
      if (cons.free_index[eq] >= 0 && (!is_displacement(c) || reached[c])) eqs.push_back(cons.free_index[eq]);
    }
    if (eqs.size() > static_cast<std::size_t>(kMaxInterface)) return;
    interface_dense_share_ = kDenseShare;
  }
  std::sort(eqs.begin(), eqs.end());
  if (eqs.empty()) return;
  // The reference is K_ff itself, which must store a diagonal on every interface equation. The
  // multipliers' columns are empty and come last (their equations are numbered after every
  // displacement): each gets a zero diagonal appended, in the storage K_ff already holds
  // (split_matrix left it the constrained columns' room).
  SparseMatrix& k = matrix_.elastic().ff;
  const int nf = static_cast<int>(k.cols());
  int first_empty = nf;
  while (first_empty > 0 && k.outerIndexPtr()[first_empty] == k.outerIndexPtr()[first_empty - 1]) --first_empty;
  for (int j : eqs) {
    if (j >= first_empty) continue;
    const int* rows = k.innerIndexPtr() + k.outerIndexPtr()[j];
    const int* end = k.innerIndexPtr() + k.outerIndexPtr()[j + 1];
    if (!std::binary_search(rows, end, j)) return;  // an interface equation without a diagonal entry
  }
  if (first_empty < nf) {
    const int nnz = static_cast<int>(k.nonZeros());
    k.resizeNonZeros(nnz + (nf - first_empty));
    for (int j = first_empty; j < nf; ++j) {
      k.innerIndexPtr()[nnz + (j - first_empty)] = j;
      k.valuePtr()[nnz + (j - first_empty)] = 0.0;
      k.outerIndexPtr()[j + 1] = nnz + (j - first_empty) + 1;
    }
  }
  on_interface_.assign(cons.n_free, 0);
  for (int j : eqs) on_interface_[j] = 1;
  interface_ = make_interface_solver(std::move(eqs));
  FactorSettings settings;  // the interface solver reads the singularity test alone
  settings.singularity = options_.factor.singularity;
  interface_->configure(settings);
  interface_use_ = 1;
}

void StaticSolver::factorize_interface_reference() {
  double seconds = 0.0;
  {
    Stopwatch watch(seconds);
    const int m = static_cast<int>(interface_->interface().size());
    try {
      const bool taken = interface_->factorize_reference(matrix_.elastic().ff, interface_dense_share_);
      if (const std::string analysis = interface_->analysis_note(); !analysis.empty() && analysis != analysis_logged_)
        log_.debug("  " + analysis), analysis_logged_ = analysis;
      if (taken) {
        interface_reference_ = matrix_.generation();
        interface_state_ = LinearSolve::FactorState{};
        stats_.interface_equations = m;
        ++stats_.factorisations;
        log_.info("  elastic system factorised with the " + std::to_string(m) +
                  " equations of the contact surfaces last: each contact pass factorises their Schur "
                  "complement only");
      } else {
        interface_use_ = -1;
        interface_.reset();
        stats_.interface_equations = 0;
        log_.info("  the " + std::to_string(m) +
                  " equations of the contact surfaces are too many for a dense Schur complement against this "
                  "elastic factorisation: each contact pass factorises the whole system");
      }
    } catch (const SolveError& err) {
      if (err.out_of_memory()) throw;
      interface_use_ = -1;
      interface_.reset();
      stats_.interface_equations = 0;
      log_.info("  the elastic system alone is not positive definite (a body held by contact or linear relations "
                "only): each contact pass factorises the whole system");
    }
  }
  stats_.factorize_seconds += seconds;
  stats_.assemble_seconds -= seconds;  // the caller times update_system as assembly
}

void StaticSolver::update_system(const Constraints& cons, const std::vector<Triplet>& contact,
                                 const std::vector<int>& condensed, const std::vector<int>& eliminated) {
  const long pattern_before = matrix_.pattern();
  matrix_.begin(cons, dofs_, distributed_ ? &owned_nodes_ : nullptr);
  if (!contact_) {  // K_ff alone: nothing to copy, nothing to add
    LUNASTER_ASSERT(condensed.empty() && eliminated.empty() && contact.empty(), "no contact hook, no contact terms");
    matrix_.fill_alone();
  } else {
    const long version = contact_->pattern_version();
    if (interface_use_ == 1 && interface_reference_ != matrix_.generation()) factorize_interface_reference();
    if (interface_use_ == 1)
      matrix_.fill_interface(cons, contact, condensed, version, interface_->interface(), on_interface_);
    else
      matrix_.fill_whole(cons, contact, condensed, eliminated, version);
  }
  if (distributed_) matrix_.agree_over_ranks(pattern_before);
}

void StaticSolver::solve_instant(double t, Vector& u) {
  log_.info("instant " + sci(t));
  Instant in;
  in.t = t;
  in.cons = Constraints::at_instant(dofs_, loads_, t, *model_.mesh);
  if (in_parts_) in.cons.take_from_owners(layout_.equation_halo());
  in.cons.impose(u);
  in.f_ext = external_forces(model_, dofs_, loads_, t, distributed_ ? &node_owner_ : nullptr,
                             in_parts_ ? &layout_.equation_halo() : nullptr);
  stats_.n_free = std::max(stats_.n_free, in_parts_ ? static_cast<int>(free_numbers_.n_global) : in.cons.n_free);
  // The entries this rank answers for in the norms: all of them, or in parts its owned ones.
  in.owned_free = in_parts_ ? free_numbers_.n_owned : in.cons.n_free;
  if (contact_) {
    Stopwatch watch(stats_.contact_seconds);
    contact_->set_instant(t);
    contact_->begin_step(u, log_);
  }
  const int factorisations_before = stats_.factorisations;
  const int refinements_before = stats_.refinement_steps;
  for (int fixed_point = 0;; ++fixed_point) {
    newton_loop(in, u, fixed_point);
    if (!contact_ || !contact_->has_contact()) break;
    log_.info("contact: " + std::to_string(contact_->n_active()) + " active point(s) in this pass");
    ++stats_.contact_passes;
    bool settled = false;
    {
      Stopwatch watch(stats_.contact_seconds);
      try {
        settled = contact_->settle(u, log_);
      } catch (ConvergenceError& err) {
        err.add_hint("at instant " + sci(t) + ", after " + std::to_string(in.total_newton) +
                     " Newton iteration(s); last residuals: relative " + sci(in.norms.relative) + ", absolute " +
                     sci(in.norms.absolute) + " N");
        err.failure().residuals_known = true;
        err.failure().relative = in.norms.relative, err.failure().absolute = in.norms.absolute;
        throw;
      }
    }
    if (layout_.all_ranks(settled)) break;
  }
  log_.info("  converged in " + std::to_string(in.total_newton) + " Newton iteration(s), " +
            std::to_string(stats_.factorisations - factorisations_before) + " factorisation(s)" +
            (stats_.refinement_steps > refinements_before
                 ? ", " + std::to_string(stats_.refinement_steps - refinements_before) + " refinement step(s)"
                 : std::string()));
}

void StaticSolver::newton_loop(Instant& in, Vector& u, int fixed_point) {
  log_.info("  | iter |  relative resid. |  absolute resid. |");
  in.carried_residual = Vector();
  in.norms = ResidualNorms{};
  for (int iter = 0; iter <= options_.iter_glob_maxi; ++iter) {
    std::vector<Triplet> k_contact;
    Vector residual, r_free;
    bool tangent_pending = false;
    if (converged_at(in, u, iter, residual, r_free, k_contact, tangent_pending)) return;
    if (iter == options_.iter_glob_maxi) break;
    if (tangent_pending) {
      Stopwatch watch(stats_.contact_seconds);
      Vector again = Vector::Zero(dofs_.n_dofs());  // the residual is in `residual` already
      contact_->add_to_system(u, k_contact, again);
    }
    newton_step(in, u, iter, residual, r_free, k_contact);
    ++in.total_newton;
  }
  ConvergenceError err("Newton did not converge at instant " + sci(in.t) + " within " +
                           std::to_string(options_.iter_glob_maxi) + " iterations",
                       {"last residuals: relative " + sci(in.norms.relative) + ", absolute " +
                            sci(in.norms.absolute) + " N",
                        "loop: Newton (contact/geometry fixed-point pass " + std::to_string(fixed_point) + ")"});
  Failure& f = err.failure();
  f.what = Failure::What::NewtonIterations;
  f.limit = options_.iter_glob_maxi;
  f.residuals_known = true, f.relative = in.norms.relative, f.absolute = in.norms.absolute;
  throw err;
}

bool StaticSolver::converged_at(Instant& in, const Vector& u, int iter, Vector& residual, Vector& r_free,
                                std::vector<Triplet>& k_contact, bool& tangent_pending) {
  if (in.carried_residual.size() == dofs_.n_dofs()) {
    residual.swap(in.carried_residual);
    in.carried_residual = Vector();
  } else {
    Stopwatch watch(stats_.assemble_seconds);
    residual = internal_forces(u) - in.f_ext;
  }
  // The residual may converge from the second iteration on, and in a pass after the first
  // (a new pairing or new statuses) already at its start: a hook that gives its residual
  // alone gives it first, and its tangent only for an iteration that solves.
  const bool may_converge = iter > 0 || in.last_converged_maxi >= 0.0;
  if (contact_) {
    Stopwatch watch(stats_.contact_seconds);
    tangent_pending = may_converge && contact_->add_residual(u, residual);
    if (!tangent_pending) contact_->add_to_system(u, k_contact, residual);
  }
  in.norms = convergence_->measure(in.cons, residual, in.f_ext, u, in.owned_free, r_free);
  char line[96];
  std::snprintf(line, sizeof line, "  | %4d |   %14.6e |   %14.6e |", iter, in.norms.relative, in.norms.absolute);
  log_.info(line);
  if (!std::isfinite(in.norms.absolute)) throw ConvergenceError("the residual became non-finite at instant " + sci(in.t));
  // In parts every rank pairs the whole surfaces alike; the ranks still decide together.
  const bool contact_ok = !contact_ || layout_.all_ranks(contact_->newton_converged());
  if (!convergence_->converged(in.norms, iter, in.last_converged_maxi, contact_ok)) return false;
  if (iter == 0) log_.info("  the new pairing or statuses leave the residual as it was: no solve in this pass");
  in.last_converged_maxi = in.norms.absolute;
  stats_.resi_glob_rela = in.norms.relative;
  return true;
}

void StaticSolver::keep_interface_or_drop(const Constraints& cons, const std::vector<Triplet>& k_contact,
                                          bool eliminations) {
  if (interface_use_ == 0) choose_interface(cons, k_contact);
  if (interface_use_ == 1 && eliminations) interface_use_ = -1, interface_.reset(), stats_.interface_equations = 0;
  if (interface_use_ == 1)
    for (const Triplet& tr : k_contact) {
      const int i = cons.free_index[tr.row()], j = cons.free_index[tr.col()];
      if (i >= 0 && j >= 0 && (!on_interface_[i] || !on_interface_[j]) && std::abs(tr.value()) > interface_floor_) {
        log_.info("  a contact term outside the surfaces' equations: each contact pass factorises the whole system");
        interface_use_ = -1, interface_.reset(), stats_.interface_equations = 0;
        break;
      }
    }
}

void StaticSolver::check_bodies_held(const Instant& in, const SystemTerms& terms, SolverKind backend) {
  // With no contact point active, the bodies must be held by Dirichlet conditions (and
  // relations) alone. Checked once, before any factorisation:
  // - from the geometry, every backend and every rank of a shared model: a body that
  //   some translation or rotation moves without moving a held equation (a free body under
  //   MUMPS would otherwise be caught only when round-off left its null pivot a zero);
  // - then, for what geometry does not see (a mechanism inside a body), by a Cholesky
  //   factorisation of K_ff, for UMFPACK and MUMPS, which return some solution of a
  //   singular but consistent system. CHOLMOD's own factorisation stops on such a system
  //   (diagnosed below; a run told to go on past singular pivots is warned instead), the
  //   interface solver's reference is that factorisation, an
  //   iterative backend chosen because factorising does not fit skips it, and so does a
  //   shared model, which would need the whole stiffness on one rank.
  if (rigid_checked_ || (contact_ && contact_->n_active() != 0)) return;
  // Every unknown of a relation (the hook's and the eliminations'): counted as holding.
  std::vector<int> related = contact_ ? contact_->related_equations() : std::vector<int>{};
  // A body that only the hook's relations hold leaves K_ff singular, rightly: the
  // mechanism check of K_ff alone is for runs whose every body the Dirichlet conditions hold.
  const bool held_by_relations = !related.empty();
  for (const Elimination& e : *terms.eliminated) {
    related.push_back(e.eq);
    for (const auto& term : e.terms) related.push_back(term.first);
  }
  // Going on past a singular matrix was asked for: a body held by nothing is a warning.
  const auto report = [this](const SolveError& rigid) {
    if (options_.factor.singularity.stop) throw rigid;
    log_.warning("going on as asked with a singular system: " + rigid.message());
  };
  // (Not in parts: a part alone may look unheld.)
  const auto unheld =
      in_parts_ ? std::optional<SolveError>() : find_unheld_body(model_, dofs_, in.cons.free_index, related, in.t);
  if (unheld) report(*unheld);
  if (!unheld && !held_by_relations && interface_use_ != 1 && backend != SolverKind::Cholmod &&
      backend != SolverKind::Petsc && !distributed_ && options_.factor.singularity.digits >= 0) {
    Stopwatch watch(stats_.assemble_seconds);
    matrix_.restore();  // K_ff itself, without this iteration's terms
    if (auto rigid = find_rigid_body_mode(model_, dofs_, in.cons.free_index, matrix_.elastic().ff, in.t,
                                          options_.factor.singularity))
      report(*rigid);
    update_system(in.cons, *terms.contact, *terms.condensed, terms.eliminated_eqs);  // the terms again
  }
  rigid_checked_ = true;
}

void StaticSolver::newton_step(Instant& in, Vector& u, int iter, Vector& residual, Vector& r_free,
                               std::vector<Triplet>& k_contact) {
  const Constraints& cons = in.cons;
  if (!matrix_.constant()) {
    Stopwatch watch(stats_.assemble_seconds);
    matrix_.refresh(u);  // a tangent that follows u: K_ff at this iterate
  }
  static const std::vector<int> no_equations;
  static const std::vector<Elimination> no_eliminations;
  SystemTerms terms;
  terms.contact = &k_contact;
  terms.condensed = contact_ ? &contact_->condensed_equations() : &no_equations;
  terms.eliminated = contact_ ? &contact_->eliminations() : &no_eliminations;
  if (!terms.eliminated->empty()) {
    Stopwatch watch(stats_.assemble_seconds);
    terms.eliminated_eqs =
        cons.eliminate(*terms.eliminated, stiffness_columns(cons, *terms.eliminated), residual, k_contact, r_free);
  }
  if (distributed_) {
    // The hook built the terms of the points that touch this rank's columns, which also
    // reach other ranks' columns: this rank keeps its own.
    k_contact.erase(std::remove_if(k_contact.begin(), k_contact.end(),
                                   [this](const Triplet& tr) { return !owned_nodes_[dofs_.node_of(tr.col())]; }),
                    k_contact.end());
  }
  keep_interface_or_drop(cons, k_contact, !terms.eliminated_eqs.empty());
  {
    Stopwatch watch(stats_.assemble_seconds);
    update_system(cons, k_contact, *terms.condensed, terms.eliminated_eqs);
    stats_.system_entries = matrix_.matrix().nonZeros();
  }
  // matrix_.elastic().ff is K_ff again when this iteration ends, however it ends (the next
  // residual, a diagnosis, a subdivided step read it).
  struct RestoreElastic {
    StaticSolver* self;
    ~RestoreElastic() { self->matrix_.restore(); }
  } restore_at_end{this};
  // The system of this iteration: the contact law may condense its multipliers out
  // (then it is SPD), and says which kind of matrix is left.
  const MatrixKind kind = contact_ ? contact_->matrix_kind() : MatrixKind::SymmetricPositiveDefinite;
  // (The interface solver is CHOLMOD's factorisation of K_ff: no other backend is chosen.)
  const SolverKind backend = interface_use_ == 1 ? SolverKind::Cholmod : choose_backend(kind);
  check_bodies_held(in, terms, backend);
  // The contact terms are in the system's storage now: their triplets (5.5e6 of them, 88 MB,
  // on the refined mortar case) go before the factorisation or the preconditioner is built.
  std::vector<Triplet>().swap(k_contact);
  // Condensed unknowns: decoupled rows (unit diagonal, zero right-hand side), set by recover().
  for (int eq : *terms.condensed)
    if (cons.free_index[eq] >= 0) r_free[cons.free_index[eq]] = 0.0;
  RefinedSolve accuracy;
  const Vector du = solve_system(in, iter, kind, backend, terms, r_free, accuracy);
  apply_increment(in, du, accuracy, terms, residual, u);
}

Vector StaticSolver::solve_system(const Instant& in, int iter, MatrixKind kind, SolverKind backend,
                                  const SystemTerms& terms, const Vector& r_free, RefinedSolve& accuracy) {
  const Constraints& cons = in.cons;
  const SparseMatrix& a = matrix_.matrix();
  const bool via_interface = interface_use_ == 1;
  const bool a_is_k_ff = !contact_ && &a == &matrix_.elastic().ff;
  // In parts, the residuals of a solve are measured on the owned entries over the ranks.
  const int n_owned_free = in.owned_free;
  const VectorNorm owned_norm = [n_owned_free](const Vector& v) {
    double squares = v.head(n_owned_free).squaredNorm();
    parallel::sum_over_ranks(&squares, 1);
    return std::sqrt(squares);
  };
  LinearSolve::System system;
  system.a = &a;
  system.kind = kind;
  system.pattern = matrix_.pattern();
  system.values_key = matrix_.values_key();
  system.statuses = contact_ ? contact_->status_key() : 0ULL;
  system.iteration = iter;
  system.product = system_product(a, a_is_k_ff);
  // |A| |x| for the backward error (not with a shared model or K_ff in PETSc's hands).
  system.abs_product = [&a, this](const Vector& x) -> Vector {
    Vector y = Vector::Zero(x.size());
    add_abs_product(a, x, y);
    if (matrix_.increment()) add_abs_product(matrix_.elastic().ff, x, y);
    return y;
  };
  system.norm = in_parts_ ? &owned_norm : nullptr;
  system.on_interface = via_interface;
  system.whole = !distributed_ && !k_ff_holder();
  system.distributed = distributed_;
  system.layout = [this, &cons, &terms] { return system_layout(cons, *terms.condensed, terms.eliminated_eqs); };
  if (&a == &matrix_.elastic().ff && !contact_ && matrix_.constant()) system.takeable = &matrix_.elastic().ff;
  if (options_.observe_factorisation && !via_interface)
    system.observe = [this](const SparseMatrix& m, MatrixKind k) {
      options_.observe_factorisation(m, k, matrix_.elastic().equation);
    };
  system.diagnose = [this, &in](const SolveError& err) { return diagnose(in.cons, err, in.t); };
  const LinearSolve::Events events = [this, &in](const LinearSolve::Event& e) { say(e, in); };
  LinearSolver& solver = via_interface ? *interface_ : linear_->backend(backend, events);
  LinearSolve::FactorState& state = via_interface ? interface_state_ : linear_->state(backend);
  return linear_->solve(solver, state, backend, system, -r_free, events, accuracy);
}

MatrixProduct StaticSolver::system_product(const SparseMatrix& a, bool a_is_k_ff) const {
  // A x for the accuracy of a solve: this rank's columns of a, summed over the ranks; the
  // backend's product once K_ff is in its hands. Without contact a is K_ff itself, with its
  // own product; with contact terms it may hold condensed or eliminated rows, which are not
  // symmetric.
  return [&a, a_is_k_ff, this](const Vector& x) -> Vector {
    Vector y;
    const LinearSolver* holder = k_ff_holder();
    if (in_parts_) {
      // The backend holding K_ff gives the owned rows whole. Otherwise x's owned entries
      // are the solve's: its ghosts take their owners' before the product, whose owned
      // entries are complete once the ranks' shares are summed into them.
      if (holder && holder->multiply(x, y)) return y;
      Vector whole_x = x;
      free_halo_->copy_to_ghosts(whole_x.data(), 1);
      y = a * whole_x;
      free_halo_->add_to_owners(y.data(), 1);
      return y;
    }
    if (holder && holder->multiply(x, y)) return y;
    y = a_is_k_ff ? matrix_.elastic().ff_times(x) : Vector(a * x);
    if (matrix_.increment()) y += matrix_.elastic().ff_times(x);  // a is C: the system is K_ff + C
    if (distributed_) parallel::sum_over_ranks(y.data(), y.size());
    return y;
  };
}

void StaticSolver::apply_increment(Instant& in, Vector du, const RefinedSolve& accuracy, const SystemTerms& terms,
                                   Vector& residual, Vector& u) {
  const Constraints& cons = in.cons;
  const int n = dofs_.n_dofs();
  if (in_parts_) free_halo_->copy_to_ghosts(du.data(), 1);  // the solve gave the owned values
  for (int eq = 0; eq < n; ++eq)
    if (cons.free_index[eq] >= 0) u[eq] += du[cons.free_index[eq]];
  // Without contact or relations the residual is linear in u, and neither f nor u_C move
  // within the instant: the next residual is this one plus K du. Its free rows are the
  // solve's own A du - b (A = K_ff, b = -r_F), its constrained rows cost K(C, F) du; the
  // product of K with u for the next iteration is saved (a third of an elastic instant's
  // products). Not from a residual already near round-off: A du - b would then be the
  // round-off of a tiny correction, far below that of K u - f, and report a state more
  // exact than the stored u can be.
  constexpr double kCarriedAbove = 1e-8;
  const bool a_is_k_ff = !contact_ && &matrix_.matrix() == &matrix_.elastic().ff;
  if (matrix_.constant() && !contact_ && terms.eliminated->empty() && terms.condensed->empty() && a_is_k_ff && !distributed_ &&
      !k_ff_holder() && accuracy.ax_minus_b.size() == cons.n_free && in.norms.relative > kCarriedAbove) {
    in.carried_residual = std::move(residual);
    for (int eq = 0; eq < n; ++eq)
      if (cons.free_index[eq] >= 0) in.carried_residual[eq] = accuracy.ax_minus_b[cons.free_index[eq]];
    matrix_.elastic().add_constrained_rows(du, in.carried_residual);
  }
  cons.recover(*terms.eliminated, du, u);
  if (!terms.condensed->empty()) {
    Stopwatch watch(stats_.contact_seconds);
    contact_->recover(u);
  }
}

SolverKind StaticSolver::choose_backend(MatrixKind kind) {
  const LinearSolve::Backend chosen = linear_->choose(kind, stats_.n_free, model_.dim, distributed_);
  using Note = LinearSolve::BackendNote;
  const std::string fallback = chosen.fallback == SolverKind::Umfpack ? "UMFPACK" : "MUMPS";
  switch (chosen.note) {
    case Note::None: break;
    case Note::AutoIterative:
    case Note::AutoMumps:
      log_.info("solver chosen automatically: " +
                std::string(chosen.note == Note::AutoIterative
                                ? "PETSc CG + BoomerAMG (relative residual 1e-12, MUMPS if it does not converge)"
                                : "MUMPS") +
                " for a 3D system of " + std::to_string(stats_.n_free) +
                " unknowns (a factorisation fills too much at this size)");
      break;
    case Note::SaddleSchur:
    case Note::Umfpack:
    case Note::Mumps:
      log_.info(std::string("CHOLMOD cannot factorise ") +
                (kind == MatrixKind::SymmetricIndefinite ? "an indefinite" : "a non-symmetric") +
                (chosen.note == Note::SaddleSchur
                     ? " system; CHOLMOD factorises the Schur complement of its multipliers and GMRES solves it (" +
                           fallback + " if that gives way)"
                 : chosen.note == Note::Umfpack ? " system; using UMFPACK (MUMPS from 10000 unknowns)"
                                                : " system; using MUMPS"));
      break;
  }
  return chosen.kind;
}

void StaticSolver::say(const LinearSolve::Event& e, const Instant& in) {
  using W = LinearSolve::Event::What;
  const std::string its = std::to_string(e.iterations);
  switch (e.what) {
    case W::SinglePrecision:
      log_.info("  linear solver: MUMPS in single precision, each solve refined in double precision");
      break;
    case W::FactorsReused:
      log_.info("         (factorisation of iteration " + std::to_string(e.iteration) + " reused)");
      break;
    case W::KrylovOnPrevious:
      if (e.converged)
        log_.info("  linear solve: previous factorisation as preconditioner, " + its +
                  " GMRES iteration(s), relative residual " + sci(e.residual));
      else
        log_.info("  linear solve: " + its + " GMRES iteration(s) with the previous factorisation did not converge "
                  "(relative residual " + sci(e.residual) + "); refactorising");
      break;
    case W::Factorised: say_factorisation(*e.solver, in); break;
    case W::SameMatrix:
      log_.info(options_.elastic_matrix ? std::string("         (factorisation of the elastic matrix reused)")
                : e.solver->iterative() ? std::string("         (same matrix as the last solve: preconditioner reused)")
                                        : std::string("         (same matrix as the last factorisation: factors reused)"));
      break;
    case W::IterativeSolved:
    case W::DirectIterated:
      log_.info("  linear solve: " + e.solver->name() + ", " + its + " iteration(s), relative residual " +
                sci(e.residual));
      break;
  }
}

void StaticSolver::say_factorisation(const LinearSolver& solver, const Instant& in) {
  // A singular matrix that the run goes past, as asked: said once for each instant and
  // pivot (the Newton iterations and contact passes of an instant refactorise it alike).
  if (const std::string note = solver.singular_note(); !note.empty()) {
    std::string where;
    if (const int column = solver.singular_column(); column >= 0)
      for (int eq = 0; eq < dofs_.n_dofs() && where.empty(); ++eq)
        if (in.cons.free_index[eq] == column) where = " at " + describe_equation(*model_.mesh, dofs_, eq);
    const std::string said = "singular matrix at instant " + sci(in.t) + where;
    if (said != singular_said_) log_.warning(said + ", going on as asked: " + solver.name() + ": " + note);
    singular_said_ = said;
  }
  // What an asked-for ordering and out-of-core factors came to, said once while it holds.
  const auto say_once = [this](const std::string& line, std::string& said) {
    if (line != said) log_.info(line);
    said = line;
  };
  if (options_.factor.ordering != FactorOrdering::Auto)
    say_once("  " + solver.name() + " ordering: " + solver.ordering_used(), ordering_logged_);
  if (const std::string f = solver.factorisation_used(); !f.empty())
    say_once("  " + solver.name() + " factorisation: " + f, factorisation_logged_);
  if (const std::string analysis = solver.analysis_note(); !analysis.empty() && analysis != analysis_logged_)
    log_.debug("  " + analysis);
  analysis_logged_ = solver.analysis_note();
  if (const std::string memory = solver.memory_used(); !memory.empty())
    say_once("  " + solver.name() + " factors: " + memory, memory_logged_);
  if (const std::string approximate = solver.approximation_note(); !approximate.empty())
    say_once("  " + solver.name() + ": " + approximate, approximation_logged_);
  if (interface_use_ == 1)
    log_.info("  linear solve: Schur complement of the " + std::to_string(interface_->interface().size()) +
              " surface equations factorised on the kept elastic factorisation");
}

}  // namespace lunaster::engine
