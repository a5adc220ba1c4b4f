#pragma once
/// Linear relations between displacement components (LIAISON_DDL, LIAISON_UNIF) in the Newton system:
/// one multiplier per relation (linear_relations.hpp), or each relation solved for one of its
/// unknowns (eliminated), added to the system as the contact terms are, through the driver's
/// ContactHook interface. Wraps the run's contact hook when there is one, which keeps its own
/// terms, statuses and results; without one, the relations are the only terms besides K, and
/// the driver runs no contact pass.
#include <memory>
#include <vector>

#include "engine/contact/contact_hook.hpp"

namespace lunaster::engine {

/// `relations`: two terms or more each (split_dirichlet gave the others to the Dirichlet
/// conditions); `multipliers`: the load functions their right-hand sides follow (loads.hpp);
/// `contact`: the run's contact hook, or null. `eliminate`: each relation solved for one of
/// its unknowns instead of a multiplier (the driver's eliminations, contact_hook.hpp), so the
/// system keeps K's kind; the contact hook must then eliminate nothing itself (the two sets of
/// eliminations are not closed against each other). A relation that is a combination of the
/// ones before it stops the run (DeckError) when eliminated.
std::unique_ptr<ContactHook> make_relations_hook(std::vector<LinearRelation> relations,
                                                 std::vector<std::function<double(double)>> multipliers,
                                                 std::unique_ptr<ContactHook> contact, bool eliminate = false);

}  // namespace lunaster::engine
