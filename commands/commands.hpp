#pragma once
/// Every command handler (one per file in commands/), listed in register_all.cpp.
#include <cstdio>
#include <string>

#include "catalog/args.hpp"
#include "commands/session.hpp"
#include "engine/nonlinear/newton_options.hpp"

namespace lunaster::cmd {

using catalog::Args;
using catalog::ConceptPtr;

/// A number as the commands' messages print it (printf's %g: 1e-09, 0.25, 1e+08).
inline std::string number_text(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", x);
  return buf;
}

ConceptPtr debut(const Args& args, Session& session);
/// DEBUT MESURE_TEMPS's report of a nonlinear command that took `wall_seconds` (nothing at level 0).
void report_times(Session& session, const engine::SolverStats& stats, double wall_seconds);
ConceptPtr fin(const Args& args, Session& session);
ConceptPtr lire_maillage(const Args& args, Session& session);
ConceptPtr defi_group(const Args& args, Session& session);
ConceptPtr modi_maillage(const Args& args, Session& session);
ConceptPtr affe_modele(const Args& args, Session& session);
ConceptPtr defi_materiau(const Args& args, Session& session);
ConceptPtr affe_materiau(const Args& args, Session& session);
ConceptPtr affe_char_meca(const Args& args, Session& session);
ConceptPtr defi_contact(const Args& args, Session& session);
ConceptPtr defi_cont(const Args& args, Session& session);
ConceptPtr defi_list_reel(const Args& args, Session& session);
ConceptPtr defi_list_inst(const Args& args, Session& session);
ConceptPtr defi_fonction(const Args& args, Session& session);
ConceptPtr defi_constante(const Args& args, Session& session);
ConceptPtr formule(const Args& args, Session& session);
ConceptPtr stat_non_line(const Args& args, Session& session);
ConceptPtr meca_non_line(const Args& args, Session& session);
ConceptPtr calc_champ(const Args& args, Session& session);
ConceptPtr crea_champ(const Args& args, Session& session);
ConceptPtr test_resu(const Args& args, Session& session);
ConceptPtr impr_resu(const Args& args, Session& session);
ConceptPtr impr_mesure(const Args& args, Session& session);
ConceptPtr post_releve_t(const Args& args, Session& session);
ConceptPtr test_table(const Args& args, Session& session);
ConceptPtr impr_table(const Args& args, Session& session);

}  // namespace lunaster::cmd
