#pragma once
/// The exchanges that keep a vector of a distributed mesh consistent among the ranks: each rank
/// holds its owned entries' values and its ghosts' (nodes of a MeshPart, or the unknowns of its
/// DofMap). Assembling its own cells leaves contributions in its ghosts' entries, which
/// add_to_owners() sums into their owners'; copy_to_ghosts() then gives every ghost its owner's
/// value. Each rank talks only with the ranks it shares entries with.
#include <vector>

#include "engine/assembly/dof_map.hpp"
#include "engine/assembly/mesh_part.hpp"

namespace lunaster::engine {

struct GlobalDofs;

class Halo {
 public:
  /// Collective. Per local entry: its global number and its owner; the owned entries are the
  /// first `n_owned`, in ascending global order; a ghost's owner holds it among its owned ones.
  Halo(const std::vector<int>& global, const std::vector<int>& owner, int n_owned, int rank, int parts);

  /// `values`: `block` values per local entry, entry after entry. Adds each ghost's values to
  /// its owner's; the ghosts' entries are left as they were. Collective.
  void add_to_owners(double* values, int block) const;
  void add_to_owners(std::vector<double>& values, int block) const { add_to_owners(values.data(), block); }
  /// Sets each ghost's `block` values to its owner's. Collective.
  void copy_to_ghosts(double* values, int block) const;
  void copy_to_ghosts(std::vector<double>& values, int block) const { copy_to_ghosts(values.data(), block); }

  /// The ranks this one shares entries with, ascending.
  const std::vector<int>& neighbours() const { return ranks_; }
  /// Local entries this rank holds as ghosts of neighbours()[k], and its owned entries that
  /// neighbours()[k] holds as ghosts, each in the order both sides agree on.
  const std::vector<int>& ghosts_of(int k) const { return ghosts_of_[k]; }
  const std::vector<int>& shared_with(int k) const { return shared_with_[k]; }

 private:
  /// Sends `from` lists' values and adds (or writes) what arrives into the `to` lists' entries.
  void move(double* values, int block, const std::vector<std::vector<int>>& from,
            const std::vector<std::vector<int>>& to, bool add) const;
  std::vector<int> ranks_;
  std::vector<std::vector<int>> ghosts_of_;
  std::vector<std::vector<int>> shared_with_;
};

/// The halo of a part's nodes.
class NodeHalo : public Halo {
 public:
  explicit NodeHalo(const MeshPart& part);
};

/// The halo of a part's unknowns numbered across the ranks by number_across_ranks (an unknown is
/// owned by its node's owner). Its entries are the numbered unknowns in their local order: every
/// equation of the DofMap without a mask, the kept ones with one (a system's free unknowns).
Halo equation_halo(const MeshPart& part, const DofMap& dofs, const GlobalDofs& numbers);

}  // namespace lunaster::engine
