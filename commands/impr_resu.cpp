// IMPR_RESU: writes results as MED (ParaView/Salome) or as a text table.
#include <algorithm>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "commands/commands.hpp"
#include "commands/concepts.hpp"
#include "commands/part_results.hpp"
#include "commands/parts.hpp"
#include "commands/selection.hpp"
#include "engine/io/atomic_file.hpp"
#include "engine/io/med_writer.hpp"
#include "engine/parallel/mpi_runtime.hpp"

namespace lunaster::cmd {

namespace {

/// Output file: FICHIER in the output folder, else <deck>_<UNITE>.<ext>.
std::filesystem::path output_path(const Args& args, const Session& session, const std::string& ext) {
  if (args.has("FICHIER")) return session.output_file(args.text("FICHIER"));
  const int unit = args.has("UNITE") ? static_cast<int>(args.integer("UNITE")) : (ext == "rmed" ? 80 : 8);
  // An .export binds the unit to a file of its own type: MED results to rmed, text to resu.
  if (const auto found = session.result_units.find(unit); found != session.result_units.end() && found->second.type != ext)
    throw args.error("UNITE", "a '" + ext + "' unit for this FORMAT",
                     "unit " + std::to_string(unit) + ", a '" + found->second.type + "' file in " +
                         session.export_path.string());
  return session.unit_output_file(unit, ext);
}

/// The steps of RESULTAT chosen by NUME_ORDRE, with only the fields NOM_CHAM names (all by
/// default); DeckError for an order or a field the result does not have.
std::vector<engine::ResultStep> selected_steps(const Args& occ, const EvolNoli& resu) {
  std::vector<engine::ResultStep> out;
  std::vector<long long> orders;
  if (occ.has("NUME_ORDRE")) orders = occ.integers("NUME_ORDRE");
  for (long long order : orders)
    if (std::none_of(resu.steps.begin(), resu.steps.end(), [&](const auto& s) { return s.nume_ordre == order; }))
      throw occ.error("NUME_ORDRE", "a time step stored in '" + resu.user_name + "' (0 to " +
                                        std::to_string(resu.steps.back().nume_ordre) + ")",
                      std::to_string(order));
  for (const auto& step : resu.steps)
    if (orders.empty() || std::find(orders.begin(), orders.end(), step.nume_ordre) != orders.end()) out.push_back(step);
  if (!occ.has("NOM_CHAM")) return out;
  const auto fields = occ.texts("NOM_CHAM");
  for (const auto& name : fields) {
    const bool stored = std::any_of(out.begin(), out.end(), [&](const auto& s) {
      return s.nodal.count(name) > 0 || s.elno.count(name) > 0;
    });
    if (!stored)
      throw occ.error("NOM_CHAM", "a field stored in '" + resu.user_name + "' (compute it with CALC_CHAMP first)",
                      "'" + name + "'");
  }
  auto unwanted = [&](const std::string& name) { return std::find(fields.begin(), fields.end(), name) == fields.end(); };
  for (auto& step : out) {
    for (auto it = step.nodal.begin(); it != step.nodal.end();) it = unwanted(it->first) ? step.nodal.erase(it) : std::next(it);
    for (auto it = step.elno.begin(); it != step.elno.end();) it = unwanted(it->first) ? step.elno.erase(it) : std::next(it);
  }
  return out;
}

/// FORMAT='RESULTAT': nodal fields of the selected steps, at the selected nodes.
void write_table(std::ostream& out, const Args& occ, const EvolNoli& resu, const engine::Mesh& mesh) {
  std::vector<int> nodes;
  if (occ.has("GROUP_NO") || occ.has("GROUP_MA")) nodes = select_nodes(occ, mesh);
  else for (int n = 0; n < mesh.n_nodes(); ++n) nodes.push_back(n);
  for (const auto& step : selected_steps(occ, resu)) {
    for (const auto& [name, f] : step.nodal) {
      char head[128];
      std::snprintf(head, sizeof head, "CHAMP %s  NUME_ORDRE %d  INST %.6e\n", name.c_str(), step.nume_ordre, step.inst);
      out << head << "NOEUD   ";
      for (const auto& c : f.components) { char b[24]; std::snprintf(b, sizeof b, " %15s", c.c_str()); out << b; }
      out << '\n';
      for (int n : nodes) {
        char b[32];
        std::snprintf(b, sizeof b, "%-8s", mesh.node_names[n].c_str());
        out << b;
        for (int c = 0; c < f.n_components(); ++c) {
          if (f.has(n, c)) std::snprintf(b, sizeof b, " %15.8e", f.value(n, c));
          else std::snprintf(b, sizeof b, " %15s", "-");
          out << b;
        }
        out << '\n';
      }
      out << '\n';
    }
  }
}

}  // namespace

ConceptPtr impr_resu(const Args& args, Session& session) {
  Session::Timer timer(session, "output");
  const std::string format = args.text("FORMAT");
  if (format == "RESULTAT") {
    for (const auto& occ : args.factors("RESU"))
      if (occ.has("MAILLAGE"))
        throw occ.error("MAILLAGE", "RESULTAT only with FORMAT='RESULTAT' (it prints result tables; a mesh is "
                                    "written with FORMAT='MED')",
                        "MAILLAGE");
    const auto path = output_path(args, session, "resu");
    // On a mesh in parts rank 0 prints the results gathered on the whole mesh, once every rank
    // has checked the occurrence's nodes and steps on its part.
    std::deque<EvolNoli> gathered;
    for (const auto& occ : args.factors("RESU")) {
      const auto resu = occ.concept_as<EvolNoli>("RESULTAT");
      const auto& ma = resu->modele->maillage;
      if (!ma->part) continue;
      if (occ.has("GROUP_NO") || occ.has("GROUP_MA")) select_nodes(occ, *ma->mesh);
      const std::vector<engine::ResultStep> chosen = selected_steps(occ, *resu);  // only these are gathered
      agree_over_ranks(nullptr);
      EvolNoli& whole = gathered.emplace_back();
      whole.user_name = resu->user_name;
      whole.steps = gather_steps_to_root(*ma->part, chosen);
    }
    // Atomic: a good file is never replaced by a truncated one.
    engine::write_file_atomically(path, [&](std::ostream& out) {
      size_t k = 0;
      for (const auto& occ : args.factors("RESU")) {
        const auto resu = occ.concept_as<EvolNoli>("RESULTAT");
        const auto& ma = resu->modele->maillage;
        if (ma->part) write_table(out, occ, gathered[k++], *ma->whole);
        else write_table(out, occ, *resu, *ma->mesh);
      }
    });
    session.log().info("  written " + path.string());
    return nullptr;
  }
  const auto path = output_path(args, session, "rmed");
  std::shared_ptr<engine::Mesh> mesh;
  std::shared_ptr<Maillage> maillage;
  std::vector<engine::MedResult> results;
  std::deque<std::vector<engine::ResultStep>> selections;  // steps chosen by NUME_ORDRE / NOM_CHAM (stable addresses)
  for (const auto& occ : args.factors("RESU")) {
    for (const char* kw : {"GROUP_NO", "GROUP_MA"})
      if (occ.has(kw))
        throw occ.error(kw, std::string("no ") + kw + " with FORMAT='MED' (the MED file holds the whole mesh; "
                                                      "FORMAT='RESULTAT' prints chosen nodes)",
                        kw);
    std::shared_ptr<engine::Mesh> this_mesh;
    if (occ.has("MAILLAGE")) {
      maillage = occ.concept_as<Maillage>("MAILLAGE");
      this_mesh = maillage->mesh;
    }
    if (occ.has("RESULTAT")) {
      auto resu = occ.concept_as<EvolNoli>("RESULTAT");
      if (this_mesh && this_mesh != resu->modele->maillage->mesh)
        throw occ.error("MAILLAGE", "the mesh of RESULTAT '" + resu->user_name + "'", "another mesh");
      this_mesh = resu->modele->maillage->mesh;
      maillage = resu->modele->maillage;
      const std::vector<engine::ResultStep>* steps = &resu->steps;
      if (occ.has("NUME_ORDRE") || occ.has("NOM_CHAM")) steps = &selections.emplace_back(selected_steps(occ, *resu));
      results.push_back({resu->user_name.empty() ? "RESU" : resu->user_name, steps});
    } else {
      for (const char* kw : {"NOM_CHAM", "NUME_ORDRE"})
        if (occ.has(kw)) throw occ.error(kw, std::string("no ") + kw + " without RESULTAT", kw);
    }
    if (mesh && this_mesh && this_mesh != mesh)
      throw occ.error("RESULTAT", "results on the same mesh in one MED file", "a result on another mesh");
    if (this_mesh) mesh = this_mesh;
  }
  if (!mesh) throw args.error("RESU", "RESULTAT or MAILLAGE in RESU", "neither");
  if (maillage->part) {
    // A mesh in parts: every field gathered to rank 0, which writes them on the whole mesh it
    // read (the file of the serial run); the others write nothing.
    agree_over_ranks(nullptr);
    std::deque<std::vector<engine::ResultStep>> wholes;
    for (auto& result : results)
      result.steps = &wholes.emplace_back(gather_steps_to_root(*maillage->part, *result.steps));
    if (engine::parallel::rank() == 0) engine::write_med(path.string(), *maillage->whole, results);
    session.log().info("  written " + path.string());
    return nullptr;
  }
  engine::write_med(path.string(), *mesh, results);
  session.log().info("  written " + path.string());
  return nullptr;
}

}  // namespace lunaster::cmd
