#include "catalog/common/keywords.hpp"
#include "catalog/specs.hpp"

namespace lunaster::catalog {

const CommandSpec& modi_maillage_spec() {
  static const CommandSpec spec = make_command(
      "MODI_MAILLAGE", "maillage", "Modify a mesh: orient boundary cells outwards, rotate it",
      {concept_kw("MAILLAGE", {"maillage"}, "Mesh to modify").required(),
       factor("ORIE_PEAU_2D", {common::group_ma("Boundary segment groups to orient").required()},
              "Orient 2D boundary segments so that their normal points out of the body")
           .occurs(0, -1),
       factor("ORIE_PEAU_3D", {common::group_ma("Boundary face groups to orient").required()},
              "Orient 3D boundary faces so that their normal points out of the body")
           .occurs(0, -1),
       factor("ROTATION",
              {real("POIN_1", "A point of the rotation axis (x, y or x, y, z; z = 0 when omitted)").count(2, 3).required(),
               real("ANGLE", "Rotation angle in degrees, counter-clockwise looking against the axis direction "
                             "(right-hand rule)")
                   .required(),
               real("DIR", "Direction of the rotation axis (dx, dy, dz; default: z). In a 2D mesh the axis must be "
                           "along z").count(3, 3),
               real("POIN_2", "A second point of the axis, instead of DIR (as many coordinates as POIN_1)").count(2, 3)},
              "Rotate every node of the mesh about an axis (occurrences are applied in order, before ORIE_PEAU)")
           .occurs(0, -1)
           .with_rules({at_most_one({"DIR", "POIN_2"})}),
       common::info()},
      {at_least_one({"ORIE_PEAU_2D", "ORIE_PEAU_3D", "ROTATION"})}, {}, true);
  return spec;
}

}  // namespace lunaster::catalog
