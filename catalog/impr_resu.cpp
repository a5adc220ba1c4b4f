#include "catalog/common/keywords.hpp"
#include "catalog/specs.hpp"

namespace lunaster::catalog {

const CommandSpec& impr_resu_spec() {
  static const CommandSpec spec = make_command(
      "IMPR_RESU", "", "Write results to a file in the output folder (MED, or text)",
      {text("FORMAT", "File format").into_values({"MED", "RESULTAT"}).def("MED"),
       integer("UNITE", "Logical unit: 80 writes <deck name>.rmed (MED) or .resu (RESULTAT)").def(80LL).range(1, 99),
       text("FICHIER", "Output file name inside the output folder (overrides UNITE)"),
       factor("RESU",
              {concept_kw("RESULTAT", {"evol_noli"}, "Result to write"),
               concept_kw("MAILLAGE", {"maillage"}, "Mesh to write (FORMAT='MED'; with RESULTAT, its mesh)"),
               text("NOM_CHAM", "Fields of RESULTAT to write (default: all)").many(),
               integer("NUME_ORDRE", "Time steps of RESULTAT to write (default: all)").many(),
               text("GROUP_NO", "Restrict the table to these node groups (FORMAT='RESULTAT' only)").many(),
               text("GROUP_MA", "Restrict the table to the nodes of these cell groups (FORMAT='RESULTAT' only)").many()},
              "What to write")
           .required()
           .occurs(1, -1)
           .with_rules({at_least_one({"RESULTAT", "MAILLAGE"})}),
       common::info()});
  return spec;
}

}  // namespace lunaster::catalog
