#include "catalog/common/keywords.hpp"
#include "catalog/specs.hpp"

namespace lunaster::catalog {

const CommandSpec& modi_maillage_spec() {
  static const CommandSpec spec = make_command(
      "MODI_MAILLAGE", "maillage", "Modify a mesh: orient boundary cells outwards",
      {concept_kw("MAILLAGE", {"maillage"}, "Mesh to modify").required(),
       factor("ORIE_PEAU_2D", {common::group_ma("Boundary segment groups to orient").required()},
              "Orient 2D boundary segments so that their normal points out of the body")
           .occurs(0, -1),
       factor("ORIE_PEAU_3D", {common::group_ma("Boundary face groups to orient").required()},
              "Orient 3D boundary faces so that their normal points out of the body")
           .occurs(0, -1),
       common::info()},
      {at_least_one({"ORIE_PEAU_2D", "ORIE_PEAU_3D"})}, {}, true);
  return spec;
}

}  // namespace lunaster::catalog
