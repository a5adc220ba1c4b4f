#include "engine/contact/contact_factory.hpp"

#include "engine/contact/contact_problem.hpp"
#include "engine/contact/mortar_problem.hpp"

namespace lunaster::engine {

std::unique_ptr<ContactHook> make_contact_hook(const ContactDefinition& definition, const Mesh& mesh, int dim) {
  using namespace contact;
  std::unique_ptr<ContactLaw> how = make_contact_law(definition.method.how);
  switch (definition.method.where) {
    case ContactDiscretisation::MortarSegments:
      return std::make_unique<MortarProblem>(definition, mesh, dim, std::move(how));
    case ContactDiscretisation::IntegrationPoints:
      return std::make_unique<ContactProblem>(definition, mesh, dim, make_integration_points(), std::move(how));
    case ContactDiscretisation::NodeToSegment:
      return std::make_unique<ContactProblem>(definition, mesh, dim, make_node_to_segment(definition.axisymmetric),
                                              std::move(how));
  }
  return nullptr;
}

}  // namespace lunaster::engine
