#pragma once
/// Commands on a mesh in parts (LIRE_MAILLAGE's PARTITIONNEUR, docs/distributed-model.md step 4).
///
/// Every rank runs the same command on its own part. What a rank finds or misses in its part
/// (a group empty here, a node name another rank holds, a check failing on one cell) must not
/// stop that rank alone: the others would wait for it in the next collective call. So:
/// - a requirement that only the whole mesh can settle (a group not empty, a name that exists)
///   is recorded with require_somewhere and decided over the ranks where the command agrees;
/// - a command agrees (agree_over_ranks) at its end, and before its first collective call:
///   if any rank failed, every rank throws the same error (the failure of the lowest failing
///   rank); if a requirement holds on no rank, every rank throws its error.
/// On a whole mesh, require_somewhere throws at once and agreeing does nothing.
#include <exception>
#include <string>

#include "engine/core/error.hpp"
#include "engine/mesh/mesh.hpp"

namespace lunaster::cmd {

/// On a whole mesh: throws `error` unless `holds_here`. On a part: records the requirement,
/// decided over the ranks by the next agree_over_ranks (it throws `error` if it holds on none).
void require_somewhere(const engine::Mesh& mesh, bool holds_here, const DeckError& error);

/// Collective on a run with a mesh in parts (every rank at the same point of the same command;
/// nothing otherwise): `failure` is this rank's exception (null if it did not fail). Throws on
/// every rank the error of a requirement held by no rank, else the failure of the lowest
/// failing rank (its own on a failing rank), else returns. Clears the recorded requirements.
void agree_over_ranks(std::exception_ptr failure);

/// Forgets the requirements recorded so far (a new command begins).
void forget_requirements();

/// True once the deck being run read a mesh in parts: commands then agree over the ranks. Set by
/// LIRE_MAILLAGE, cleared when a deck's run begins.
bool parts_in_run();
void set_parts_in_run(bool on);

/// The commands written for concepts on a mesh in parts; the runner refuses such a concept to
/// any other, naming them.
bool takes_parts(const std::string& command);
std::string commands_taking_parts();

/// Runs `step` and agrees over the ranks on how it went (agree_over_ranks): before a command's
/// first collective call, so that no rank enters it while another has stopped.
template <class Step>
void agreed(Step&& step) {
  std::exception_ptr failure;
  try {
    step();
  } catch (...) {
    failure = std::current_exception();
  }
  agree_over_ranks(failure);
}

}  // namespace lunaster::cmd
