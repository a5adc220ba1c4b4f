#include "catalog/common/keywords.hpp"
#include "catalog/specs.hpp"

namespace lunaster::catalog {

const CommandSpec& calc_champ_spec() {
  static const CommandSpec spec = make_command(
      "CALC_CHAMP", "evol_noli", "Compute derived fields (stresses, equivalent stresses) of a result",
      {concept_kw("RESULTAT", {"evol_noli"}, "Result to enrich").required(),
       text("CONTRAINTE", "Stress fields to compute").into_values({"SIGM_ELNO", "SIGM_NOEU"}).many(),
       text("CRITERES", "Equivalent stress fields to compute").into_values({"SIEQ_ELNO", "SIEQ_NOEU"}).many(),
       integer("NUME_ORDRE", "Time step numbers to process").many(), real("INST", "Times to process").many(),
       text("TOUT_ORDRE", "Process every time step (default)").into_values({"OUI"}),
       common::info()},
      {at_most_one({"NUME_ORDRE", "INST", "TOUT_ORDRE"}), at_least_one({"CONTRAINTE", "CRITERES"})}, {}, true);
  return spec;
}

}  // namespace lunaster::catalog
