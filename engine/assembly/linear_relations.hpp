#pragma once
/// Linear relations between displacement components, sum_k c_k u(node_k, cmp_k) = 0,
/// each dualised by one multiplier unknown (LAGR_DX.. on a carrier node), as
/// code_aster's LIAISON_DDL: residual r_u += c lambda, r_lambda += sum c_k u_k,
/// tangent [0 c; c^T 0]. Used today by discrete contact on QUAD8 faces (each mid-side
/// node tied to the mean of its edge's vertices, code_aster's CONTACT_8); a Dirichlet
/// condition is the one-term case, which the driver eliminates instead.
///
/// A relation whose every term is imposed by a Dirichlet condition is left out
/// (it holds anyway, and its multiplier would leave the system singular).
#include <set>
#include <utility>
#include <vector>

#include "engine/assembly/dof_map.hpp"
#include "engine/solver/linear_solver.hpp"

namespace lunaster::engine {

struct LinearRelation {
  struct Term { int node; int component; double coef; };
  std::vector<Term> terms;
  int carrier_node = -1;       ///< node carrying the multiplier
  int carrier_component = -1;  ///< LAGR_DX, LAGR_DY or LAGR_DZ
  int multiplier = -1;         ///< its equation once numbered; -1 when left out
};

class LinearRelations {
 public:
  void add(LinearRelation relation) { relations_.push_back(std::move(relation)); }
  bool empty() const { return relations_.empty(); }
  const std::vector<LinearRelation>& relations() const { return relations_; }
  /// Numbers a multiplier for every relation not wholly imposed by `imposed`
  /// ((node, component) pairs fixed by Dirichlet conditions).
  void add_dofs(DofMap& dofs, const std::set<std::pair<int, int>>& imposed);
  /// Residual and tangent of the relations at u (always active: linear).
  void add_to_system(const DofMap& dofs, const Vector& u, std::vector<Triplet>& tangent, Vector& residual) const;

 private:
  std::vector<LinearRelation> relations_;
};

}  // namespace lunaster::engine
