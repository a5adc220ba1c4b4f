#include "catalog/common/keywords.hpp"
#include "catalog/specs.hpp"

namespace lunaster::catalog {

const CommandSpec& calc_champ_spec() {
  static const CommandSpec spec = make_command(
      "CALC_CHAMP", "evol_noli", "Compute derived fields (stresses, equivalent stresses, nodal forces and reactions) of a result",
      {concept_kw("RESULTAT", {"evol_noli"}, "Result to enrich").required(),
       text("CONTRAINTE", "Stress fields to compute").into_values({"SIGM_ELNO", "SIGM_NOEU"}).many(),
       text("CRITERES", "Equivalent stress fields to compute").into_values({"SIEQ_ELNO", "SIEQ_NOEU"}).many(),
       text("FORCE",
            "Nodal force fields: FORC_NODA (internal forces B^T sigma at every node of the model) and REAC_NODA "
            "(FORC_NODA minus the applied pressures and nodal forces: the reactions of supports and contact)")
           .into_values({"FORC_NODA", "REAC_NODA"})
           .many(),
       integer("NUME_ORDRE", "Time step numbers to process").many(), real("INST", "Times to process").many(),
       text("TOUT_ORDRE", "Process every time step (default)").into_values({"OUI"}),
       common::info()},
      {at_most_one({"NUME_ORDRE", "INST", "TOUT_ORDRE"}), at_least_one({"CONTRAINTE", "CRITERES", "FORCE"})}, {}, true);
  return spec;
}

}  // namespace lunaster::catalog
