// DEFI_MATERIAU: linear isotropic elasticity (ELAS) and the hardening of the von Mises laws
// (ECRO_LINE, TRACTION), checked as code_aster checks them.
#include "commands/commands.hpp"
#include "commands/concepts.hpp"

namespace lunaster::cmd {

namespace {

engine::CurveEnd curve_end(char prolongation) {
  return prolongation == 'C' ? engine::CurveEnd::Constant
                             : prolongation == 'L' ? engine::CurveEnd::Linear : engine::CurveEnd::Excluded;
}

/// ECRO_LINE: E_T = D_SIGM_EPSI must be below E (code_aster's COMPOR1_54: H = E E_T / (E - E_T)).
engine::IsotropicHardening ecro_line(const Args& occ, const engine::ElasticMaterial& elas) {
  const double slope = occ.real("D_SIGM_EPSI"), sy = occ.real("SY");
  if (!engine::check_linear_hardening(elas.young, slope, sy).empty())
    throw occ.error("D_SIGM_EPSI", "a slope below ELAS E = " + number_text(elas.young), number_text(slope),
                    {"for linear elasticity with a von Mises law, keep D_SIGM_EPSI below E and give a large SY"});
  return engine::IsotropicHardening::linear(sy, engine::plastic_modulus(elas.young, slope));
}

/// TRACTION: SIGM a function of EPSI whose points make a traction curve (engine::check_traction_curve).
engine::TractionCurve traction(const Args& occ) {
  auto f = occ.concept_as<Fonction>("SIGM");
  if (f->nom_para != "EPSI")
    throw occ.error("SIGM", "a function of EPSI", "'" + f->user_name + "', a function of " + f->nom_para);
  const std::string why = engine::check_traction_curve(f->abscissas, f->ordinates);
  if (!why.empty())
    throw occ.error("SIGM", "a traction curve (its first point the yield point, E = SIGM/EPSI there)",
                    "'" + f->user_name + "': " + why);
  return engine::traction_curve(f->abscissas, f->ordinates, curve_end(f->prol_droite));
}

}  // namespace

ConceptPtr defi_materiau(const Args& args, Session&) {
  auto mat = std::make_shared<Mater>();
  if (args.count("ELAS") > 0) {
    const Args elas = args.factor("ELAS");
    mat->has_elas = true;
    mat->elas.young = elas.real("E");
    mat->elas.poisson = elas.real("NU");
    if (elas.has("RHO")) mat->elas.density = elas.real("RHO");  // E > 0, -1 < NU < 0.5: catalogue bounds
  }
  if (args.count("ECRO_LINE") > 0) mat->ecro_line = ecro_line(args.factor("ECRO_LINE"), mat->elas);
  if (args.count("TRACTION") > 0) mat->traction = traction(args.factor("TRACTION"));
  return mat;
}

}  // namespace lunaster::cmd
