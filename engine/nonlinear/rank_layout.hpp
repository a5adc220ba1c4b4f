#pragma once
/// How a run's unknowns are laid out over the ranks of an MPI run: what differs between a run
/// on one process, a model shared among the ranks and a mesh in parts, held by one object
/// (who owns which node, the numbering across the ranks, the exchanges) and asked of it
/// instead of tested as flags throughout the driver.
#include <memory>
#include <vector>

#include "engine/assembly/dof_map.hpp"
#include "engine/assembly/global_dofs.hpp"
#include "engine/assembly/halo.hpp"
#include "engine/assembly/mesh_part.hpp"
#include "engine/core/log.hpp"
#include "engine/fe/fe_model.hpp"
#include "engine/nonlinear/constraints.hpp"
#include "engine/contact/contact_hook.hpp"
#include "engine/solver/linear_solver.hpp"

namespace lunaster::engine {

class RankLayout {
 public:
  enum class Kind {
    Whole,   ///< every rank (or the one process) holds the whole model and every entry
    Shared,  ///< the model shared among the ranks: each holds its own nodes' stiffness columns, vectors whole
    InParts  ///< a mesh in parts: vectors are the part's (owned entries first, then the ghosts')
  };
  /// Whole.
  RankLayout() = default;
  /// The model's volume cells partitioned among the ranks (Scotch): each rank assembles the
  /// columns of the nodes it owns; `hook` (may be null) shares its pairing among the ranks.
  /// Said in the log. Collective.
  static RankLayout shared(const FeModel& model, ContactHook* hook, const Log& log);
  /// This rank's part of a mesh in parts; `numbered`: the part with the hook's nodes (or the
  /// part), whose unknowns `dofs` numbers. `constrained` becomes the set the owners hold.
  /// Said in the log. Collective.
  static RankLayout in_parts(const MeshPart& part, const MeshPart& numbered, const DofMap& dofs,
                             const NodeHalo& node_halo, std::vector<int>& constrained, const ContactHook* hook,
                             const Log& log);

  Kind kind() const { return kind_; }
  bool in_parts() const { return kind_ == Kind::InParts; }
  /// The part's equation halo (InParts only).
  const Halo& equation_halo() const { return *equation_halo_; }
  /// The system's free unknowns numbered across the ranks, and their exchanges (InParts only).
  const GlobalDofs& free_numbers() const { return free_numbers_; }
  const Halo& free_halo() const { return *free_halo_; }
  /// Every unknown of the part numbered across the ranks (InParts only).
  const GlobalDofs& unknown_numbers() const { return unknown_numbers_; }
  /// Per node, whether this rank assembles its columns (Shared, InParts); null when Whole.
  const std::vector<char>* owned_nodes() const { return kind_ == Kind::Whole ? nullptr : &owned_nodes_; }
  /// Per node, the rank owning its equations (Shared, InParts; -1 outside the cells).
  const std::vector<int>& node_owner() const { return node_owner_; }
  /// Per mesh cell, the rank whose volume cell it is (-1 for other cells); empty when Whole.
  const std::vector<int>& cell_rank() const { return cell_rank_; }
  /// Of the n unknowns a vector has here, those this rank answers for in norms: all of them,
  /// or in parts its owned ones.
  int owned_equations(int n) const { return in_parts() ? unknown_numbers_.n_owned : n; }
  /// The system's equations over the ranks: n_free here, or in parts over all of them.
  long long global_free(int n_free) const { return in_parts() ? free_numbers_.n_global : n_free; }
  /// Of the n_free equations here, those this rank answers for in norms.
  int owned_free(int n_free) const { return in_parts() ? free_numbers_.n_owned : n_free; }

  /// The largest |v_i| over the first n_owned entries, over the ranks in parts (a NaN stays a
  /// NaN). Collective in parts.
  double largest_entry(const Vector& v, int n_owned) const;
  /// A value each rank computed on its own entries, as the ranks' largest in parts. Collective in parts.
  double largest_over_ranks(double here) const;
  /// A decision the ranks take together in parts: true when every rank's is. Collective in parts.
  bool all_ranks(bool here) const;
  /// v holds this rank's share of a sum (products with its stiffness columns): made whole,
  /// summed over the ranks (Shared), or its owned entries completed and copied to the ghosts
  /// (InParts). Collective unless Whole.
  void complete(Vector& v) const;

  /// The node blocks of the system's equations (condensed and eliminated equations left out),
  /// what algebraic multigrid aggregates, with the coordinates of its rigid-body modes, and
  /// how they are numbered across the ranks. `nodes`: the mesh of the unknowns' nodes;
  /// `node_blocks`: in parts, every unknown's number for PETSc's node blocks (not with a
  /// hook's multipliers).
  SystemLayout system_layout(const FeModel& model, const Mesh& nodes, const DofMap& dofs, const Constraints& cons,
                             const std::vector<int>& condensed, const std::vector<int>& eliminated,
                             bool node_blocks) const;
  /// In parts: the stiffness columns of `nodes`' unknowns, whole, on every rank (each assembled
  /// by the node's owner; in this rank's numbering). Collective.
  SparseMatrix gathered_columns(const FeModel& model, const DofMap& dofs, const MeshPart& part,
                                const std::vector<int>& nodes) const;

 private:
  Kind kind_ = Kind::Whole;
  std::unique_ptr<Halo> equation_halo_;
  std::unique_ptr<Halo> free_halo_;
  GlobalDofs free_numbers_;
  GlobalDofs unknown_numbers_;  ///< every unknown of the part, numbered across the ranks (PETSc's rows)
  std::vector<int> node_owner_;
  std::vector<char> owned_nodes_;
  std::vector<int> cell_rank_;
};

}  // namespace lunaster::engine
