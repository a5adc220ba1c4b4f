#include "engine/contact/contact_factory.hpp"

#include "engine/contact/contact_problem.hpp"
#include "engine/contact/mortar_problem.hpp"

namespace lunaster::engine {

std::unique_ptr<ContactHook> make_contact_hook(const ContactDefinition& definition, const Mesh& mesh, int dim) {
  using namespace contact;
  if (definition.method == ContactMethod::MortarLagrange || definition.method == ContactMethod::MortarPenalty)
    return std::make_unique<MortarProblem>(definition, mesh, dim);
  std::unique_ptr<Discretisation> where;
  std::unique_ptr<ContactLaw> how;
  switch (definition.method) {
    case ContactMethod::Continuous: where = make_integration_points(), how = make_augmented_lagrangian_law(); break;
    case ContactMethod::ContinuousPenalty: where = make_integration_points(), how = make_penalty_law(false); break;
    case ContactMethod::DiscreteLagrange:
      where = make_node_to_segment(definition.axisymmetric), how = make_active_set_law();
      break;
    case ContactMethod::DiscretePenalty:
      where = make_node_to_segment(definition.axisymmetric), how = make_penalty_law(true);
      break;
    default: break;
  }
  return std::make_unique<ContactProblem>(definition, mesh, dim, std::move(where), std::move(how));
}

}  // namespace lunaster::engine
