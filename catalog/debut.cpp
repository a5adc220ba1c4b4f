#include "catalog/common/keywords.hpp"
#include "catalog/specs.hpp"

namespace lunaster::catalog {

const CommandSpec& debut_spec() {
  static const CommandSpec spec = make_command(
      "DEBUT", "", "Start of a study (accepted for code_aster decks; a deck may also start without it)",
      {text("CODE", "code_aster test-suite marker, accepted and ignored").into_values({"OUI", "NON"}).legacy(),
       text("PAR_LOT", "code_aster batch mode switch, accepted and ignored").into_values({"OUI", "NON"}).legacy()});
  return spec;
}

}  // namespace lunaster::catalog
