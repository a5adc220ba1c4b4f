// IMPR_MESURE: appends one CSV row describing what a STAT_NON_LINE result cost
// (unknowns, iterations, wall time per phase, peak memory) and how far chosen
// components are from exact values. Meant for studies that loop over meshes and
// methods inside one deck: times are those since the previous IMPR_MESURE.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "commands/commands.hpp"
#include "commands/concepts.hpp"
#include "commands/selection.hpp"
#include "engine/io/atomic_file.hpp"
#include "engine/parallel/mpi_runtime.hpp"

namespace lunaster::cmd {

namespace {

/// Peak resident memory of the process in MiB since the last reset (Linux VmHWM), -1 if unknown.
double peak_rss_mib() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;  // kB
  return -1.0;
}

/// Starts a new peak-memory window (Linux: writing 5 to clear_refs resets VmHWM).
void reset_peak_rss() {
  std::ofstream clear("/proc/self/clear_refs");
  if (clear) clear << "5";
}

const engine::ResultStep& step_of(const Args& occ, const EvolNoli& resu) {
  if (!occ.has("NUME_ORDRE")) return resu.steps.back();
  for (const auto& s : resu.steps)
    if (s.nume_ordre == occ.integer("NUME_ORDRE")) return s;
  throw occ.error("NUME_ORDRE", "a numéro d'ordre stored in the result (0.." + std::to_string(resu.steps.size() - 1) + ")",
                  std::to_string(occ.integer("NUME_ORDRE")));
}

/// Largest relative (absolute if the reference is 0) error of one component over a node set;
/// -1 when the component is defined on none of its nodes here (on a mesh in parts, this rank's:
/// the caller takes the largest over the ranks).
double max_error(const Args& occ, const EvolNoli& resu) {
  const engine::ResultStep& step = step_of(occ, resu);
  const std::string cham = occ.text("NOM_CHAM");
  const auto it = step.nodal.find(cham);
  if (it == step.nodal.end()) {
    std::string have;
    for (const auto& [name, field] : step.nodal) have += (have.empty() ? "" : ", ") + name;
    throw occ.error("NOM_CHAM", "a field stored at this step (" + have + ")", "'" + cham + "'",
                    {"stresses need CALC_CHAMP (CONTRAINTE='SIGM_NOEU') first"});
  }
  const engine::NodalField& f = it->second;
  const int cmp = f.component_index(occ.text("NOM_CMP"));
  if (cmp < 0) {
    std::string have;
    for (const auto& c : f.components) have += (have.empty() ? "" : ", ") + c;
    throw occ.error("NOM_CMP", "a component of " + cham + " (" + have + ")", "'" + occ.text("NOM_CMP") + "'");
  }
  const double refe = occ.real("VALE_REFE");
  const double scale = refe != 0.0 ? std::abs(refe) : 1.0;
  double worst = -1.0;
  for (int n : select_nodes(occ, *resu.modele->maillage->mesh))
    if (f.has(n, cmp)) worst = std::max(worst, std::abs(f.value(n, cmp) - refe) / scale);
  return worst;
}

/// On a mesh in parts (every rank at the same IMPR_MESURE): each value the largest over the
/// ranks. Unchanged otherwise.
std::vector<double> largest_over_ranks(std::vector<double> values, bool in_parts) {
  if (!in_parts) return values;
  const std::vector<double> all = engine::parallel::gather_all(values);
  for (size_t i = 0; i < all.size(); ++i) {
    double& value = values[i % values.size()];
    value = std::max(value, all[i]);
  }
  return values;
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

/// A CSV field, quoted when it holds a comma, a quote or a line break.
std::string csv_field(const std::string& v) {
  if (v.find_first_of(",\"\n") == std::string::npos) return v;
  std::string out = "\"";
  for (char c : v) {
    if (c == '"') out += '"';
    out += c == '\n' ? ' ' : c;
  }
  return out + "\"";
}

/// Header line of an existing file ("" if it does not exist or is empty).
std::string existing_header(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string line;
  if (in) std::getline(in, line);
  return line;
}

/// Appends `row` to FICHIER (created with `header`), atomically: the file is rewritten whole
/// through a temporary, so a run killed while writing leaves the previous rows, never a
/// half-written last one.
void write_row(const Args& args, Session& session, const std::string& header, const std::string& row) {
  const auto path = session.output_file(args.text("FICHIER"));
  const std::string old = existing_header(path);
  if (!old.empty() && old != header)
    throw args.error("FICHIER", "a new file or one with the same columns (" + header + ")",
                     "'" + path.string() + "' with columns " + old, {"use another FICHIER for another set of columns"});
  std::string previous;
  if (!old.empty()) {
    std::ifstream in(path, std::ios::binary);
    previous.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    if (!previous.empty() && previous.back() != '\n') previous += '\n';
  }
  engine::write_file_atomically(path, [&](std::ostream& out) {
    if (old.empty()) out << header << '\n';
    out << previous << row << '\n';
  });
  session.log().info("  measured: " + row);
}

}  // namespace

ConceptPtr impr_mesure(const Args& args, Session& session) {
  const auto now = std::chrono::steady_clock::now();
  std::shared_ptr<EvolNoli> resu;
  if (args.has("RESULTAT")) resu = args.concept_as<EvolNoli>("RESULTAT");
  std::vector<std::string> names, values;
  if (args.has("PARA")) {
    names = args.texts("PARA");
    values = args.texts("VALE_K");
    if (names.size() != values.size())
      throw args.error("VALE_K", std::to_string(names.size()) + " value(s), one per PARA", std::to_string(values.size()));
  }
  const auto delta = [&](const std::string& phase) {
    const auto cur = session.phase_seconds.find(phase);
    const auto old = session.phase_seconds_measured.find(phase);
    return (cur == session.phase_seconds.end() ? 0.0 : cur->second) -
           (old == session.phase_seconds_measured.end() ? 0.0 : old->second);
  };
  const engine::SolverStats st = resu ? resu->stats : engine::SolverStats{};
  // On a mesh in parts: the whole mesh's nodes (the unknowns are counted over the ranks by the
  // solve), and the times, the peak memory and the errors the largest over the ranks.
  const bool in_parts = resu && resu->in_parts();
  std::vector<double> measured = {std::chrono::duration<double>(now - session.measure_mark).count(),
                                  delta("read"), delta("post"), delta("output"), st.assemble_seconds,
                                  st.contact_seconds, st.factorize_seconds, st.solve_seconds, peak_rss_mib()};
  for (const auto& occ : args.factors("ERREUR")) measured.push_back(resu ? max_error(occ, *resu) : 0.0);
  measured = largest_over_ranks(measured, in_parts);
  const auto errors = args.factors("ERREUR");
  for (size_t k = 0; k < errors.size(); ++k)
    if (resu && measured[9 + k] < 0.0)
      throw errors[k].error("NOM_CMP", "a component defined on at least one selected node",
                            "'" + errors[k].text("NOM_CMP") + "' undefined there");
  const double total = measured[0], read = measured[1], post = measured[2], output = measured[3];
  const double assemble = measured[4], contact = measured[5], factorize = measured[6], solve = measured[7];
  const double inner = assemble + contact + factorize + solve;
  const auto add = [&](const std::string& name, const std::string& value) {
    names.push_back(name);
    values.push_back(value);
  };
  const auto count = [&](long long v) { return resu ? std::to_string(v) : std::string(); };
  const auto& maillage = resu ? resu->modele->maillage : nullptr;
  add("nodes", count(!resu ? 0 : maillage->part ? maillage->part->n_global_nodes : maillage->mesh->n_nodes()));
  add("unknowns", count(st.n_dofs));
  add("free_unknowns", count(st.n_free));
  add("instants", count(st.instants));
  add("newton_iter", count(st.newton_iterations));
  add("contact_passes", count(st.contact_passes));
  add("t_read", number(read));
  add("t_assemble", number(assemble));
  add("t_contact", number(contact));
  add("t_factor", number(factorize));
  add("t_solve", number(solve));
  add("t_post", number(post));
  add("t_output", number(output));
  add("t_other", number(std::max(0.0, total - read - post - output - inner)));
  add("t_total", number(total));
  add("peak_rss_mb", number(measured[8]));
  add("resi_glob_rela", resu ? number(st.resi_glob_rela) : std::string());
  add("solve_resid_raw", resu ? number(st.solve_residual_raw) : std::string());
  add("solve_resid", resu ? number(st.solve_residual) : std::string());
  add("refinements", count(st.refinement_steps));
  for (size_t k = 0; k < errors.size(); ++k) add(errors[k].text("NOM"), resu ? number(measured[9 + k]) : std::string());

  std::ostringstream header, row;
  for (size_t i = 0; i < names.size(); ++i) {
    header << (i ? "," : "") << names[i];
    row << (i ? "," : "") << csv_field(values[i]);
  }
  if (engine::parallel::writes_output()) write_row(args, session, header.str(), row.str());
  session.phase_seconds_measured = session.phase_seconds;
  reset_peak_rss();
  session.measure_mark = std::chrono::steady_clock::now();
  return nullptr;
}

}  // namespace lunaster::cmd
