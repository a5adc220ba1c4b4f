#include "catalog/common/keywords.hpp"
#include "catalog/specs.hpp"

namespace lunaster::catalog {

// code_aster's FORMULE: a Python expression of named parameters; the other names it uses are
// given as keywords (p0 = p0, F = F). lunaster reads the expression itself, evaluated without Python.
const CommandSpec& formule_spec() {
  static const CommandSpec spec = [] {
    CommandSpec s = make_command(
        "FORMULE", "formule", "Define a function by a formula of named parameters (a Python expression)",
        {text("VALE", "The formula: numbers, the parameters, the names given as other keywords, + - * / // % **, "
                      "comparisons, math's functions and constants (sqrt, exp, log, sin, atan2, pow, abs, min, "
                      "max, pi ...), calls of the functions given, and 'a if c else b'")
             .required(),
         text("NOM_PARA", "Names of the parameters, in the order of a call (e.g. INST, or X, Y)").many().required()});
    s.body = s.body.others(
        {real("<name>", "A real the formula uses under this name (e.g. p0 = p0)"),
         concept_kw("<name>", {"fonction", "formule", "function"},
                    "A function the formula calls under this name: DEFI_FONCTION, DEFI_CONSTANTE, FORMULE, or "
                    "a function of the deck (a Python def converted)")});
    return s;
  }();
  return spec;
}

const CommandSpec& defi_constante_spec() {
  static const CommandSpec spec = make_command(
      "DEFI_CONSTANTE", "fonction", "Define a constant function",
      {real("VALE", "The value, at every abscissa").required(),
       text("NOM_RESU", "Name of the function's values in code_aster's tables: accepted, no effect (lunaster prints "
                        "no function tables)")
           .def("TOUTRESU")});
  return spec;
}

}  // namespace lunaster::catalog
