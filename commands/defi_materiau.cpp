// DEFI_MATERIAU: linear isotropic elasticity (ELAS).
#include "commands/commands.hpp"
#include "commands/concepts.hpp"

namespace lunaster::cmd {

ConceptPtr defi_materiau(const Args& args, Session&) {
  auto mat = std::make_shared<Mater>();
  if (args.count("ELAS") > 0) {
    const Args elas = args.factor("ELAS");
    mat->has_elas = true;
    mat->elas.young = elas.real("E");
    mat->elas.poisson = elas.real("NU");
    if (elas.has("RHO")) mat->elas.density = elas.real("RHO");  // E > 0, -1 < NU < 0.5: catalogue bounds
  }
  return mat;
}

}  // namespace lunaster::cmd
