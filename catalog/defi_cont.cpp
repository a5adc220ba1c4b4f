#include "catalog/common/keywords.hpp"
#include "catalog/specs.hpp"

namespace lunaster::catalog {

namespace {

Keyword mortar_zone() {
  std::vector<Keyword> children = {
      text("APPARIEMENT", "Pairing and discretisation of the zone: mortar (segment-to-segment, dual multipliers)")
          .into_values({"MORTAR"})
          .def("MORTAR"),
      text("GROUP_MA_ESCL", "Slave boundary cell group (carries the contact conditions)").required(),
      text("GROUP_MA_MAIT", "Master boundary cell group").required(),
      text("ALGO_CONT",
           "Enforcement: exact weighted gaps with multipliers eliminated from the solve (the system stays symmetric "
           "positive definite), or a penalty on the weighted gaps")
          .into_values({"LAGRANGIEN", "PENALISATION"})
          .def("LAGRANGIEN"),
      text("CONTACT_INIT", "Initial contact status: all active, none, or where already interpenetrating")
          .into_values({"OUI", "NON", "INTERPENETRE"})
          .def("INTERPENETRE"),
      real("DIST_MAIT", "Thickness added to the master surface (the gap is reduced by it)").def(0.0).range(0.0, std::nullopt),
      real("DIST_ESCL", "Thickness added to the slave surface (the gap is reduced by it)").def(0.0).range(0.0, std::nullopt),
  };
  std::vector<Block> blocks = {
      Block{"ALGO_CONT",
            {"LAGRANGIEN"},
            {real("COEF_CONT",
                  "Complementarity constant c of the active-set law, as a multiple of E/h (E the largest Young's "
                  "modulus of the model, h the smallest slave edge): a slave node is in contact where "
                  "pressure - c gap > 0. It weighs gap against pressure only where an active node's gap is not yet "
                  "closed (after a new pairing)")
                 .def(100.0)
                 .above(0.0)},
            {}},
      Block{"ALGO_CONT",
            {"PENALISATION"},
            {real("COEF_CONT", "Penalty on the weighted gaps (Pa/m): the contact pressure is COEF_CONT times the "
                               "penetration")
                 .required()
                 .above(0.0)},
            {}},
  };
  return factor("ZONE", children, "One contact zone (slave/master pair)").required().occurs(1, -1).with_blocks(blocks);
}

}  // namespace

const CommandSpec& defi_cont_spec() {
  std::vector<Keyword> keywords = {
      concept_kw("MODELE", {"modele"}, "Model carrying the contact surfaces").required(),
      text("REAC_GEOM",
           "Geometric update: pair again in the converged configuration until the pairing no longer changes (or "
           "the displacement since the last pairing is below RESI_GEOM), or pair once at the start")
          .into_values({"AUTOMATIQUE", "SANS"})
          .def("AUTOMATIQUE"),
      integer("ITER_GEOM_MAXI", "Maximum number of new pairings per instant").def(10LL).range(1, std::nullopt),
      real("RESI_GEOM", "Largest displacement change since the last pairing, relative to the largest displacement, "
                        "below which the pairing has converged")
          .def(0.01)
          .range(0.0, std::nullopt),
      mortar_zone(),
      common::info(),
  };
  static const CommandSpec spec = make_command(
      "DEFI_CONT", "char_contact",
      "Define frictionless mortar contact zones (code_aster 17 syntax; pass to STAT_NON_LINE CONTACT or "
      "MECA_NON_LINE CONTACT=_F(DEFINITION=...))",
      keywords, {}, {});
  return spec;
}

}  // namespace lunaster::catalog
