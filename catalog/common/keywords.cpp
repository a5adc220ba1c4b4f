#include "catalog/common/keywords.hpp"

namespace lunaster::catalog::common {

Keyword tout(std::string doc) { return text("TOUT", std::move(doc)).into_values({"OUI"}); }
Keyword group_ma(std::string doc) { return text("GROUP_MA", std::move(doc)).many(); }
Keyword group_no(std::string doc) { return text("GROUP_NO", std::move(doc)).many(); }
Keyword maille(std::string doc) { return text("MAILLE", std::move(doc)).many(); }
Keyword noeud(std::string doc) { return text("NOEUD", std::move(doc)).many(); }
Keyword info() {
  return integer("INFO",
                 "code_aster's amount of printed information (1 normal, 2 detailed): accepted so that code_aster "
                 "decks run, no effect (lunaster's log detail is set for the whole run: `lunaster run -v` or -q)")
      .into_values({1LL, 2LL})
      .def(1LL);
}

Keyword contact_integration(std::vector<Scalar> schemes) {
  return text("INTEGRATION", "Integration scheme of the contact terms on the slave surface")
      .into_values(std::move(schemes))
      .def("AUTO");
}

std::vector<Block> ordre_int_blocks() {
  return {
      Block{"INTEGRATION", {"GAUSS"},
            {integer("ORDRE_INT", "Number of Gauss points per direction").def(3LL).range(1, 6)}, {}},
      Block{"INTEGRATION", {"SIMPSON"},
            {integer("ORDRE_INT", "Number of Simpson subdivisions of the slave cell").def(1LL).range(1, 4)}, {}},
      Block{"INTEGRATION", {"NCOTES"},
            {integer("ORDRE_INT", "Degree of the Newton-Cotes interpolating polynomial").def(3LL).range(3, 8)}, {}},
  };
}

std::vector<Keyword> contact_loop_keywords() {
  return {
      text("ALGO_RESO_GEOM", "Geometry (pairing) loop: fixed point or generalised Newton")
          .into_values({"POINT_FIXE", "NEWTON"})
          .def("POINT_FIXE"),
      text("REAC_GEOM", "Geometric update: until converged, a fixed number of times, or never")
          .into_values({"AUTOMATIQUE", "CONTROLE", "SANS"})
          .def("AUTOMATIQUE"),
      integer("NB_ITER_GEOM", "Number of geometric updates with REAC_GEOM='CONTROLE'").def(2LL).range(0, std::nullopt),
      integer("ITER_GEOM_MAXI", "Maximum number of geometric updates with REAC_GEOM='AUTOMATIQUE'")
          .def(10LL)
          .range(1, std::nullopt),
      real("RESI_GEOM", "Relative geometry change below which the pairing has converged").def(0.01).range(0.0, std::nullopt),
      integer("ITER_CONT_MAXI",
              "Maximum number of contact status iterations (absent: 30; with the discrete methods, ITER_CONT_MULT "
              "per contact point)")
          .range(1, std::nullopt),
  };
}

Keyword iter_cont_mult() {
  return integer("ITER_CONT_MULT",
                 "Contact status iterations allowed per contact point (absent: 4, unless ITER_CONT_MAXI is given): "
                 "the active set adds or removes one point per iteration")
      .range(1, std::nullopt);
}

Keyword algo_reso_cont(bool discrete) {
  if (discrete)
    return text("ALGO_RESO_CONT", "Contact status loop: fixed point (statuses updated between Newton solves)")
        .into_values({"POINT_FIXE"})
        .refuse("NEWTON", "the discrete formulation updates its contact statuses between Newton solves only");
  return text("ALGO_RESO_CONT",
              "Contact status loop: fixed point (statuses updated once Newton converged) or generalised Newton "
              "(statuses updated at every Newton iteration)")
      .into_values({"POINT_FIXE", "NEWTON"});
}

std::vector<Keyword> test_reference_keywords(bool integers) {
  std::vector<Keyword> out = {
      real("VALE_CALC", "Non-regression value computed by lunaster itself"),
      real("TOLE_MACHINE", "Relative tolerance of the VALE_CALC check").def(1e-6).range(0.0, std::nullopt),
      text("REFERENCE", "Source of VALE_REFE")
          .into_values({"ANALYTIQUE", "SOURCE_EXTERNE", "AUTRE_ASTER", "NON_DEFINI"}),
      real("VALE_REFE", "Reference value from an independent source"),
      text("CRITERE", "Relative or absolute comparison").into_values({"RELATIF", "ABSOLU"}).def("RELATIF"),
      real("PRECISION", "Tolerance of the VALE_REFE check").def(1e-3).range(0.0, std::nullopt),
      real("ORDRE_GRANDEUR", "Magnitude of the tested quantity: a RELATIF check divides by it when the reference (VALE_CALC or VALE_REFE) is smaller, as for a value zero in theory").above(0.0),
      text("VALE_ABS",
           "'OUI': compare the absolute values, |computed| with |VALE_CALC| and |VALE_REFE| (as code_aster: a "
           "quantity whose sign depends on a convention, such as an orientation of the normal, or a contact "
           "pressure of either sign); the check lines print the absolute values")
          .into_values({"OUI", "NON"})
          .def("NON"),
      text("LEGENDE", "Free label printed with the check"),
  };
  if (integers) {
    out.push_back(integer("VALE_CALC_I", "Non-regression value of an integer parameter (instead of VALE_CALC)"));
    out.push_back(integer("VALE_REFE_I", "Reference value of an integer parameter (instead of VALE_REFE)"));
  }
  return out;
}

std::vector<Rule> test_reference_rules(bool integers) {
  if (!integers) return {together({"VALE_REFE", "REFERENCE"}), at_least_one({"VALE_CALC", "VALE_REFE"})};
  return {present_present({"VALE_REFE", "REFERENCE"}), present_present({"VALE_REFE_I", "REFERENCE"}),
          at_most_one({"VALE_CALC", "VALE_CALC_I"}), at_most_one({"VALE_REFE", "VALE_REFE_I"}),
          at_least_one({"VALE_CALC", "VALE_REFE", "VALE_CALC_I", "VALE_REFE_I"})};
}

}  // namespace lunaster::catalog::common
