#include "catalog/common/keywords.hpp"
#include "catalog/specs.hpp"

namespace lunaster::catalog {

const CommandSpec& defi_fonction_spec() {
  auto prolongation = [](const std::string& name, const std::string& side) {
    return text(name, "Extension " + side + " of the abscissas: error, constant or linear")
        .into_values({"EXCLU", "CONSTANT", "LINEAIRE"})
        .def("EXCLU");
  };
  static const CommandSpec spec = make_command(
      "DEFI_FONCTION", "fonction", "Define a piecewise linear function of one parameter",
      {text("NOM_PARA", "Name of the parameter").into_values({"INST", "X", "Y", "Z", "EPSI"}).required(),
       real("VALE", "Pairs x1, f(x1), x2, f(x2), ... with increasing x").count(2, -1).required(),
       prolongation("PROL_GAUCHE", "left"), prolongation("PROL_DROITE", "right"),
       text("INTERPOL", "Interpolation (only linear)").into_values({"LIN"}).count(1, 2).def("LIN"),
       text("NOM_RESU", "Name of the function's values in code_aster's tables: accepted, no effect (lunaster prints no "
                        "function tables)")
           .def("TOUTRESU"),
       common::info()});
  return spec;
}

}  // namespace lunaster::catalog
