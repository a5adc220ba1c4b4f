#pragma once
/// Dirichlet conditions and linear relations between Newton increments, applied by elimination
/// (deal.II's AffineConstraints idea): one object says which unknowns are held and at what value,
/// and one elimination turns K du = -r into the system of the unknowns left.
#include <functional>
#include <utility>
#include <vector>

#include "engine/assembly/dof_map.hpp"
#include "engine/contact/contact_hook.hpp"
#include "engine/nonlinear/loads.hpp"
#include "engine/solver/linear_solver.hpp"

namespace lunaster::engine {

class Halo;

/// Dirichlet conditions at one instant, applied by elimination: the held equations leave the
/// system, the others are renumbered 0..n_free-1 in ascending order.
struct Constraints {
  std::vector<int> free_index;   ///< per equation: index in the reduced system, -1 if constrained
  std::vector<int> constrained;  ///< constrained equations, ascending
  std::vector<double> values;    ///< imposed value per constrained equation
  int n_free = 0;

  /// The equations `loads`' Dirichlet conditions hold: the same set at every instant (only the
  /// imposed values follow the load functions). Sorted, unique. Throws DeckError for a condition
  /// on an unknown the model does not carry.
  static std::vector<int> held_equations(const DofMap& dofs, const MechanicalLoads& loads, const Mesh& mesh);
  /// The conditions at instant t (value * multiplier(t); the last condition on an equation wins).
  static Constraints at_instant(const DofMap& dofs, const MechanicalLoads& loads, double t, const Mesh& mesh);
  /// `constrained` (ascending) held at zero, over `n` equations.
  static Constraints holding(int n, const std::vector<int>& constrained);

  /// In parts: every unknown held as its owner holds it (the part may miss a ghost's constrained
  /// face), through the part's equation halo. Collective.
  void take_from_owners(const Halo& equation_halo);

  /// Writes the imposed values into u.
  void impose(Vector& u) const;

  /// Column of the stiffness K at an eliminated equation: (row over the whole numbering,
  /// value), every row free, zeros left out. Filled by whoever holds K (system_matrix.hpp).
  using Column = std::vector<std::pair<int, double>>;
  using ColumnSource = std::function<void(int eq, Column& column)>;

  /// Elimination of unknowns by linear relations du_E = A du_R + b (contact_hook.hpp):
  /// K' = K_RR + K_RE A + A^T K_ER + A^T K_EE A and r' = (r + K b)_R + A^T (r + K b)_E. Only
  /// the columns of K at E are read (K is symmetric, `columns`), so the cost follows the
  /// relations, not the model. The terms of K' beyond K_RR are appended to `triplets` (as
  /// contact terms, whose columns at E are read too); `r_free` becomes r'. Returns the
  /// eliminated equations, whose rows and columns the system replaces by a unit diagonal.
  std::vector<int> eliminate(const std::vector<Elimination>& relations, const ColumnSource& columns,
                             const Vector& residual, std::vector<Triplet>& triplets, Vector& r_free) const;
  /// After the solve of the eliminated system: du_e = b_e + sum a_k du_k for each relation, added to u.
  void recover(const std::vector<Elimination>& relations, const Vector& du_free, Vector& u) const;
};

}  // namespace lunaster::engine
