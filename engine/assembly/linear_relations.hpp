#pragma once
/// Linear relations between displacement components, sum_k c_k u(node_k, cmp_k) = v(t),
/// each dualised by one multiplier unknown (LAGR_DX.. on a carrier node), as code_aster's
/// LIAISON_DDL: residual r_u += c lambda, r_lambda += sum c_k u_k - v(t), tangent [0 c; c^T 0].
/// v(t) = value * (multiplier of load `load` at t), as for Dirichlet values (loads.hpp).
///
/// One facility for every kinematic condition:
/// - a one-term relation c u = v is a Dirichlet condition u = v / c, which the driver
///   eliminates: split_dirichlet() moves it there, so no multiplier is ever spent on it;
/// - the others are dualised here: the deck's LIAISON_DDL, and the ties discrete contact puts
///   on QUAD8 faces (each mid-side node tied to the mean of its edge's vertices, code_aster's
///   CONTACT_8).
///
/// A relation whose every term is imposed by a Dirichlet condition is left out (it holds
/// anyway, and its multiplier would leave the system singular).
#include <functional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "engine/assembly/dof_map.hpp"
#include "engine/core/linalg.hpp"

namespace lunaster::engine {

/// Imposed value of one displacement component; `load` indexes the multiplier (loads.hpp).
/// Here, beside the relations, because a one-term relation becomes one (split_dirichlet).
struct DirichletValue { int node; int component; double value; int load; };

struct LinearRelation {
  struct Term { int node; int component; double coef; };
  std::vector<Term> terms;
  double value = 0.0;          ///< right-hand side v, scaled by the load's multiplier
  int load = -1;               ///< index of the load multiplier; -1: v as given
  int carrier_node = -1;       ///< node carrying the multiplier; -1: chosen by add_dofs
  int carrier_component = -1;  ///< LAGR_DX, LAGR_DY or LAGR_DZ
  int multiplier = -1;         ///< its equation once numbered; -1 when left out
  std::string label;           ///< what messages call it ("LIAISON_DDL[2] of CHARGE 'CH'"); see relation_name
};

/// How messages name relation `index` (0-based) of a list: its label, else "linear relation N".
std::string relation_name(const LinearRelation& relation, size_t index);

class LinearRelations {
 public:
  LinearRelations() = default;
  explicit LinearRelations(std::vector<LinearRelation> relations) : relations_(std::move(relations)) {}
  void add(LinearRelation relation) { relations_.push_back(std::move(relation)); }
  bool empty() const { return relations_.empty(); }
  const std::vector<LinearRelation>& relations() const { return relations_; }
  /// Numbers a multiplier for every relation not wholly imposed by `imposed`
  /// ((node, component) pairs fixed by Dirichlet conditions). A relation without a carrier
  /// gets the first free slot LAGR_DX, LAGR_DY, LAGR_DZ of its terms' nodes, in term order;
  /// throws DeckError naming the relation when every slot is taken (three multipliers
  /// per node at most).
  void add_dofs(DofMap& dofs, const std::set<std::pair<int, int>>& imposed);
  /// Whether any relation has a multiplier (after add_dofs).
  bool any_multiplier() const;
  /// Residual and tangent of the relations at u (always active: linear). `factor(load)` is
  /// the multiplier of a relation's right-hand side; without it, the values as given.
  void add_to_system(const DofMap& dofs, const Vector& u, std::vector<Triplet>& tangent, Vector& residual,
                     const std::function<double(int)>& factor = {}) const;
  /// The residual part of add_to_system alone.
  void add_residual(const DofMap& dofs, const Vector& u, Vector& residual,
                    const std::function<double(int)>& factor = {}) const;

 private:
  std::vector<LinearRelation> relations_;
};

/// True when every term of `relation` is on a (node, component) of `imposed`: the relation
/// then needs no unknown of its own (its multiplier would leave the system singular).
bool imposed_only(const LinearRelation& relation, const std::set<std::pair<int, int>>& imposed);

/// Sums the terms of each relation on one (node, component) and drops those whose sum is
/// zero; then moves every relation left with one term, c u = v, to `dirichlet` as u = v / c
/// (same load). Returns the relations left (two terms or more, in their order). A relation
/// left with no term is returned too, for the caller to refuse (0 = v).
std::vector<LinearRelation> split_dirichlet(std::vector<LinearRelation> relations,
                                            std::vector<DirichletValue>& dirichlet);

}  // namespace lunaster::engine
