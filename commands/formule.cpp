// FORMULE: a function given by an expression of named parameters (commands/formula.hpp reads it);
// the other names it uses are the command's other keywords, reals or functions.

#include "commands/commands.hpp"
#include "commands/concepts.hpp"
#include "commands/formula.hpp"

#include "catalog/lookup.hpp"

namespace lunaster::cmd {

ConceptPtr formule(const Args& args, Session&) {
  auto f = std::make_shared<Formule>();
  f->vale = args.text("VALE");
  f->nom_para = args.texts("NOM_PARA");
  for (std::size_t i = 0; i < f->nom_para.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (f->nom_para[i] == f->nom_para[j])
        throw args.error("NOM_PARA", "distinct parameter names", "'" + f->nom_para[i] + "' twice");
  std::map<std::string, double> reals;
  std::map<std::string, std::shared_ptr<const RealFunction>> functions;
  for (const auto& name : args.other_names()) {
    const catalog::Value& value = args.node().simple.at(name).front();
    if (std::holds_alternative<double>(value)) {
      reals[name] = args.real(name);
    } else {
      auto function = std::dynamic_pointer_cast<const RealFunction>(args.concept_value(name));
      if (!function) throw args.error(name, "a real or a function", catalog::describe(value));
      functions[name] = function;
    }
  }
  try {
    f->compiled = compile_formula(f->vale, f->nom_para, reals, functions);
  } catch (const FormulaError& e) {
    // the formula with a caret under the place
    std::string one_line = f->vale;
    for (auto& c : one_line)
      if (c == '\n' || c == '\t' || c == '\r') c = ' ';
    std::vector<std::string> hints = e.hints;
    hints.push_back("in: " + one_line);
    hints.push_back("    " + std::string(std::min(e.offset, one_line.size()), ' ') + "^");
    throw args.error("VALE", "a formula of " + std::to_string(f->nom_para.size()) + " parameter(s) lunaster reads", e.what,
                     hints);
  }
  return f;
}

ConceptPtr defi_constante(const Args& args, Session&) {
  auto f = std::make_shared<Fonction>();
  f->nom_para = "TOUTPARA";
  f->abscissas = {0.0};
  f->ordinates = {args.real("VALE")};
  f->prol_gauche = f->prol_droite = 'C';
  args.has("NOM_RESU");  // a name for code_aster's tables: lunaster prints none
  return f;
}

}  // namespace lunaster::cmd
