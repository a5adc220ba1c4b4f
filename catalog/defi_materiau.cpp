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
       factor("ECRO_LINE",
              {real("D_SIGM_EPSI", "Slope E_T of the uniaxial stress-strain curve after yield (Pa), below E")
                   .required()
                   .range(0.0, std::nullopt),
               real("SY", "Yield stress (Pa)").required().above(0.0)},
              "Linear isotropic hardening of the von Mises laws (VMIS_ISOT_LINE)"),
       factor("TRACTION",
              {concept_kw("SIGM", {"fonction"},
                          "Uniaxial stress as a function of EPSI; its first point is the yield point and sets E "
                          "(= SIGM/EPSI there), PROL_DROITE extends it")
                   .required()},
              "Traction curve of the von Mises laws with piecewise linear hardening (VMIS_ISOT_TRAC)"),
       common::info()});
  return spec;
}

}  // namespace lunaster::catalog
