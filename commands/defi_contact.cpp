// DEFI_CONTACT: contact definition in current code_aster syntax.
#include "commands/commands.hpp"
#include "commands/concepts.hpp"
#include "commands/contact_keywords.hpp"

namespace lunaster::cmd {

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
  // On a mesh in parts the surfaces are checked whole.
  warn_contact_surfaces(args.factors("ZONE"), contact_surfaces(def, mo), *mo.maillage, session, true);
  return result;
}

}  // namespace lunaster::cmd
