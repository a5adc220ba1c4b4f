// DEFI_CONTACT: contact definition in current code_aster syntax.
#include "commands/commands.hpp"
#include "commands/concepts.hpp"
#include "commands/contact_keywords.hpp"

namespace lunaster::cmd {

namespace {

bool given(const catalog::Args& a, const char* kw) { return a.declares(kw) && a.has(kw); }

/// FROTTEMENT='COULOMB': each zone's coefficient and algorithm (the same algorithm in every
/// zone); without it, no friction keyword.
void read_friction(const Args& args, bool continuous, engine::ContactDefinition& def) {
  const bool friction = args.text("FROTTEMENT") == "COULOMB";
  const auto zones = args.factors("ZONE");
  static const char* const zone_keywords[] = {"COULOMB", "ALGO_FROT", "COEF_FROT", "COEF_PENA_FROT", "E_T",
                                              "SEUIL_INIT", "COEF_MATR_FROT"};
  if (!friction) {
    for (const auto& zone : zones)
      for (const char* kw : zone_keywords)
        if (given(zone, kw))
          throw zone.error(kw, "no friction keyword with FROTTEMENT='SANS'", "a value",
                           {"FROTTEMENT='COULOMB' asks for Coulomb friction; without it the contact is frictionless"});
    for (const char* kw : {"ALGO_RESO_FROT", "RESI_FROT", "ITER_FROT_MAXI"})
      if (given(args, kw))
        throw args.error(kw, "no friction keyword with FROTTEMENT='SANS'", "a value",
                         {"FROTTEMENT='COULOMB' asks for Coulomb friction"});
    return;
  }
  if (given(args, "ALGO_RESO_FROT") && args.text("ALGO_RESO_FROT") != "NEWTON")
    throw args.error("ALGO_RESO_FROT", "'NEWTON'", "'" + args.text("ALGO_RESO_FROT") + "'",
                     {"lunaster solves Coulomb's law within Newton (stick/slip and slip directions at every "
                      "iteration, a consistent tangent); code_aster's fixed point on the Tresca threshold converges "
                      "to the same solution, so ALGO_RESO_FROT='NEWTON' (or none) computes the same contact"});
  if (given(args, "ITER_FROT_MAXI"))
    throw args.error("ITER_FROT_MAXI", "no setting of the friction fixed point", "a value",
                     {"it bounds code_aster's fixed point on the Tresca threshold (ALGO_RESO_FROT='POINT_FIXE'); with "
                      "ALGO_RESO_FROT='NEWTON' ITER_GLOB_MAXI bounds the iterations; remove the keyword"});
  // code_aster's default: Newton goes on until the friction bounds move by less than 1e-4.
  def.resi_frot = given(args, "RESI_FROT") ? args.real("RESI_FROT") : 1e-4;
  using engine::FrictionEnforcement;
  for (size_t z = 0; z < zones.size(); ++z) {
    const auto& zone = zones[z];
    engine::ContactZone& cz = def.zones[z];
    if (!given(zone, "COULOMB"))
      throw zone.error("COULOMB", "the friction coefficient mu (>= 0) with FROTTEMENT='COULOMB'", "none");
    cz.mu = zone.real("COULOMB");
    for (const char* kw : {"SEUIL_INIT", "COEF_MATR_FROT"})
      if (given(zone, kw))
        throw zone.error(kw, "no such setting", "a value",
                         {std::string(kw) == "SEUIL_INIT"
                              ? "it starts code_aster's fixed point on the Tresca threshold; lunaster solves Coulomb's "
                                "law within Newton from the first iteration and needs no initial threshold"
                              : "it scales code_aster's symmetric approximation of the friction matrix; lunaster "
                                "assembles the consistent (unsymmetric) tangent, which needs no factor"});
    FrictionEnforcement how;
    if (continuous) {
      const std::string algo = given(zone, "ALGO_FROT") ? zone.text("ALGO_FROT") : "STANDARD";
      how = algo == "PENALISATION" ? FrictionEnforcement::Penalty : FrictionEnforcement::AugmentedLagrangian;
      if (how == FrictionEnforcement::Penalty) {
        if (!given(zone, "COEF_PENA_FROT"))
          throw zone.error("COEF_PENA_FROT", "the tangential penalty (Pa/m) with ALGO_FROT='PENALISATION'", "none");
        if (given(zone, "COEF_FROT"))
          throw zone.error("COEF_FROT", "no COEF_FROT with ALGO_FROT='PENALISATION' (COEF_PENA_FROT)", "a value");
        cz.coef_frot = zone.real("COEF_PENA_FROT");
      } else {
        if (given(zone, "COEF_PENA_FROT"))
          throw zone.error("COEF_PENA_FROT", "no COEF_PENA_FROT with ALGO_FROT='STANDARD' (COEF_FROT)", "a value");
        // Relative to E / h (contact_problem.cpp); 1e-3: the slip direction follows the tractions
        // (a larger one lets the round-off slip of a sticking point decide it) while the
        // multipliers' rows stay well scaled (below about 1e-9 a factorisation loses them).
        cz.coef_frot = given(zone, "COEF_FROT") ? zone.real("COEF_FROT") : 1e-3;
      }
    } else {
      // code_aster (CONTACT3_3): friction is allowed only with a penalised normal contact.
      if (def.method != engine::ContactMethod::DiscretePenalty)
        throw zone.error("ALGO_CONT", "'PENALISATION' with FROTTEMENT='COULOMB' and FORMULATION='DISCRETE'",
                         "'" + (given(zone, "ALGO_CONT") ? zone.text("ALGO_CONT") : std::string("CONTRAINTE")) + "'",
                         {"as in code_aster, discrete friction is penalised (E_T) and needs a penalised normal "
                          "contact (E_N); FORMULATION='CONTINUE' has exact friction (ALGO_FROT='STANDARD')"});
      if (!given(zone, "E_T"))
        throw zone.error("E_T", "the tangential penalty stiffness (N/m) with FROTTEMENT='COULOMB'", "none");
      how = FrictionEnforcement::Penalty;
      cz.coef_frot = zone.real("E_T");
    }
    if (z > 0 && how != def.friction)
      throw zone.error("ALGO_FROT", "the same friction algorithm in every zone", "another one than zone 1's");
    def.friction = how;
  }
}

}  // namespace

ConceptPtr defi_contact(const Args& args, Session& session) {
  auto result = std::make_shared<CharContact>();
  result->modele = args.concept_as<Modele>("MODELE");
  const Modele& mo = *result->modele;
  auto& def = result->contact;
  const bool continuous = args.text("FORMULATION") == "CONTINUE";
  if (args.text("LISSAGE") != "NON")
    throw args.error("LISSAGE", "'NON' (each master cell's own normal)", "'" + args.text("LISSAGE") + "'",
                     {"lunaster does not smooth the master normals at the nodes; on a plane master surface they "
                      "are the same normal, and LISSAGE = 'NON' (or no LISSAGE) computes the same contact"});
  // code_aster's projected conjugate gradient (ALGO_CONT='GCP') and its settings: named, refused.
  for (const auto& zone : args.factors("ZONE"))
    if (zone.has("ALGO_CONT") && zone.text("ALGO_CONT") == "GCP")
      throw zone.error("ALGO_CONT", "'CONTRAINTE' or 'PENALISATION' with FORMULATION='DISCRETE'", "'GCP'",
                       {"lunaster does not have code_aster's projected conjugate gradient on the contact pressures; "
                        "ALGO_CONT='CONTRAINTE' (the active set) solves the same discrete contact problem exactly, "
                        "without RESI_ABSO, ITER_GCP_MAXI, RECH_LINEAIRE, PRE_COND, COEF_RESI and ITER_PRE_MAXI"});
  for (const char* kw : {"RESI_ABSO", "ITER_GCP_MAXI", "RECH_LINEAIRE", "PRE_COND", "COEF_RESI", "ITER_PRE_MAXI"})
    if (args.has(kw))
      throw args.error(kw, "no setting of ALGO_CONT='GCP' (which lunaster does not have)", "a value",
                       {"it sets code_aster's projected conjugate gradient, which no zone asks for"});
  read_contact_loops(args, def);
  for (const auto& zone : args.factors("ZONE")) {
    const std::string algo = zone.has("ALGO_CONT") ? zone.text("ALGO_CONT") : (continuous ? "STANDARD" : "CONTRAINTE");
    engine::ContactMethod method;
    if (continuous) {
      if (algo != "STANDARD" && algo != "PENALISATION")
        throw zone.error("ALGO_CONT", "'STANDARD' or 'PENALISATION' with FORMULATION='CONTINUE'", "'" + algo + "'");
      method = algo == "PENALISATION" ? engine::ContactMethod::ContinuousPenalty : engine::ContactMethod::Continuous;
    } else {
      if (algo != "CONTRAINTE" && algo != "PENALISATION")
        throw zone.error("ALGO_CONT", "'CONTRAINTE' or 'PENALISATION' with FORMULATION='DISCRETE'", "'" + algo + "'");
      method = algo == "PENALISATION" ? engine::ContactMethod::DiscretePenalty : engine::ContactMethod::DiscreteLagrange;
    }
    if (!def.zones.empty() && method != def.method)
      throw zone.error("ALGO_CONT", "the same contact algorithm in every zone", "'" + algo + "'");
    def.method = method;
    def.zones.push_back(read_contact_zone(zone, *mo.maillage->mesh, mo.dim, method));
  }
  read_friction(args, continuous, def);
  // On a mesh in parts the surfaces are checked whole.
  warn_contact_surfaces(args.factors("ZONE"), contact_surfaces(def, mo), *mo.maillage, session, true);
  return result;
}

}  // namespace lunaster::cmd
