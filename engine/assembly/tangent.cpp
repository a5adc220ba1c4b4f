/// Internal force and tangent of a model's behaviours for a Newton driver (tangent.hpp).
#include "engine/assembly/tangent.hpp"

#include "engine/assembly/assembly.hpp"

namespace lunaster::engine {

Tangent::Tangent(const CellBehaviours& behaviours, const DofMap& dofs)
    : behaviours_(behaviours), dofs_(dofs), constant_(behaviours.all_linear()),
      states_(make_material_states(behaviours)) {}

bool Tangent::assemble(const Vector& u, SparseMatrix* k, Vector* f_int) {
  // A linear tangent is the stiffness at rest, assembled by the two-worker column split (the
  // matrix every linear solve has used); the force and the states come from the element loop.
  if (constant_ && k) {
    *k = assemble_stiffness_matrix(behaviours_, dofs_);
    k = nullptr;
  }
  if (!k && !f_int) return true;
  return assemble_internal_force(behaviours_, dofs_, u, states_, f_int, k);
}

}  // namespace lunaster::engine
