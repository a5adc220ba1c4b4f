// DEBUT and FIN: start and end of a deck (kept for code_aster readers).
#include "commands/commands.hpp"

namespace lunaster::cmd {

ConceptPtr debut(const Args&, Session&) { return nullptr; }

ConceptPtr fin(const Args&, Session& session) {
  session.fin_called = true;
  return nullptr;
}

}  // namespace lunaster::cmd
