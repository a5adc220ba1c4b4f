#pragma once
/// Linear relations between displacement components (LIAISON_DDL) in the Newton system:
/// one multiplier per relation (linear_relations.hpp), added to the system as the contact
/// terms are, through the driver's ContactHook interface. Wraps the run's contact hook when
/// there is one, which keeps its own terms, statuses and results; without one, the relations
/// are the only terms besides K, and the driver runs no contact pass.
#include <memory>
#include <vector>

#include "engine/nonlinear/contact_hook.hpp"

namespace lunaster::engine {

/// `relations`: two terms or more each (split_dirichlet gave the others to the Dirichlet
/// conditions); `multipliers`: the load functions their right-hand sides follow (loads.hpp);
/// `contact`: the run's contact hook, or null.
std::unique_ptr<ContactHook> make_relations_hook(std::vector<LinearRelation> relations,
                                                 std::vector<std::function<double(double)>> multipliers,
                                                 std::unique_ptr<ContactHook> contact);

}  // namespace lunaster::engine
