#include "catalog/common/keywords.hpp"
#include "catalog/specs.hpp"

namespace lunaster::catalog {

namespace {

std::vector<Keyword> zone_surfaces() {
  return {text("GROUP_MA_ESCL", "Slave boundary cell group").required(),
          text("GROUP_MA_MAIT", "Master boundary cell group").required(),
          real("TOLE_PROJ_EXT",
               "How far outside a master cell the projection of a slave point may fall and still pair it, in the "
               "cell's reference coordinates (its reference segment or face spans 2 units along each direction, "
               "0.5 is a quarter of it): within it the projection is brought back onto the cell's boundary; "
               "beyond it on every master cell the point is not paired (no contact there). 0, or negative as "
               "code_aster spells it: no projection outside a cell is taken. code_aster's default 0.5")
              .def(0.5),
          text("APPARIEMENT", "Pairing: MAIT_ESCL, each slave point projected on the master surface (what lunaster "
                              "does). NODAL (each slave node with its nearest master node) is refused")
              .into_values({"MAIT_ESCL"})
              .refuse("NODAL", "lunaster pairs a slave point with its projection on the master surface (MAIT_ESCL), "
                               "not with the nearest master node; on matching meshes the two coincide")
              .def("MAIT_ESCL"),
          text("NORMALE", "Normal of the pairing: MAIT, the master surface's (what lunaster does). The slave's "
                          "(ESCL) or their mean (MAIT_ESCL) are refused")
              .into_values({"MAIT"})
              .refuse("ESCL", "lunaster projects along the master surface's normal (NORMALE='MAIT')")
              .refuse("MAIT_ESCL", "lunaster projects along the master surface's normal (NORMALE='MAIT')")
              .def("MAIT")};
}

/// A zone's friction keywords (read with FROTTEMENT='COULOMB' only; DEFI_CONTACT refuses them
/// otherwise).
Keyword coulomb() {
  return real("COULOMB", "Coulomb's friction coefficient mu of the zone (FROTTEMENT='COULOMB'): the tangential "
                         "traction is at most mu times the contact pressure")
      .range(0.0, std::nullopt);
}

std::vector<Keyword> continuous_friction() {
  return {coulomb(),
          text("ALGO_FROT", "Friction algorithm: STANDARD (augmented Lagrangian on the tangential tractions, "
                            "reported as code_aster's semi-multipliers LAGS_F1[, LAGS_F2] = traction / (mu p), |LAGS_F| "
                            "<= 1: sticking points do not slip at all) or PENALISATION (an elastic slip t / "
                            "COEF_PENA_FROT while sticking). Default STANDARD")
              .into_values({"STANDARD", "PENALISATION"}),
          real("COEF_FROT", "ALGO_FROT='STANDARD': augmentation of the tangential tractions, relative: c = "
                            "COEF_FROT E / h (E the model's largest Young's modulus, h the zone's smallest slave "
                            "edge); a point sticks while |lambda_t + c slip| <= mu p. Changes the iterations, not "
                            "the solution. Default 1e-3 (code_aster's COEF_FROT, 100 by default, scales its "
                            "normalised semi-multipliers' slip in 1/m: another quantity); from 1e-8 to 1e-2 the "
                            "frictional patch tests converge, at E / h (1) the 3D one chatters")
              .above(0.0),
          real("COEF_PENA_FROT", "ALGO_FROT='PENALISATION': tangential penalty (Pa/m), the traction per slip while "
                                 "sticking; required there")
              .above(0.0),
          real("SEUIL_INIT", "code_aster's initial Tresca threshold of its friction fixed point: refused, lunaster "
                             "solves Coulomb's law within Newton (ALGO_RESO_FROT='NEWTON') and needs none")};
}

std::vector<Keyword> discrete_friction() {
  return {coulomb(),
          real("E_T", "Tangential penalty stiffness of each slave node (N/m; FROTTEMENT='COULOMB', required): "
                      "a node sticks while its tangential force is below mu times its normal force, with an "
                      "elastic slip force / E_T")
              .above(0.0),
          text("ALGO_FROT", "Friction algorithm of the discrete formulation: PENALISATION only").into_values({"PENALISATION"}),
          real("COEF_MATR_FROT", "code_aster's factor on its symmetric friction matrix while the residual is "
                                 "above 1e-3: refused, lunaster's friction tangent is consistent (unsymmetric)")};
}

Keyword continuous_zone() {
  std::vector<Keyword> children = zone_surfaces();
  children.push_back(text("ALGO_CONT", "Contact algorithm: augmented Lagrangian or penalty")
                         .into_values({"STANDARD", "PENALISATION"})
                         .def("STANDARD"));
  children.push_back(common::contact_integration({"AUTO", "GAUSS", "SIMPSON", "NCOTES"}));
  children.push_back(text("CONTACT_INIT", "Initial contact status: all active, none, or where already interpenetrating")
                         .into_values({"OUI", "NON", "INTERPENETRE"})
                         .def("INTERPENETRE"));
  for (auto& kw : continuous_friction()) children.push_back(kw);
  std::vector<Block> blocks = {
      Block{"ALGO_CONT", {"STANDARD"}, {real("COEF_CONT", "Augmentation coefficient rho of the contact Lagrangian").def(100.0).above(0.0)}, {}},
      Block{"ALGO_CONT", {"PENALISATION"}, {real("COEF_PENA_CONT", "Normal penalty coefficient").required().above(0.0)}, {}},
  };
  for (auto& block : common::ordre_int_blocks()) blocks.push_back(block);
  return factor("ZONE", children, "One contact zone (slave/master pair)").required().occurs(1, -1).with_blocks(blocks);
}

Keyword discrete_zone() {
  std::vector<Keyword> children = zone_surfaces();
  children.push_back(text("ALGO_CONT", "Contact algorithm: active set with Lagrange multipliers or penalty; GCP "
                                       "(code_aster's projected conjugate gradient on the contact pressures) is "
                                       "refused: lunaster does not have it, CONTRAINTE solves the same problem exactly")
                         .into_values({"CONTRAINTE", "PENALISATION", "GCP"})
                         .def("CONTRAINTE"));
  for (auto& kw : discrete_friction()) children.push_back(kw);
  std::vector<Block> blocks = {
      Block{"ALGO_CONT", {"PENALISATION"}, {real("E_N", "Normal penalty stiffness (Pa/m)").required().above(0.0)}, {}},
  };
  return factor("ZONE", children, "One contact zone (slave/master pair)").required().occurs(1, -1).with_blocks(blocks);
}

/// A setting of code_aster's ALGO_CONT='GCP' (its convergence, iterations, line search and
/// preconditioner): known by name, refused with GCP itself.
Keyword gcp_keyword(const std::string& name, bool is_real) {
  const std::string what = "code_aster's setting of ALGO_CONT='GCP', the projected conjugate gradient lunaster does "
                           "not have: refused (ALGO_CONT='CONTRAINTE' solves the same contact problem exactly)";
  if (is_real) return real(name, what);
  if (name == "RECH_LINEAIRE") return text(name, what).into_values({"ADMISSIBLE", "NON_ADMISSIBLE"});
  if (name == "PRE_COND") return text(name, what).into_values({"DIRICHLET", "SANS"});
  return integer(name, what);
}

}  // namespace

const CommandSpec& defi_contact_spec() {
  std::vector<Keyword> keywords = {
      concept_kw("MODELE", {"modele"}, "Model carrying the contact surfaces").required(),
      text("FORMULATION", "Discrete (node-to-segment) or continuous (augmented Lagrangian) formulation")
          .into_values({"DISCRETE", "CONTINUE"})
          .def("DISCRETE"),
      text("FROTTEMENT", "Friction: SANS (frictionless) or COULOMB (Coulomb's law, each zone's COULOMB; CONTINUE: "
                         "ALGO_FROT, COEF_FROT or COEF_PENA_FROT; DISCRETE: ALGO_CONT='PENALISATION' and E_T)")
          .into_values({"SANS", "COULOMB"})
          .def("SANS"),
      text("LISSAGE",
           "Smoothing of the master normals: NON takes each master cell's own normal at the projection of a "
           "slave point, as lunaster does. OUI (normals averaged at the master nodes and interpolated) is "
           "refused: lunaster does not smooth them")
          .into_values({"OUI", "NON"})
          .def("NON"),
  };
  for (auto& kw : common::contact_loop_keywords()) keywords.push_back(kw);
  keywords.push_back(common::info());
  static const CommandSpec spec = make_command(
      "DEFI_CONTACT", "char_contact", "Define contact zones, frictionless or with Coulomb friction (pass to STAT_NON_LINE CONTACT)", keywords, {},
      {Block{"FORMULATION",
             {"CONTINUE"},
             {common::algo_reso_cont(false), continuous_zone(),
              text("ALGO_RESO_FROT", "Friction loop (FROTTEMENT='COULOMB'): NEWTON, Coulomb's law within Newton "
                                     "(statuses stick/slip and slip directions updated at each iteration, a "
                                     "consistent unsymmetric tangent). POINT_FIXE (code_aster's fixed point on the "
                                     "Tresca threshold) is refused: Newton solves the same law")
                  .into_values({"NEWTON", "POINT_FIXE"}),
              real("RESI_FROT", "Friction (FROTTEMENT='COULOMB'): Newton converges only once the contact "
                                "pressures, the friction bounds, moved over its last iteration by at most this "
                                "much relative to the largest, besides RESI_GLOB_*. Default 1e-4")
                  .above(0.0),
              integer("ITER_FROT_MAXI", "code_aster's iteration limit of its friction fixed point "
                                        "(ALGO_RESO_FROT='POINT_FIXE'): refused, ITER_GLOB_MAXI bounds Newton")},
             {}},
       Block{"FORMULATION",
             {"DISCRETE"},
             {common::algo_reso_cont(true), common::iter_cont_mult(), discrete_zone(), gcp_keyword("RESI_ABSO", true),
              gcp_keyword("ITER_GCP_MAXI", false), gcp_keyword("RECH_LINEAIRE", false),
              gcp_keyword("PRE_COND", false), gcp_keyword("COEF_RESI", true), gcp_keyword("ITER_PRE_MAXI", false)},
             {at_most_one({"ITER_CONT_MAXI", "ITER_CONT_MULT"})}}});
  return spec;
}

}  // namespace lunaster::catalog
