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
       factor("DEBUG", {text("SDVERI", "code_aster data-structure checks, accepted and ignored").into_values({"OUI", "NON"}),
                        text("JXVERI", "code_aster memory-manager checks, accepted and ignored").into_values({"OUI", "NON"}),
                        text("JEVEUX", "code_aster memory-manager debugging, accepted and ignored").into_values({"OUI", "NON"}),
                        text("HIST_ETAPE", "code_aster command history, accepted and ignored").into_values({"OUI", "NON"})},
              "code_aster debugging switches, accepted and ignored")
           .legacy(),
       factor("ERREUR", {text("ERREUR_F", "code_aster's reaction to an error: lunaster always stops the deck at its "
                                          "first error with the reason, which both values end in")
                             .into_values({"ABORT", "EXCEPTION"})},
              "code_aster error handling, accepted (a lunaster error always stops the deck)")
           .legacy(),
       integer("INFO", "code_aster message level of DEBUT, accepted and ignored (lunaster's log has one level)")
           .into_values({1LL, 2LL})
           .legacy(),
       text("IMPR_MACRO", "code_aster's echo of the commands inside its macros, accepted and ignored (lunaster's "
                          "commands are not macros)")
           .into_values({"OUI", "NON"})
           .legacy(),
       factor("MESURE_TEMPS",
              {integer("NIVE_DETAIL", "0: no report; 1: at the end of each STAT_NON_LINE or MECA_NON_LINE, its wall "
                                      "time and that of its main phases (assembly, contact, factorisation, solve); "
                                      "2: also its counts (instants, Newton iterations, factorisations, contact "
                                      "passes, refinement steps); 3 (code_aster's times of every time step) is "
                                      "refused: lunaster measures whole commands")
                   .into_values({0LL, 1LL, 2LL, 3LL})
                   .def(1LL),
               text("MOYENNE", "OUI: under mpirun, each time as its mean and standard deviation over the ranks "
                               "(NON: rank 0's)")
                   .into_values({"OUI", "NON"})
                   .def("NON")},
              "Report of the time the nonlinear commands took (without MESURE_TEMPS, none)"),
       text("IGNORE_ALARM", "code_aster alarm identifiers to silence, accepted and ignored (lunaster's warnings "
                            "have no identifiers)")
           .many()
           .legacy()});
  return spec;
}

}  // namespace lunaster::catalog
