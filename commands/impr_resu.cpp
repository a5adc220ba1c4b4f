// IMPR_RESU: writes results as MED (ParaView/Salome) or as a text table.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "commands/commands.hpp"
#include "commands/concepts.hpp"
#include "commands/selection.hpp"
#include "engine/io/atomic_file.hpp"
#include "engine/io/med_writer.hpp"

namespace lunaster::cmd {

namespace {

/// Output file: FICHIER in the output folder, else <deck>_<UNITE>.<ext>.
std::filesystem::path output_path(const Args& args, const Session& session, const std::string& ext) {
  if (args.has("FICHIER")) return session.output_file(args.text("FICHIER"));
  const std::string unit = args.has("UNITE") ? std::to_string(args.integer("UNITE")) : (ext == "rmed" ? "80" : "8");
  return session.output_file(session.deck_path.stem().string() + "_" + unit + "." + ext);
}

void write_table(std::ostream& out, const Args& occ, const EvolNoli& resu) {
  const engine::Mesh& mesh = *resu.modele->maillage->mesh;
  std::vector<int> nodes;
  if (occ.has("GROUP_NO") || occ.has("GROUP_MA")) nodes = select_nodes(occ, mesh);
  else for (int n = 0; n < mesh.n_nodes(); ++n) nodes.push_back(n);
  std::vector<std::string> fields;
  if (occ.has("NOM_CHAM")) fields = occ.texts("NOM_CHAM");
  for (const auto& step : resu.steps) {
    if (occ.has("NUME_ORDRE")) {
      const auto wanted = occ.integers("NUME_ORDRE");
      if (std::find(wanted.begin(), wanted.end(), step.nume_ordre) == wanted.end()) continue;
    }
    for (const auto& [name, f] : step.nodal) {
      if (!fields.empty() && std::find(fields.begin(), fields.end(), name) == fields.end()) continue;
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
    const auto path = output_path(args, session, "resu");
    // Atomic: a good file is never replaced by a truncated one.
    engine::write_file_atomically(path, [&](std::ostream& out) {
      for (const auto& occ : args.factors("RESU"))
        if (occ.has("RESULTAT")) write_table(out, occ, *occ.concept_as<EvolNoli>("RESULTAT"));
    });
    session.log().info("  written " + path.string());
    return nullptr;
  }
  const auto path = output_path(args, session, "rmed");
  std::shared_ptr<engine::Mesh> mesh;
  std::vector<engine::MedResult> results;
  for (const auto& occ : args.factors("RESU")) {
    std::shared_ptr<engine::Mesh> this_mesh;
    if (occ.has("RESULTAT")) {
      auto resu = occ.concept_as<EvolNoli>("RESULTAT");
      this_mesh = resu->modele->maillage->mesh;
      results.push_back({resu->user_name.empty() ? "RESU" : resu->user_name, &resu->steps});
    } else if (occ.has("MAILLAGE")) {
      this_mesh = occ.concept_as<Maillage>("MAILLAGE")->mesh;
    }
    if (mesh && this_mesh && this_mesh != mesh)
      throw occ.error("RESULTAT", "results on the same mesh in one MED file", "a result on another mesh");
    if (this_mesh) mesh = this_mesh;
  }
  if (!mesh) throw args.error("RESU", "RESULTAT or MAILLAGE in RESU", "neither");
  engine::write_med(path.string(), *mesh, results);
  session.log().info("  written " + path.string());
  return nullptr;
}

}  // namespace lunaster::cmd
