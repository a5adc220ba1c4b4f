#include "catalog/common/keywords.hpp"
#include "catalog/specs.hpp"

namespace lunaster::catalog {

const CommandSpec& affe_modele_spec() {
  static const CommandSpec spec = make_command(
      "AFFE_MODELE", "modele", "Assign finite elements (phenomenon and modelling) to mesh cells",
      {concept_kw("MAILLAGE", {"maillage"}, "Mesh of the model").required(),
       factor("AFFE",
              {common::tout("Assign to every cell"), common::group_ma("Cell groups to assign"),
               text("PHENOMENE", "Physical phenomenon").into_values({"MECANIQUE"}).required(),
               text("MODELISATION",
                    "Modelling: plane strain, plane stress, 3D, or axisymmetric (AXIS: x is the radius r >= 0, "
                    "y the axis; SIZZ is the hoop stress; integrals are per radian as in code_aster, so "
                    "FORCE_NODALE values and nodal reactions are per radian; AXIS cannot be mixed with D_PLAN/C_PLAN)")
                   .into_values({"D_PLAN", "C_PLAN", "3D", "AXIS"})
                   .required()},
              "One assignment of elements to cells")
           .required()
           .occurs(1, -1)
           .with_rules({exactly_one({"TOUT", "GROUP_MA"})}),
       common::info()});
  return spec;
}

}  // namespace lunaster::catalog
