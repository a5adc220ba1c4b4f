#include "engine/assembly/linear_relations.hpp"

namespace lunaster::engine {

void LinearRelations::add_dofs(DofMap& dofs, const std::set<std::pair<int, int>>& imposed) {
  for (auto& r : relations_) {
    bool all_imposed = true;
    for (const auto& t : r.terms) all_imposed = all_imposed && imposed.count({t.node, t.component});
    r.multiplier = all_imposed ? -1 : dofs.add(r.carrier_node, r.carrier_component);
  }
}

void LinearRelations::add_to_system(const DofMap& dofs, const Vector& u, std::vector<Triplet>& tangent,
                                    Vector& residual) const {
  for (const auto& r : relations_) {
    const int leq = r.multiplier;
    if (leq < 0) continue;
    const double lambda = u[leq];
    for (const auto& t : r.terms) {
      const int eq = dofs.dof(t.node, t.component);
      residual[leq] += t.coef * u[eq];
      residual[eq] += t.coef * lambda;
      tangent.emplace_back(leq, eq, t.coef);
      tangent.emplace_back(eq, leq, t.coef);
    }
  }
}

}  // namespace lunaster::engine
