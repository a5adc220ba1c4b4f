#include "catalog/common/keywords.hpp"
#include "catalog/specs.hpp"

namespace lunaster::catalog {

const CommandSpec& defi_list_inst_spec() {
  static const CommandSpec spec = make_command(
      "DEFI_LIST_INST", "list_inst", "Define time steps with automatic step cutting on failure",
      {factor("DEFI_LIST",
              {text("METHODE", "How the steps are given (only 'MANUEL')").into_values({"MANUEL"}).def("MANUEL"),
               concept_kw("LIST_INST", {"listr8"}, "The time steps").required()},
              "The initial list of time steps")
           .required(),
       factor("ECHEC",
              {text("EVENEMENT", "Event triggering the action").into_values({"ERREUR"}).def("ERREUR"),
               text("ACTION", "Cut the step, or stop").into_values({"DECOUPE", "ARRET"}).def("DECOUPE"),
               text("SUBD_METHODE", "How the step is cut").into_values({"MANUEL"}).def("MANUEL"),
               integer("SUBD_PAS", "Number of sub-steps a failed step is cut into").def(4LL).range(2, std::nullopt),
               integer("SUBD_NIVEAU", "Maximum number of successive cuts").def(3LL).range(0, std::nullopt)},
              "What to do when a step fails")
           .occurs(0, -1),
       common::info()});
  return spec;
}

}  // namespace lunaster::catalog
