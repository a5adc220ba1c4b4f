// CREA_CHAMP: a field taken out of a result at one time step or out of a mesh (OPERATION='EXTR'),
// or a field at nodes built from constants or functions (AFFE), other fields' components (ASSE),
// a linear combination (COMB), or functions evaluated at the nodes (EVAL).
#include <algorithm>
#include <cmath>
#include <functional>
#include <map>

#include "commands/commands.hpp"
#include "commands/concepts.hpp"
#include "commands/selection.hpp"

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

/// The components of the quantities a field at nodes is built with, in code_aster's order of
/// each quantity (a built field's components follow it).
const std::vector<std::string>& quantity_components(const std::string& quantity) {
  static const std::map<std::string, std::vector<std::string>> table = [] {
    std::map<std::string, std::vector<std::string>> t;
    t["DEPL"] = {"DX", "DY", "DZ", "DRX", "DRY", "DRZ", "LAGS_C", "LAGS_F1", "LAGS_F2"};
    t["TEMP"] = {"TEMP"};
    t["GEOM"] = {"X", "Y", "Z"};
    t["SIEF"] = {"SIXX", "SIYY", "SIZZ", "SIXY", "SIXZ", "SIYZ"};
    for (int i = 1; i <= 30; ++i) t["NEUT"].push_back("X" + std::to_string(i));
    return t;
  }();
  static const std::vector<std::string> none;
  const auto it = table.find(quantity);
  return it == table.end() ? none : it->second;
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

ConceptPtr extract_from_result(const Args& args, Session& session) {
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

/// EXTR of a mesh: NOM_CHAM='GEOMETRIE', the nodes' coordinates X, Y, Z (code_aster's geometry
/// has three, Z = 0 in 2D).
ConceptPtr extract_from_mesh(const Args& args, Session& session) {
  auto ma = args.concept_as<Maillage>("MAILLAGE");
  if (args.text("NOM_CHAM") != "GEOMETRIE")
    throw args.error("NOM_CHAM", "'GEOMETRIE' with MAILLAGE (the nodes' coordinates)", "'" + args.text("NOM_CHAM") + "'",
                     {"code_aster's ABSC_CURV (curvilinear abscissa) is not offered"});
  if (args.text("TYPE_CHAM") != "NOEU_GEOM_R")
    throw args.error("TYPE_CHAM", "'NOEU_GEOM_R' (GEOMETRIE: a field of GEOM at nodes)", "'" + args.text("TYPE_CHAM") + "'");
  const engine::Mesh& mesh = *ma->mesh;
  auto field = std::make_shared<ChamGd>();
  field->maillage = ma;
  field->type_cham = "NOEU_GEOM_R";
  field->nom_cham = "GEOMETRIE";
  field->nodal = engine::NodalField({"X", "Y", "Z"}, mesh.n_nodes());
  for (int n = 0; n < mesh.n_nodes(); ++n)
    for (int k = 0; k < 3; ++k) field->nodal.set(n, k, mesh.node(n)[k]);
  session.log().info("  GEOMETRIE of '" + ma->user_name + "': NOEU_GEOM_R, " + std::to_string(mesh.n_nodes()) + " node(s)");
  return field;
}

/// TYPE_CHAM of a field built at nodes: NOEU_<quantity>_R, or _F where `functions` allows it.
/// Returns the quantity; DeckError at TYPE_CHAM otherwise.
std::string built_quantity(const Args& args, bool functions) {
  const std::string type_cham = args.text("TYPE_CHAM");
  const std::string op = args.text("OPERATION");
  const std::string kinds = functions ? "_R or _F" : "_R";
  if (type_cham.rfind("NOEU_", 0) != 0)
    throw args.error("TYPE_CHAM", "a field at nodes, NOEU_<quantity>" + kinds + ", with OPERATION='" + op + "'",
                     "'" + type_cham + "'",
                     {"lunaster builds fields at nodes from constants, functions and other fields; fields per cell "
                      "(ELGA_, ELNO_, ELEM_, CART_) come from results (EXTR)"});
  const size_t last = type_cham.rfind('_');
  const std::string quantity = type_cham.substr(5, last == std::string::npos || last < 5 ? std::string::npos : last - 5);
  const std::string suffix = last == std::string::npos ? "" : type_cham.substr(last);
  if (quantity_components(quantity).empty() || !(suffix == "_R" || (functions && suffix == "_F")))
    throw args.error("TYPE_CHAM", "NOEU_ with DEPL, TEMP, NEUT, GEOM or SIEF, " + kinds, "'" + type_cham + "'");
  return quantity;
}

/// The column of `cmp`, a component of `quantity`, in `components` (the built field's); DeckError
/// at `kw` when the quantity has no such component.
int built_column(const Args& occ, const std::string& kw, const std::string& quantity,
                 const std::vector<std::string>& components, const std::string& cmp) {
  const auto it = std::find(components.begin(), components.end(), cmp);
  if (it != components.end()) return static_cast<int>(it - components.begin());
  const auto& known = quantity_components(quantity);
  std::string list;
  for (size_t i = 0; i < known.size() && i < 9; ++i) list += (i ? ", " : "") + known[i];
  if (known.size() > 9) list += " ... " + known.back();
  throw occ.error(kw, "a component of " + quantity + " (" + list + ")", "'" + cmp + "'");
}

/// The components named by every occurrence (under `kw`), in the quantity's order.
std::vector<std::string> built_components(const std::vector<Args>& occs, const std::string& quantity,
                                          const std::function<std::vector<std::string>(const Args&)>& names_of,
                                          const std::string& kw) {
  const auto& known = quantity_components(quantity);
  std::vector<bool> used(known.size(), false);
  for (const auto& occ : occs)
    for (const auto& cmp : names_of(occ)) used[static_cast<size_t>(built_column(occ, kw, quantity, known, cmp))] = true;
  std::vector<std::string> out;
  for (size_t i = 0; i < known.size(); ++i)
    if (used[i]) out.push_back(known[i]);
  return out;
}

/// The support of a built field: MAILLAGE, or MODELE's mesh (TOUT then means the model's nodes).
struct Support {
  std::shared_ptr<Maillage> maillage;
  std::shared_ptr<Modele> modele;
};

Support support_of(const Args& args) {
  Support s;
  if (args.has("MODELE")) {
    s.modele = args.concept_as<Modele>("MODELE");
    s.maillage = s.modele->maillage;
  } else {
    s.maillage = args.concept_as<Maillage>("MAILLAGE");
  }
  return s;
}

/// The nodes of an AFFE or ASSE occurrence: TOUT (the mesh's, or the nodes of the model's cells),
/// GROUP_MA's nodes, GROUP_NO, NOEUD.
std::vector<int> occurrence_nodes(const Args& occ, const Support& s) {
  const engine::Mesh& mesh = *s.maillage->mesh;
  if (occ.has("TOUT") && s.modele) {
    std::vector<int> cells;
    for (int c = 0; c < mesh.n_cells(); ++c)
      if (c < static_cast<int>(s.modele->modelisation.size()) && s.modele->modelisation[c] != engine::Modelisation::None)
        cells.push_back(c);
    return mesh.nodes_of_cells(cells);
  }
  return select_nodes(occ, mesh);
}

std::shared_ptr<ChamGd> new_field(const Args& args, const Support& s, const std::string& quantity,
                                  std::vector<std::string> components) {
  auto field = std::make_shared<ChamGd>();
  field->maillage = s.maillage;
  field->type_cham = args.text("TYPE_CHAM");
  field->nom_cham = quantity;
  field->nodal = engine::NodalField(std::move(components), s.maillage->mesh->n_nodes());
  return field;
}

void log_built(Session& session, const Args& args, const ChamGd& field) {
  long long defined = 0;
  for (unsigned char d : field.nodal.defined) defined += d;
  std::string cmps;
  for (const auto& c : field.nodal.components) cmps += (cmps.empty() ? "" : ", ") + c;
  session.log().info("  " + args.text("OPERATION") + ": " + field.type_cham + " (" + cmps + "), " +
                     std::to_string(defined) + " value(s)");
}

ConceptPtr affe(const Args& args, Session& session) {
  const std::string quantity = built_quantity(args, true);
  const bool functions = args.text("TYPE_CHAM").back() == 'F';
  const Support s = support_of(args);
  const auto occs = args.factors("AFFE");
  auto field = new_field(args, s, quantity,
                         built_components(occs, quantity, [](const Args& o) { return o.texts("NOM_CMP"); }, "NOM_CMP"));
  if (functions) field->functions.resize(field->nodal.values.size());
  for (const auto& occ : occs) {
    const auto cmps = occ.texts("NOM_CMP");
    const char* kw = functions ? "VALE_F" : "VALE";
    if (!occ.has(kw))
      throw occ.error(functions ? "VALE" : "VALE_F",
                      std::string(kw) + (functions ? " (functions: TYPE_CHAM is a *_F field)" : " (reals: TYPE_CHAM is a *_R field)"),
                      functions ? "reals" : "functions");
    const size_t n_values = functions ? occ.concepts(kw).size() : occ.reals(kw).size();
    if (n_values != cmps.size())
      throw occ.error(kw, "one value per component of NOM_CMP (" + std::to_string(cmps.size()) + ")",
                      std::to_string(n_values) + " value(s)");
    const auto nodes = occurrence_nodes(occ, s);
    for (size_t i = 0; i < cmps.size(); ++i) {
      const int col = built_column(occ, "NOM_CMP", quantity, field->nodal.components, cmps[i]);
      std::shared_ptr<const RealFunction> f;
      if (functions) f = std::dynamic_pointer_cast<const RealFunction>(occ.concepts(kw)[i]);
      const double v = functions ? 0.0 : occ.reals(kw)[i];
      for (int n : nodes) {
        field->nodal.set(n, col, v);
        if (functions) field->functions[static_cast<size_t>(n) * field->nodal.components.size() + col] = f;
      }
    }
  }
  log_built(session, args, *field);
  return field;
}

/// A field at nodes of the support's mesh, of reals, for ASSE, COMB and EVAL; DeckError at `kw`.
std::shared_ptr<ChamGd> source_field(const Args& occ, const std::string& kw, const Maillage* mesh, bool reals) {
  auto f = occ.concept_as<ChamGd>(kw);
  if (!f->at_nodes())
    throw occ.error(kw, "a field at nodes (NOEU_*)", "'" + f->user_name + "', a field of type " + f->type_cham);
  if (mesh && f->maillage->mesh != mesh->mesh)
    throw occ.error(kw, "a field on the mesh '" + mesh->user_name + "'",
                    "'" + f->user_name + "', on '" + f->maillage->user_name + "'");
  if (reals && f->of_functions())
    throw occ.error(kw, "a field of reals (*_R)", "'" + f->user_name + "', a field of functions (" + f->type_cham + ")",
                    {"evaluate it first: CREA_CHAMP OPERATION='EVAL'"});
  return f;
}

ConceptPtr asse(const Args& args, Session& session) {
  const std::string quantity = built_quantity(args, false);
  const Support s = support_of(args);
  const auto occs = args.factors("ASSE");
  const auto result_names = [&](const Args& occ) {
    if (occ.has("NOM_CMP_RESU")) return occ.texts("NOM_CMP_RESU");
    if (occ.has("NOM_CMP")) return occ.texts("NOM_CMP");
    return source_field(occ, "CHAM_GD", s.maillage.get(), true)->nodal.components;
  };
  auto field = new_field(args, s, quantity,
                         built_components(occs, quantity, result_names, "NOM_CMP_RESU"));
  for (const auto& occ : occs) {
    const auto src = source_field(occ, "CHAM_GD", s.maillage.get(), true);
    const std::vector<std::string> from = occ.has("NOM_CMP") ? occ.texts("NOM_CMP") : src->nodal.components;
    const std::vector<std::string> to = result_names(occ);
    if (to.size() != from.size())
      throw occ.error("NOM_CMP_RESU", "one name per component of NOM_CMP (" + std::to_string(from.size()) + ")",
                      std::to_string(to.size()) + " name(s)");
    const bool cumul = occ.text("CUMUL") == "OUI";
    const double coef = occ.real("COEF_R");
    const auto nodes = occurrence_nodes(occ, s);
    for (size_t i = 0; i < from.size(); ++i) {
      const int in = src->nodal.component_index(from[i]);
      if (in < 0) {
        std::string have;
        for (const auto& c : src->nodal.components) have += (have.empty() ? "" : ", ") + c;
        throw occ.error("NOM_CMP", "a component of '" + src->user_name + "' (" + have + ")", "'" + from[i] + "'");
      }
      const int out = built_column(occ, occ.has("NOM_CMP_RESU") ? "NOM_CMP_RESU" : "NOM_CMP", quantity,
                                   field->nodal.components, to[i]);
      // code_aster takes the component where the field has it, among the nodes selected.
      for (int n : nodes) {
        if (!src->nodal.has(n, in)) continue;
        const double v = coef * src->nodal.value(n, in);
        field->nodal.set(n, out, cumul && field->nodal.has(n, out) ? field->nodal.value(n, out) + v : v);
      }
    }
  }
  log_built(session, args, *field);
  return field;
}

ConceptPtr comb(const Args& args, Session& session) {
  const std::string quantity = built_quantity(args, false);
  const auto occs = args.factors("COMB");
  const auto first = source_field(occs.front(), "CHAM_GD", nullptr, true);
  auto field = std::make_shared<ChamGd>();
  field->maillage = first->maillage;
  field->type_cham = args.text("TYPE_CHAM");
  field->nom_cham = quantity;
  field->nodal = engine::NodalField(first->nodal.components, first->nodal.n_nodes);
  std::fill(field->nodal.defined.begin(), field->nodal.defined.end(), 1);
  for (const auto& occ : occs) {
    const auto f = source_field(occ, "CHAM_GD", first->maillage.get(), true);
    if (f->type_cham != field->type_cham || f->nodal.components != first->nodal.components)
      throw occ.error("CHAM_GD", "a field of " + field->type_cham + " with the components of '" + first->user_name + "'",
                      "'" + f->user_name + "', of " + f->type_cham);
    const double coef = occ.real("COEF_R");
    for (size_t k = 0; k < field->nodal.values.size(); ++k) {
      field->nodal.values[k] += coef * f->nodal.values[k];
      field->nodal.defined[k] = field->nodal.defined[k] && f->nodal.defined[k];
    }
  }
  for (size_t k = 0; k < field->nodal.values.size(); ++k)
    if (!field->nodal.defined[k]) field->nodal.values[k] = 0.0;
  log_built(session, args, *field);
  return field;
}

ConceptPtr eval(const Args& args, Session& session) {
  const std::string quantity = built_quantity(args, false);
  const auto cham_f = source_field(args, "CHAM_F", nullptr, false);
  if (!cham_f->of_functions())
    throw args.error("CHAM_F", "a field of functions (NOEU_*_F, CREA_CHAMP AFFE with VALE_F)",
                     "'" + cham_f->user_name + "', of " + cham_f->type_cham);
  std::vector<std::shared_ptr<ChamGd>> paras;
  for (const auto& c : args.concepts("CHAM_PARA")) {
    auto p = std::dynamic_pointer_cast<ChamGd>(c);
    if (!p->at_nodes() || p->of_functions() || p->maillage->mesh != cham_f->maillage->mesh)
      throw args.error("CHAM_PARA", "fields of reals at nodes on the mesh of '" + cham_f->user_name + "'",
                       "'" + p->user_name + "', of " + p->type_cham);
    paras.push_back(p);
  }
  const engine::NodalField& fn = cham_f->nodal;
  for (const auto& c : fn.components) built_column(args, "TYPE_CHAM", quantity, quantity_components(quantity), c);
  auto field = std::make_shared<ChamGd>();
  field->maillage = cham_f->maillage;
  field->type_cham = args.text("TYPE_CHAM");
  field->nom_cham = quantity;
  field->nodal = engine::NodalField(fn.components, fn.n_nodes);
  const engine::Mesh& mesh = *cham_f->maillage->mesh;
  std::vector<double> values;
  for (int n = 0; n < fn.n_nodes; ++n)
    for (int k = 0; k < fn.n_components(); ++k) {
      if (!fn.has(n, k)) continue;
      const auto& f = cham_f->functions[static_cast<size_t>(n) * fn.components.size() + k];
      const std::vector<std::string> names = f->parameters();
      values.assign(names.size(), 0.0);
      for (size_t i = 0; i < names.size(); ++i) {
        bool found = false;
        for (const auto& p : paras) {
          const int col = p->nodal.component_index(names[i]);
          if (col >= 0 && p->nodal.has(n, col)) {
            values[i] = p->nodal.value(n, col);
            found = true;
            break;
          }
        }
        if (!found)
          throw args.error("CHAM_PARA", "fields giving the parameter " + names[i] + " of '" + f->user_name + "' (" +
                                            fn.components[k] + ") at node " + mesh.node_names[n],
                           "none that has it there");
      }
      field->nodal.set(n, k, f->evaluate(values));
    }
  log_built(session, args, *field);
  return field;
}

}  // namespace

ConceptPtr crea_champ(const Args& args, Session& session) {
  const std::string operation = args.text("OPERATION");
  if (operation == "EXTR") return args.has("MAILLAGE") ? extract_from_mesh(args, session) : extract_from_result(args, session);
  if (operation == "AFFE") return affe(args, session);
  if (operation == "ASSE") return asse(args, session);
  if (operation == "COMB") return comb(args, session);
  return eval(args, session);
}

}  // namespace lunaster::cmd
