#include "catalog/common/keywords.hpp"
#include "catalog/specs.hpp"

namespace lunaster::catalog {

const CommandSpec& defi_group_spec() {
  static const CommandSpec spec = make_command(
      "DEFI_GROUP", "maillage", "Create node or cell groups in a mesh",
      {concept_kw("MAILLAGE", {"maillage"}, "Mesh to enrich").required(),
       factor("CREA_GROUP_NO",
              {common::group_ma("Cell groups whose nodes form node groups of the same name (or NOM)"),
               common::noeud("Nodes of the new group (with NOM)"),
               text("TOUT_GROUP_MA", "Create a node group for every cell group").into_values({"OUI"}),
               text("NOM", "Name of the new node group")},
              "Create node groups")
           .occurs(0, -1)
           .with_rules({exactly_one({"GROUP_MA", "NOEUD", "TOUT_GROUP_MA"}), present_present({"NOEUD", "NOM"})}),
       factor("CREA_GROUP_MA",
              {text("NOM", "Name of the new cell group").required(), common::group_ma("Cell groups to merge"),
               common::maille("Cells of the new group")},
              "Create cell groups")
           .occurs(0, -1)
           .with_rules({exactly_one({"GROUP_MA", "MAILLE"})}),
       common::info()},
      {at_least_one({"CREA_GROUP_NO", "CREA_GROUP_MA"})}, {}, true);
  return spec;
}

}  // namespace lunaster::catalog
