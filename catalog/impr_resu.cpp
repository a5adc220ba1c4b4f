#include "catalog/common/keywords.hpp"
#include "catalog/specs.hpp"

namespace lunaster::catalog {

const CommandSpec& impr_resu_spec() {
  static const CommandSpec spec = make_command(
      "IMPR_RESU", "", "Write results to a file in the output folder (MED, or text)",
      {text("FORMAT", "File format").into_values({"MED", "RESULTAT"}).def("MED"),
       integer("UNITE", "Logical unit: 80 writes <deck name>.rmed (MED) or .resu (RESULTAT)").def(80LL).range(1, 99),
       text("FICHIER", "Output file name inside the output folder (overrides UNITE)"),
       concept_kw("MODELE", {"modele"},
                  "Write only what lies on this model's cells (those carrying an element, and the boundary cells whose "
                  "nodes are all theirs): FORMAT='RESULTAT' prints the nodes of its cells "
                  "(and, under MAILLAGE, only its cells); FORMAT='MED', whose file holds the whole mesh, takes a "
                  "model of every cell of the mesh only. Its mesh must be that of RESU"),
       factor("RESU",
              {concept_kw("RESULTAT", {"evol_noli"}, "Result to write"),
               concept_kw("MAILLAGE", {"maillage"},
                          "Mesh to write (with RESULTAT, its mesh): FORMAT='MED' writes it in the file, "
                          "FORMAT='RESULTAT' prints its nodes' coordinates and its cells' nodes"),
               text("NOM_CHAM", "Fields of RESULTAT to write (default: all)").many(),
               text("NOM_CMP",
                    "Components to write (default: all): each field keeps those of them it has, a field with "
                    "none of them is left out; a component no field written has is an error")
                   .many(),
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
