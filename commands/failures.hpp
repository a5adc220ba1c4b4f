#pragma once
/// The engine reports a failure in its own terms (iterations, residuals, tolerances) with
/// its numbers in Error::failure(); here it is said again in the keywords of the deck.
#include "engine/core/error.hpp"

namespace lunaster::cmd {

/// Rephrases `err` (message and hints) with the deck keywords that govern what failed:
/// ITER_GLOB_MAXI, RESI_GLOB_RELA, ITER_CONT_MAXI, CONTACT_INIT, SOLVEUR, FORMAT ...
/// Errors without a typed failure are left as they are.
void say_in_keywords(Error& err);

}  // namespace lunaster::cmd
