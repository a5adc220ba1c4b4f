#pragma once
/// The exchanges that keep a vector of a distributed mesh's nodes consistent among the ranks:
/// each rank holds its owned nodes' values and its ghosts' (MeshPart). Assembling its own cells
/// leaves contributions in its ghosts' entries, which add_to_owners() sums into their owners';
/// copy_to_ghosts() then gives every ghost its owner's value. Each rank talks only with the
/// ranks it shares nodes with.
#include <vector>

#include "engine/assembly/mesh_part.hpp"

namespace lunaster::engine {

class NodeHalo {
 public:
  /// Collective: every rank builds its halo from its own part.
  explicit NodeHalo(const MeshPart& part);

  /// `values`: `block` values per local node, node after node. Adds each ghost's values to its
  /// owner's; the ghosts' entries are left as they were. Collective.
  void add_to_owners(std::vector<double>& values, int block) const;
  /// Sets each ghost's `block` values to its owner's. Collective.
  void copy_to_ghosts(std::vector<double>& values, int block) const;

  /// The ranks this one shares nodes with, ascending.
  const std::vector<int>& neighbours() const { return ranks_; }
  /// Local nodes this rank holds as ghosts of neighbours()[k], and its owned nodes that
  /// neighbours()[k] holds as ghosts, each in the order both sides agree on.
  const std::vector<int>& ghosts_of(int k) const { return ghosts_of_[k]; }
  const std::vector<int>& shared_with(int k) const { return shared_with_[k]; }

 private:
  /// Sends `from` lists' values and adds (or writes) what arrives into the `to` lists' nodes.
  void move(std::vector<double>& values, int block, const std::vector<std::vector<int>>& from,
            const std::vector<std::vector<int>>& to, bool add) const;
  std::vector<int> ranks_;
  std::vector<std::vector<int>> ghosts_of_;
  std::vector<std::vector<int>> shared_with_;
};

}  // namespace lunaster::engine
