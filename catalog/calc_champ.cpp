#include "catalog/common/keywords.hpp"
#include "catalog/specs.hpp"

namespace lunaster::catalog {

const CommandSpec& calc_champ_spec() {
  static const CommandSpec spec = make_command(
      "CALC_CHAMP", "evol_noli", "Compute derived fields (stresses, equivalent stresses, nodal forces and reactions) of a result",
      {concept_kw("RESULTAT", {"evol_noli"}, "Result to enrich").required(),
       text("CONTRAINTE",
            "Stress fields to compute: SIGM_ELNO, SIGM_NOEU, and SIEF_ELNO, SIEF_NOEU (code_aster's stresses of the "
            "nonlinear computation at the cells' nodes and their nodal means: with RELATION='ELAS', the only "
            "behaviour here, the same values as SIGM_ELNO and SIGM_NOEU, as code_aster gets on a STAT_NON_LINE "
            "result of continuum cells)")
           .into_values({"SIGM_ELNO", "SIGM_NOEU", "SIEF_ELNO", "SIEF_NOEU"})
           .many(),
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
