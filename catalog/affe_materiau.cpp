#include "catalog/common/keywords.hpp"
#include "catalog/specs.hpp"

namespace lunaster::catalog {

const CommandSpec& affe_materiau_spec() {
  static const CommandSpec spec = make_command(
      "AFFE_MATERIAU", "cham_mater", "Assign materials to mesh cells",
      {concept_kw("MAILLAGE", {"maillage"}, "Mesh carrying the materials").required(),
       concept_kw("MODELE", {"modele"}, "Model (optional, checked against the mesh)"),
       factor("AFFE",
              {common::tout("Assign to every cell"), common::group_ma("Cell groups to assign"),
               concept_kw("MATER", {"mater"}, "Material to assign").required()},
              "One assignment of a material to cells")
           .required()
           .occurs(1, -1)
           .with_rules({exactly_one({"TOUT", "GROUP_MA"})}),
       common::info()});
  return spec;
}

}  // namespace lunaster::catalog
