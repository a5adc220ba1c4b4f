#include "engine/contact/contact_factory.hpp"

#include "engine/contact/continuous_contact.hpp"
#include "engine/contact/discrete_contact.hpp"

namespace lunaster::engine {

std::unique_ptr<ContactHook> make_contact_hook(const ContactDefinition& definition, const Mesh& mesh, int dim) {
  switch (definition.method) {
    case ContactMethod::Continuous:
    case ContactMethod::ContinuousPenalty:
      return std::make_unique<contact::ContinuousContact>(definition, mesh, dim);
    case ContactMethod::DiscreteLagrange:
    case ContactMethod::DiscretePenalty:
      return std::make_unique<contact::DiscreteContact>(definition, mesh, dim);
  }
  return nullptr;
}

}  // namespace lunaster::engine
