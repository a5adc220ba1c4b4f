// TEST_RESU: checks result values against non-regression (VALE_CALC) and
// reference (VALE_REFE) values; prints one OK/NOOK line per check.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "commands/commands.hpp"
#include "commands/concepts.hpp"
#include "commands/selection.hpp"

namespace lunaster::cmd {

namespace {

const engine::ResultStep& find_step(const Args& occ, const EvolNoli& resu) {
  for (const auto& s : resu.steps) {
    if (occ.has("NUME_ORDRE") && s.nume_ordre == occ.integer("NUME_ORDRE")) return s;
    if (occ.has("INST") && std::abs(s.inst - occ.real("INST")) <= 1e-6 * std::max(1.0, std::abs(s.inst))) return s;
  }
  if (occ.has("INST")) throw occ.error("INST", "an instant stored in the result", std::to_string(occ.real("INST")));
  throw occ.error("NUME_ORDRE", "a numéro d'ordre stored in the result (0.." + std::to_string(resu.steps.size() - 1) + ")",
                  std::to_string(occ.integer("NUME_ORDRE")));
}

struct Probe {
  double value = 0.0;
  std::string where;  ///< node name or "MIN"/"MAX"...
};

/// Values of one component of a nodal field over a node set.
std::vector<double> nodal_values(const Args& occ, const engine::NodalField& f, int cmp, const std::vector<int>& nodes) {
  std::vector<double> out;
  for (int n : nodes)
    if (f.has(n, cmp)) out.push_back(f.value(n, cmp));
  if (out.empty()) throw occ.error("NOM_CMP", "a component defined on the selected nodes", "'" + f.components[cmp] + "' undefined there");
  return out;
}

double reduce(const std::string& type, const std::vector<double>& v) {
  if (type == "MIN") return *std::min_element(v.begin(), v.end());
  if (type == "MAX") return *std::max_element(v.begin(), v.end());
  double s = 0.0;
  for (double x : v) s += type == "SOMM_ABS" ? std::abs(x) : x;
  return s;
}

Probe probe_value(const Args& occ, const EvolNoli& resu, const engine::ResultStep& step) {
  const engine::Mesh& mesh = *resu.modele->maillage->mesh;
  const std::string cham = occ.text("NOM_CHAM");
  const std::string cmp_name = occ.text("NOM_CMP");
  auto nit = step.nodal.find(cham);
  if (nit == step.nodal.end()) {
    std::string have;
    for (const auto& [name, field] : step.nodal) have += (have.empty() ? "" : ", ") + name;
    throw occ.error("NOM_CHAM", "a field stored at this step (" + have + ")", "'" + cham + "'",
                    {"stresses need CALC_CHAMP (CONTRAINTE='SIGM_NOEU') first"});
  }
  const engine::NodalField& f = nit->second;
  const int cmp = f.component_index(cmp_name);
  if (cmp < 0) {
    std::string have;
    for (const auto& c : f.components) have += (have.empty() ? "" : ", ") + c;
    throw occ.error("NOM_CMP", "a component of " + cham + " (" + have + ")", "'" + cmp_name + "'");
  }
  Probe p;
  if (occ.has("TYPE_TEST")) {
    std::vector<int> nodes;
    if (occ.has("GROUP_NO") || occ.has("NOEUD") || occ.has("GROUP_MA")) nodes = select_nodes(occ, mesh);
    else for (int n = 0; n < mesh.n_nodes(); ++n) nodes.push_back(n);
    p.value = reduce(occ.text("TYPE_TEST"), nodal_values(occ, f, cmp, nodes));
    p.where = occ.text("TYPE_TEST");
    if (occ.has("GROUP_NO")) p.where += "(" + occ.texts("GROUP_NO").front() + ")";
    else if (occ.has("GROUP_MA")) p.where += "(" + occ.texts("GROUP_MA").front() + ")";
    return p;
  }
  const std::vector<int> nodes = select_nodes(occ, mesh);
  const char* kw = occ.has("GROUP_NO") ? "GROUP_NO" : "NOEUD";
  if (nodes.size() != 1)
    throw occ.error(kw, "a single node (or TYPE_TEST to reduce over a group)", std::to_string(nodes.size()) + " nodes");
  p.value = nodal_values(occ, f, cmp, nodes).front();
  p.where = occ.has("GROUP_NO") ? occ.texts("GROUP_NO").front() : mesh.node_names[nodes.front()];
  return p;
}

std::string check_line(bool ok, const std::string& kind, const std::string& what, double refe, double calc, double err,
                       double tol, const std::string& critere) {
  char buf[320];
  std::snprintf(buf, sizeof buf, "%s %-14s %s  refe=%.9e  calc=%.9e  err=%.3e  tol=%.3e  %s", ok ? " OK " : "NOOK",
                kind.c_str(), what.c_str(), refe, calc, err, tol, critere.c_str());
  return buf;
}

/// Relative (or absolute) difference as code_aster: RELATIF divides by |refe|,
/// or by ORDRE_GRANDEUR when the reference is zero.
double difference(double calc, double refe, bool relative, double magnitude) {
  const double d = std::abs(calc - refe);
  if (!relative) return d;
  const double scale = refe != 0.0 ? std::abs(refe) : magnitude;
  return scale > 0.0 ? d / scale : d;
}

}  // namespace

ConceptPtr test_resu(const Args& args, Session& session) {
  for (const auto& occ : args.factors("RESU")) {
    auto resu = occ.concept_as<EvolNoli>("RESULTAT");
    const engine::ResultStep& step = find_step(occ, *resu);
    const Probe p = probe_value(occ, *resu, step);
    std::string what = occ.text("NOM_CHAM") + "  " + p.where + "  " + occ.text("NOM_CMP");
    if (occ.has("LEGENDE")) what += "  [" + occ.text("LEGENDE") + "]";
    const bool relative = occ.text("CRITERE") == "RELATIF";
    const double magnitude = occ.has("ORDRE_GRANDEUR") ? occ.real("ORDRE_GRANDEUR") : 0.0;
    bool any = false;
    if (occ.has("VALE_CALC")) {
      any = true;
      const double refe = occ.real("VALE_CALC");
      const double tol = occ.real("TOLE_MACHINE");
      const double err = difference(p.value, refe, relative, magnitude);
      const bool ok = err <= tol;
      if (!session.code_aster_vale_calc) {
        session.tests.push_back({ok, check_line(ok, "NON_REGRESSION", what, refe, p.value, err, tol, occ.text("CRITERE"))});
        session.log().always(session.tests.back().text);
      } else {
        // A .comm's VALE_CALC is code_aster's result: the check compares lunaster with code_aster.
        session.comparisons.push_back({what, p.value, refe, err, tol});
        std::string line = check_line(ok, "CODE_ASTER", what, refe, p.value, err, tol, occ.text("CRITERE"));
        if (session.vale_calc_report) {
          line.replace(0, 4, ok ? "SAME" : "DIFF");  // a report line, not a check
          session.log().always(line);
        } else {
          session.tests.push_back({ok, line});
          session.log().always(line);
        }
      }
    }
    if (occ.has("VALE_REFE")) {
      any = true;
      const double refe = occ.real("VALE_REFE");
      const double tol = occ.real("PRECISION");
      const double err = difference(p.value, refe, relative, magnitude);
      const bool ok = err <= tol;
      session.tests.push_back({ok, check_line(ok, occ.text("REFERENCE"), what, refe, p.value, err, tol, occ.text("CRITERE"))});
      session.log().always(session.tests.back().text);
    }
    char value[64];
    std::snprintf(value, sizeof value, "%.12e", p.value);
    if (!any) throw occ.error("VALE_CALC", "VALE_CALC and/or VALE_REFE", "neither", {"computed value: " + std::string(value)});
    if (!occ.has("VALE_CALC")) session.log().always("      computed value (paste as VALE_CALC): " + std::string(value));
  }
  return nullptr;
}

}  // namespace lunaster::cmd
