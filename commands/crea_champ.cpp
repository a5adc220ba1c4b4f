// CREA_CHAMP: a field taken out of a result at one time step (OPERATION='EXTR').
#include <cmath>

#include "commands/commands.hpp"
#include "commands/concepts.hpp"

namespace lunaster::cmd {

namespace {

/// The quantity of code_aster's TYPE_CHAM a result field has (DEPL, SIEF, VARI, INFC...); empty
/// if lunaster knows none for it.
std::string quantity_of(const std::string& nom_cham) {
  if (nom_cham == "DEPL" || nom_cham == "FORC_NODA" || nom_cham == "REAC_NODA") return "DEPL";
  for (const char* prefix : {"SIGM_", "SIEF_", "SIEQ_"})
    if (nom_cham.rfind(prefix, 0) == 0) return "SIEF";
  if (nom_cham.rfind("VARI_", 0) == 0) return "VARI";
  if (nom_cham.rfind("EPSI_", 0) == 0) return "EPSI";
  if (nom_cham == "CONT_NOEU") return "INFC";
  return {};
}

const engine::ResultStep& chosen_step(const Args& args, const EvolNoli& resu) {
  for (const auto& s : resu.steps) {
    if (args.has("NUME_ORDRE") && s.nume_ordre == args.integer("NUME_ORDRE")) return s;
    if (args.has("INST") && std::abs(s.inst - args.real("INST")) <= 1e-6 * std::max(1.0, std::abs(s.inst))) return s;
  }
  const std::string stored = "0 to " + std::to_string(resu.steps.back().nume_ordre) + ", times " +
                             number_text(resu.steps.front().inst) + " to " + number_text(resu.steps.back().inst);
  if (args.has("INST"))
    throw args.error("INST", "a time stored in '" + resu.user_name + "' (" + stored + ")", number_text(args.real("INST")));
  throw args.error("NUME_ORDRE", "a time step stored in '" + resu.user_name + "' (" + stored + ")",
                   std::to_string(args.integer("NUME_ORDRE")));
}

}  // namespace

ConceptPtr crea_champ(const Args& args, Session& session) {
  const std::string operation = args.text("OPERATION");
  if (operation != "EXTR")
    throw args.error("OPERATION", "'EXTR' (a field taken out of a result)", "'" + operation + "'",
                     {"lunaster's fields come from results: building one from constants, functions or other fields "
                      "(AFFE, ASSE, COMB, EVAL, DISC...) is not offered"});
  const auto resu = args.concept_as<EvolNoli>("RESULTAT");
  const engine::ResultStep& step = chosen_step(args, *resu);
  const std::string nom_cham = args.text("NOM_CHAM"), type_cham = args.text("TYPE_CHAM");
  auto field = std::make_shared<ChamGd>();
  field->maillage = resu->modele->maillage;
  field->type_cham = type_cham;
  field->nom_cham = nom_cham;
  std::string where;
  if (const auto n = step.nodal.find(nom_cham); n != step.nodal.end()) {
    where = "NOEU", field->nodal = n->second;
  } else if (const auto e = step.elno.find(nom_cham); e != step.elno.end()) {
    where = "ELNO", static_cast<engine::ElnoField&>(field->cells) = e->second;
  } else if (const auto g = step.elga.find(nom_cham); g != step.elga.end()) {
    where = "ELGA", field->cells = g->second;
  } else {
    std::string have;
    for (const auto& [name, f] : step.nodal) have += (have.empty() ? "" : ", ") + name;
    for (const auto& [name, f] : step.elno) have += (have.empty() ? "" : ", ") + name;
    for (const auto& [name, f] : step.elga) have += (have.empty() ? "" : ", ") + name;
    throw args.error("NOM_CHAM", "a field stored at this step of '" + resu->user_name + "' (" + have + ")",
                     "'" + nom_cham + "'", {"compute it with CALC_CHAMP first"});
  }
  const std::string quantity = quantity_of(nom_cham);
  const std::string expected = where + "_" + (quantity.empty() ? "?" : quantity) + "_R";
  if (quantity.empty() || type_cham != expected)
    throw args.error("TYPE_CHAM", quantity.empty() ? "a type for " + nom_cham + ", which lunaster does not type"
                                                   : "'" + expected + "' (" + nom_cham + ": a field of " + quantity + " at " + where + ")",
                     "'" + type_cham + "'");
  const size_t n_values = where == "NOEU" ? field->nodal.values.size() : field->cells.values.size();
  session.log().info("  " + nom_cham + " of '" + resu->user_name + "' at NUME_ORDRE " + std::to_string(step.nume_ordre) +
                     " (INST " + number_text(step.inst) + "): " + type_cham + ", " + std::to_string(n_values) +
                     " value(s)");
  return field;
}

}  // namespace lunaster::cmd
