/// describe_equation: equation -> "node N12, component DY".
#include "engine/assembly/equation_name.hpp"

namespace lunaster::engine {

std::string describe_equation(const Mesh& mesh, const DofMap& dofs, int eq) {
  if (eq < 0 || eq >= dofs.n_dofs()) return "equation " + std::to_string(eq);
  const int node = dofs.node_of(eq);
  const std::string name =
      node < static_cast<int>(mesh.node_names.size()) ? mesh.node_names[node] : "N" + std::to_string(node + 1);
  return "node " + name + ", component " + component_name(dofs.component_of(eq));
}

}  // namespace lunaster::engine
