#include "engine/nonlinear/rank_layout.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>

#include "engine/assembly/assembly.hpp"
#include "engine/core/error.hpp"
#include "engine/assembly/partition.hpp"
#include "engine/mesh/cell_type.hpp"

#include "engine/parallel/mpi_runtime.hpp"

namespace lunaster::engine {

double RankLayout::largest_entry(const Vector& v, int n_owned) const {
  if (!in_parts()) return v.size() ? v.cwiseAbs().maxCoeff() : 0.0;
  const double here = n_owned > 0 ? v.head(n_owned).cwiseAbs().maxCoeff() : 0.0;
  // A NaN stays a NaN over the ranks (max would drop it): the ranks stop alike.
  const double bad = parallel::max_over_ranks(std::isfinite(here) ? 0.0 : 1.0);
  return bad > 0.0 ? std::numeric_limits<double>::quiet_NaN() : parallel::max_over_ranks(here);
}

double RankLayout::largest_over_ranks(double here) const {
  return in_parts() ? parallel::max_over_ranks(here) : here;
}

bool RankLayout::all_ranks(bool here) const {
  return in_parts() ? parallel::max_over_ranks(here ? 0.0 : 1.0) == 0.0 : here;
}

void RankLayout::complete(Vector& v) const {
  if (kind_ == Kind::Shared) parallel::sum_over_ranks(v.data(), v.size());
  if (kind_ != Kind::InParts) return;
  equation_halo_->add_to_owners(v.data(), 1);
  equation_halo_->copy_to_ghosts(v.data(), 1);
}

RankLayout RankLayout::shared(const FeModel& model, ContactHook* hook, const Log& log) {
  const Mesh& mesh = *model.mesh;
  const std::vector<int> cells = model.volume_cells();
  const CellPartition part = partition_cells(mesh, cells, model.dim);
  RankLayout out;
  out.kind_ = Kind::Shared;
  out.node_owner_ = part.node_owner;
  out.cell_rank_.assign(mesh.n_cells(), -1);
  for (size_t i = 0; i < cells.size(); ++i) out.cell_rank_[cells[i]] = part.cell_part[i];
  out.owned_nodes_.assign(mesh.n_nodes(), 0);
  std::vector<int> nodes_of(part.parts, 0), cells_of(part.parts, 0);
  for (int v = 0; v < mesh.n_nodes(); ++v)
    if (out.node_owner_[v] >= 0) ++nodes_of[out.node_owner_[v]], out.owned_nodes_[v] = out.node_owner_[v] == parallel::rank();
  if (hook) hook->share_among_ranks(out.owned_nodes_);
  for (int p : part.cell_part) ++cells_of[p];
  std::string counts;
  for (int r = 0; r < part.parts; ++r)
    counts += (r ? ", " : "") + std::to_string(cells_of[r]) + " / " + std::to_string(nodes_of[r]);
  log.info("model shared among " + std::to_string(part.parts) + " ranks, " +
            std::to_string(parallel::ranks_on_this_machine()) + " on this machine (Scotch): cells / nodes per rank " +
            counts + "; " + std::to_string(part.interface_nodes) +
            " nodes on interfaces; each rank assembles the stiffness of its own nodes" +
            (hook ? std::string(", pairs its share of the contact points and builds the contact terms "
                                    "of its own columns")
                      : std::string()));
  return out;
}

RankLayout RankLayout::in_parts(const MeshPart& part, const MeshPart& numbered, const DofMap& dofs,
                                const NodeHalo& node_halo, std::vector<int>& constrained, const ContactHook* hook,
                                const Log& log) {
  const int n = dofs.n_dofs();
  RankLayout out;
  out.kind_ = Kind::InParts;
  out.node_owner_ = numbered.node_owner;
  out.cell_rank_ = part.cell_part;
  out.owned_nodes_.assign(numbered.mesh.n_nodes(), 0);
  std::fill(out.owned_nodes_.begin(), out.owned_nodes_.begin() + part.n_owned_nodes, 1);
  out.unknown_numbers_ = number_across_ranks(numbered, dofs, node_halo);
  const GlobalDofs& numbers = out.unknown_numbers_;
  out.equation_halo_ = std::make_unique<Halo>(engine::equation_halo(numbered, dofs, numbers));
  // The constrained set the owners decide; the free unknowns, numbered across the ranks in
  // the order of the system's equations (free_index: ascending, the owned ones first).
  {
    Constraints owners = Constraints::holding(n, constrained);
    owners.take_from_owners(*out.equation_halo_);
    constrained = owners.constrained;
  }
  std::vector<char> free(n, 1);
  for (int eq : constrained) free[eq] = 0;
  out.free_numbers_ = number_across_ranks(numbered, dofs, node_halo, &free);
  out.free_halo_ = std::make_unique<Halo>(engine::equation_halo(numbered, dofs, out.free_numbers_));
  std::string counts;
  for (int owned : parallel::gather_all(std::vector<int>{part.n_owned_nodes}))
    counts += (counts.empty() ? "" : ", ") + std::to_string(owned);
  std::string hook_said;
  if (hook && hook->has_contact())
    hook_said += "; the contact surfaces are whole on every rank, which pairs every point and keeps the contact "
                 "terms of its own nodes' columns";
  if (hook && !hook->related_equations().empty())
    hook_said += "; every rank builds every linear relation (their nodes beyond its part are its ghosts) and "
                 "keeps the terms of its own nodes' columns";
  log.info("mesh in parts on " + std::to_string(part.parts) + " ranks: owned nodes per rank " + counts + ", " +
            std::to_string(numbers.n_global) + " unknowns; each rank assembles the stiffness of its own nodes and "
            "holds its part's vectors" + hook_said);
  return out;
}

SystemLayout RankLayout::system_layout(const FeModel& model, const Mesh& nodes, const DofMap& dofs,
                                       const Constraints& cons, const std::vector<int>& condensed,
                                       const std::vector<int>& eliminated, bool node_blocks) const {
  const Mesh& mesh = *model.mesh;
  SystemLayout layout;
  layout.dim = model.dim;
  for (int c : model.volume_cells()) layout.quadratic = layout.quadratic || cell_info(mesh.cell_types[c]).order > 1;
  layout.block.assign(cons.n_free, -1);
  layout.component.assign(cons.n_free, 0);
  std::vector<char> outside(cons.n_free, 0);
  for (const std::vector<int>* rows : {&condensed, &eliminated})
    for (int eq : *rows)
      if (cons.free_index[eq] >= 0) outside[cons.free_index[eq]] = 1;
  std::vector<int> block_of_node(nodes.n_nodes(), -1);
  for (int eq = 0; eq < dofs.n_dofs(); ++eq) {
    const int k = cons.free_index[eq], c = dofs.component_of(eq);
    if (k < 0 || outside[k] || !is_displacement(c) || c >= layout.dim) continue;
    const int node = dofs.node_of(eq);
    if (block_of_node[node] < 0) {
      block_of_node[node] = layout.n_blocks();
      for (int d = 0; d < layout.dim; ++d) layout.coords.push_back(nodes.node(node)[d]);
    }
    layout.block[k] = block_of_node[node];
    layout.component[k] = c;
  }
  if (in_parts()) {
    for (int eq = 0; eq < dofs.n_dofs(); ++eq)
      if (cons.free_index[eq] >= 0) layout.global.push_back(free_numbers_.global[eq]);
    layout.first = free_numbers_.first;
    layout.n_global = free_numbers_.n_global;
    layout.n_owned = free_numbers_.n_owned;
    // Node blocks for PETSc: every unknown's number (the owned nodes' dim unknowns in a row).
    // Not with a hook's multipliers, which MUMPS alone solves in parts (run() refuses PETSc).
    if (node_blocks) {
      for (int eq = 0; eq < dofs.n_dofs(); ++eq)
        if (cons.free_index[eq] >= 0) layout.row.push_back(unknown_numbers_.global[eq]);
      layout.first_row = unknown_numbers_.first;
      layout.n_rows = unknown_numbers_.n_global;
      layout.n_owned_rows = unknown_numbers_.n_owned;
      layout.row_coords.resize(unknown_numbers_.n_owned);
      for (int eq = 0; eq < unknown_numbers_.n_owned; ++eq) {
        LUNASTER_ASSERT(dofs.component_of(eq) == eq % layout.dim, "in parts every node carries dim unknowns in order");
        layout.row_coords[eq] = mesh.node(dofs.node_of(eq))[dofs.component_of(eq)];
      }
    }
  } else if (kind_ == Kind::Shared) {
    layout.owner.assign(cons.n_free, -1);
    for (int eq = 0; eq < dofs.n_dofs(); ++eq)
      if (cons.free_index[eq] >= 0) layout.owner[cons.free_index[eq]] = node_owner_[dofs.node_of(eq)];
  }
  return layout;
}

SparseMatrix RankLayout::gathered_columns(const FeModel& model, const DofMap& dofs, const MeshPart& part,
                                          const std::vector<int>& nodes) const {
  const int n = dofs.n_dofs();
  std::vector<char> mask(model.mesh->n_nodes(), 0);
  for (int v : nodes)
    if (part.owns(v)) mask[v] = 1;
  const SparseMatrix mine = assemble_stiffness_matrix(model, dofs, &mask);
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

}  // namespace lunaster::engine
