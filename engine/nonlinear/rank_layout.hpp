#pragma once
/// How a run's unknowns are laid out over the ranks of an MPI run: what differs between a run
/// on one process, a model shared among the ranks and a mesh in parts, asked of one object
/// instead of tested as flags throughout the driver.
#include <memory>

#include "engine/assembly/halo.hpp"
#include "engine/solver/linear_solver.hpp"

namespace lunaster::engine {

class RankLayout {
 public:
  enum class Kind {
    Whole,   ///< every rank (or the one process) holds the whole model and every entry
    Shared,  ///< the model shared among the ranks: each holds its own nodes' stiffness columns, vectors whole
    InParts  ///< a mesh in parts: vectors are the part's (owned entries first, then the ghosts')
  };
  RankLayout() = default;
  /// Whole or Shared (no halo).
  explicit RankLayout(Kind kind) : kind_(kind) {}
  /// InParts: the part's equation halo (owned by the layout) and its owned unknowns (the first ones).
  RankLayout(std::unique_ptr<Halo> equation_halo, int owned_equations)
      : kind_(Kind::InParts), equation_halo_(std::move(equation_halo)), owned_equations_(owned_equations) {}

  Kind kind() const { return kind_; }
  /// Whether this rank holds the whole stiffness (Whole).
  bool whole() const { return kind_ == Kind::Whole; }
  bool in_parts() const { return kind_ == Kind::InParts; }
  /// The part's equation halo (InParts only).
  const Halo& equation_halo() const { return *equation_halo_; }
  /// Of the n unknowns a vector has here, those this rank answers for in norms: all of them,
  /// or in parts its owned ones.
  int owned_equations(int n) const { return in_parts() ? owned_equations_ : n; }
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

 private:
  Kind kind_ = Kind::Whole;
  std::unique_ptr<Halo> equation_halo_;
  int owned_equations_ = 0;
};

}  // namespace lunaster::engine
