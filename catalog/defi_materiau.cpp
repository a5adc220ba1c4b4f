#include "catalog/common/keywords.hpp"
#include "catalog/specs.hpp"

namespace lunaster::catalog {

const CommandSpec& defi_materiau_spec() {
  static const CommandSpec spec = make_command(
      "DEFI_MATERIAU", "mater", "Define a material",
      {factor("ELAS",
              {real("E", "Young's modulus (Pa)").required().above(0.0),
               real("NU", "Poisson's ratio").required().above(-1.0).below(0.5),
               real("RHO", "Density (kg/m3): the mass AFFE_CHAR_MECA PESANTEUR weighs (no default)").range(0.0, std::nullopt)},
              "Isotropic linear elasticity")
           .required(),
       common::info()});
  return spec;
}

}  // namespace lunaster::catalog
