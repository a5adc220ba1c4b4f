// IMPR_RESU: writes results as MED (ParaView/Salome) or as a text table.
#include <algorithm>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <fstream>
#include <set>
#include <type_traits>

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

/// A field with only the components `keep` names that it has (in its own order); false if none.
template <class Field>
bool only_components(Field& f, const std::vector<std::string>& keep) {
  std::vector<int> columns;
  for (int c = 0; c < f.n_components(); ++c)
    if (std::find(keep.begin(), keep.end(), f.components[c]) != keep.end()) columns.push_back(c);
  if (columns.empty()) return false;
  const size_t width = f.components.size(), rows = width ? f.values.size() / width : 0;
  Field kept = f;
  kept.components.clear();
  for (int c : columns) kept.components.push_back(f.components[c]);
  kept.values.assign(rows * columns.size(), 0.0);
  if constexpr (std::is_same_v<Field, engine::NodalField>) kept.defined.assign(rows * columns.size(), 0);
  for (size_t r = 0; r < rows; ++r)
    for (size_t k = 0; k < columns.size(); ++k) {
      kept.values[r * columns.size() + k] = f.values[r * width + columns[k]];
      if constexpr (std::is_same_v<Field, engine::NodalField>)
        kept.defined[r * columns.size() + k] = f.defined[r * width + columns[k]];
    }
  f = std::move(kept);
  return true;
}

/// NOM_CMP: every field of the steps keeps the components named that it has; a field with none
/// of them is left out; DeckError for a component that no field has.
void keep_components(const Args& occ, std::vector<engine::ResultStep>& steps) {
  const auto keep = occ.texts("NOM_CMP");
  std::set<std::string> found;
  auto filter = [&](auto& fields) {
    for (auto it = fields.begin(); it != fields.end();) {
      for (const auto& c : it->second.components) found.insert(c);
      it = only_components(it->second, keep) ? std::next(it) : fields.erase(it);
    }
  };
  for (auto& step : steps) filter(step.nodal), filter(step.elno), filter(step.elga);
  for (const auto& name : keep)
    if (!found.count(name)) {
      std::string have;
      for (const auto& c : found) have += (have.empty() ? "" : ", ") + c;
      throw occ.error("NOM_CMP", "components of the fields written (" + have + ")", "'" + name + "'");
    }
}

/// NOM_CHAM: only the fields named; DeckError for one no chosen step has.
void keep_fields(const Args& occ, const EvolNoli& resu, std::vector<engine::ResultStep>& out) {
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
  if (occ.has("NOM_CHAM")) keep_fields(occ, resu, out);
  if (occ.has("NOM_CMP")) keep_components(occ, out);
  return out;
}

/// MODELE: per cell of `mesh`, whether the model has it; empty without MODELE. DeckError for a
/// model of another mesh.
std::vector<char> model_cells(const Args& args, const Args& occ, const Maillage& maillage) {
  if (!args.has("MODELE")) return {};
  const auto modele = args.concept_as<Modele>("MODELE");
  if (modele->maillage.get() != &maillage)
    throw args.error("MODELE", "a model of the mesh written ('" + maillage.user_name + "')",
                     "'" + modele->user_name + "', a model of '" + modele->maillage->user_name + "'",
                     {"in " + occ.where()});
  if (maillage.part)
    throw args.error("MODELE", "a model of a mesh read whole", "'" + modele->user_name + "', on a mesh in parts",
                     {"remove MODELE: the file holds the whole mesh"});
  // The cells carrying an element, and the boundary cells lying on them (all their nodes theirs).
  const engine::Mesh& mesh = *maillage.mesh;
  std::vector<char> in_model(mesh.n_cells(), 0), on_model(mesh.n_nodes(), 0);
  for (int c = 0; c < mesh.n_cells() && c < static_cast<int>(modele->modelisation.size()); ++c)
    if ((in_model[c] = modele->modelisation[c] != engine::Modelisation::None))
      for (int a = 0; a < mesh.cell_n_nodes(c); ++a) on_model[mesh.cell(c)[a]] = 1;
  for (int c = 0; c < mesh.n_cells(); ++c) {
    bool all_on = mesh.cell_n_nodes(c) > 0;
    for (int a = 0; a < mesh.cell_n_nodes(c); ++a) all_on = all_on && on_model[mesh.cell(c)[a]];
    in_model[c] = in_model[c] || all_on;
  }
  return in_model;
}

/// The nodes of the model's cells (every node without MODELE).
std::vector<char> model_nodes(const engine::Mesh& mesh, const std::vector<char>& in_model) {
  std::vector<char> out(mesh.n_nodes(), in_model.empty() ? 1 : 0);
  for (size_t c = 0; c < in_model.size(); ++c)
    if (in_model[c])
      for (int a = 0; a < mesh.cell_n_nodes(static_cast<int>(c)); ++a) out[mesh.cell(static_cast<int>(c))[a]] = 1;
  return out;
}

/// FORMAT='RESULTAT' with MAILLAGE: the coordinates of the nodes and the nodes of the cells (of
/// the model's cells only, with MODELE).
void write_mesh_table(std::ostream& out, const Maillage& maillage, const engine::Mesh& mesh,
                      const std::vector<char>& in_model) {
  const std::vector<char> nodes = model_nodes(mesh, in_model);
  out << "MAILLAGE " << (maillage.user_name.empty() ? "-" : maillage.user_name) << "\nNOEUD   ";
  for (const char* axis : {"X", "Y", "Z"}) { char b[24]; std::snprintf(b, sizeof b, " %15s", axis); out << b; }
  out << '\n';
  for (int n = 0; n < mesh.n_nodes(); ++n) {
    if (!nodes[n]) continue;
    char b[32];
    std::snprintf(b, sizeof b, "%-8s", mesh.node_names[n].c_str());
    out << b;
    for (int a = 0; a < 3; ++a) { std::snprintf(b, sizeof b, " %15.8e", mesh.node(n)[a]); out << b; }
    out << '\n';
  }
  out << "\nMAILLE   TYPE     NOEUDS\n";
  for (int c = 0; c < mesh.n_cells(); ++c) {
    if (!in_model.empty() && !in_model[c]) continue;
    char b[48];
    const std::string type(engine::cell_info(mesh.cell_types[c]).name);
    std::snprintf(b, sizeof b, "%-8s %-8s", mesh.cell_names[c].c_str(), type.c_str());
    out << b;
    for (int a = 0; a < mesh.cell_n_nodes(c); ++a) out << ' ' << mesh.node_names[mesh.cell(c)[a]];
    out << '\n';
  }
  out << '\n';
}

/// FORMAT='RESULTAT': nodal fields of the selected steps, at the selected nodes (of the model's
/// cells only, with MODELE).
void write_table(std::ostream& out, const Args& occ, const EvolNoli& resu, const engine::Mesh& mesh,
                 const std::vector<char>& in_model) {
  std::vector<int> nodes;
  const std::vector<char> kept = model_nodes(mesh, in_model);
  if (occ.has("GROUP_NO") || occ.has("GROUP_MA")) nodes = select_nodes(occ, mesh);
  else for (int n = 0; n < mesh.n_nodes(); ++n) nodes.push_back(n);
  nodes.erase(std::remove_if(nodes.begin(), nodes.end(), [&](int n) { return !kept[n]; }), nodes.end());
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
    std::vector<std::vector<char>> in_model;  // per occurrence (MODELE)
    for (const auto& occ : args.factors("RESU")) {
      std::shared_ptr<Maillage> maillage;
      if (occ.has("MAILLAGE")) maillage = occ.concept_as<Maillage>("MAILLAGE");
      if (occ.has("RESULTAT")) {
        const auto resu = occ.concept_as<EvolNoli>("RESULTAT");
        if (maillage && maillage != resu->modele->maillage)
          throw occ.error("MAILLAGE", "the mesh of RESULTAT '" + resu->user_name + "'", "'" + maillage->user_name + "'");
        maillage = resu->modele->maillage;
      } else {
        for (const char* kw : {"NOM_CHAM", "NUME_ORDRE", "NOM_CMP", "GROUP_NO", "GROUP_MA"})
          if (occ.has(kw)) throw occ.error(kw, std::string("no ") + kw + " without RESULTAT", kw);
        if (maillage->part)
          throw occ.error("MAILLAGE", "a mesh read whole (FORMAT='RESULTAT' prints its nodes and cells)",
                          "'" + maillage->user_name + "', a mesh in parts", {"write it with FORMAT='MED'"});
      }
      in_model.push_back(model_cells(args, occ, *maillage));
    }
    const auto path = output_path(args, session, "resu");
    // On a mesh in parts rank 0 prints the results gathered on the whole mesh, once every rank
    // has checked the occurrence's nodes and steps on its part.
    std::deque<EvolNoli> gathered;
    for (const auto& occ : args.factors("RESU")) {
      if (!occ.has("RESULTAT")) continue;
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
      size_t k = 0, i = 0;
      for (const auto& occ : args.factors("RESU")) {
        const std::vector<char>& cells = in_model[i++];
        if (occ.has("MAILLAGE") && !occ.has("RESULTAT")) {
          const auto ma = occ.concept_as<Maillage>("MAILLAGE");
          write_mesh_table(out, *ma, *ma->mesh, cells);
          continue;
        }
        const auto resu = occ.concept_as<EvolNoli>("RESULTAT");
        const auto& ma = resu->modele->maillage;
        if (occ.has("MAILLAGE") && !ma->part) write_mesh_table(out, *ma, *ma->mesh, cells);
        else if (occ.has("MAILLAGE")) write_mesh_table(out, *ma, *ma->whole, cells);
        if (ma->part) write_table(out, occ, gathered[k++], *ma->whole, cells);
        else write_table(out, occ, *resu, *ma->mesh, cells);
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
      if (occ.has("NUME_ORDRE") || occ.has("NOM_CHAM") || occ.has("NOM_CMP"))
        steps = &selections.emplace_back(selected_steps(occ, *resu));
      results.push_back({resu->user_name.empty() ? "RESU" : resu->user_name, steps});
    } else {
      for (const char* kw : {"NOM_CHAM", "NUME_ORDRE", "NOM_CMP"})
        if (occ.has(kw)) throw occ.error(kw, std::string("no ") + kw + " without RESULTAT", kw);
    }
    // MODELE: the MED file holds the whole mesh, so the model must have every cell.
    if (this_mesh && args.has("MODELE")) {
      const std::vector<char> in_model = model_cells(args, occ, *maillage);
      const auto left = std::count(in_model.begin(), in_model.end(), 0);
      if (left > 0)
        throw args.error("MODELE", "with FORMAT='MED', a model of every cell of the mesh (the file holds the whole "
                                   "mesh)",
                         "'" + args.concept_as<Modele>("MODELE")->user_name + "', without " + std::to_string(left) +
                             " cell(s) of '" + maillage->user_name + "'",
                         {"remove MODELE, or print the model's nodes with FORMAT='RESULTAT'"});
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
