#include "catalog/common/keywords.hpp"
#include "catalog/specs.hpp"

namespace lunaster::catalog {

// code_aster's debugging and batch switches change nothing in a lunaster run's results; they
// are accepted (and documented as such) so that code_aster command files run as they are.
const CommandSpec& debut_spec() {
  static const CommandSpec spec = make_command(
      "DEBUT", "", "Start of a study (accepted for code_aster decks; a deck may also start without it)",
      {text("CODE", "code_aster test-suite marker, accepted and ignored; the older form "
                    "CODE=_F(NIV_PUB_WEB='INTERNET'|'INTRANET', VISU_EFICAS='OUI'|'NON') too")
           .into_values({"OUI", "NON"})
           .or_factor({text("NIV_PUB_WEB", "code_aster publication level, ignored").into_values({"INTERNET", "INTRANET"}),
                       text("VISU_EFICAS", "code_aster GUI flag, ignored").into_values({"OUI", "NON"})})
           .legacy(),
       text("PAR_LOT", "code_aster batch mode switch, accepted and ignored").into_values({"OUI", "NON"}).legacy(),
       factor("DEBUG", {text("SDVERI", "code_aster data-structure checks, accepted and ignored").into_values({"OUI", "NON"})},
              "code_aster debugging switches, accepted and ignored")
           .legacy(),
       text("IGNORE_ALARM", "code_aster alarm identifiers to silence, accepted and ignored (lunaster's warnings "
                            "have no identifiers)")
           .many()
           .legacy()});
  return spec;
}

}  // namespace lunaster::catalog
