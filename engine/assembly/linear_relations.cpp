#include "engine/assembly/linear_relations.hpp"

#include <map>
#include <string>

#include "engine/core/error.hpp"

namespace lunaster::engine {

void LinearRelations::add_dofs(DofMap& dofs, const std::set<std::pair<int, int>>& imposed) {
  for (size_t i = 0; i < relations_.size(); ++i) {
    LinearRelation& r = relations_[i];
    if (imposed_only(r, imposed)) {
      r.multiplier = -1;
      continue;
    }
    if (r.carrier_node < 0) {
      for (size_t k = 0; k < r.terms.size() && r.carrier_node < 0; ++k)
        for (int c = LAGR_DX; c <= LAGR_DZ && r.carrier_node < 0; ++c)
          if (dofs.dof(r.terms[k].node, c) < 0) r.carrier_node = r.terms[k].node, r.carrier_component = c;
      if (r.carrier_node < 0)
        throw DeckError(relation_name(r, i) +
                        ": every node of it already carries three relation multipliers (the most a node "
                        "carries); relate these nodes through fewer relations, or add a node to this one");
    }
    r.multiplier = dofs.add(r.carrier_node, r.carrier_component);
  }
}

std::string relation_name(const LinearRelation& relation, size_t index) {
  return relation.label.empty() ? "linear relation " + std::to_string(index + 1) : relation.label;
}

bool imposed_only(const LinearRelation& relation, const std::set<std::pair<int, int>>& imposed) {
  for (const auto& t : relation.terms)
    if (!imposed.count({t.node, t.component})) return false;
  return true;
}

bool LinearRelations::any_multiplier() const {
  for (const auto& r : relations_)
    if (r.multiplier >= 0) return true;
  return false;
}

void LinearRelations::add_to_system(const DofMap& dofs, const Vector& u, std::vector<Triplet>& tangent,
                                    Vector& residual, const std::function<double(int)>& factor) const {
  add_residual(dofs, u, residual, factor);
  for (const auto& r : relations_) {
    const int leq = r.multiplier;
    if (leq < 0) continue;
    for (const auto& t : r.terms) {
      const int eq = dofs.dof(t.node, t.component);
      tangent.emplace_back(leq, eq, t.coef);
      tangent.emplace_back(eq, leq, t.coef);
    }
  }
}

void LinearRelations::add_residual(const DofMap& dofs, const Vector& u, Vector& residual,
                                   const std::function<double(int)>& factor) const {
  for (const auto& r : relations_) {
    const int leq = r.multiplier;
    if (leq < 0) continue;
    const double lambda = u[leq];
    if (r.value != 0.0) residual[leq] -= r.value * (r.load >= 0 && factor ? factor(r.load) : 1.0);
    for (const auto& t : r.terms) {
      const int eq = dofs.dof(t.node, t.component);
      residual[leq] += t.coef * u[eq];
      residual[eq] += t.coef * lambda;
    }
  }
}

std::vector<LinearRelation> split_dirichlet(std::vector<LinearRelation> relations,
                                            std::vector<DirichletValue>& dirichlet) {
  std::vector<LinearRelation> left;
  for (LinearRelation& r : relations) {
    std::map<std::pair<int, int>, double> sum;
    std::vector<std::pair<int, int>> order;
    for (const auto& t : r.terms) {
      auto [it, fresh] = sum.emplace(std::make_pair(t.node, t.component), 0.0);
      if (fresh) order.push_back(it->first);
      it->second += t.coef;
    }
    r.terms.clear();
    for (const auto& key : order)
      if (sum[key] != 0.0) r.terms.push_back({key.first, key.second, sum[key]});
    if (r.terms.size() == 1) {
      const auto& t = r.terms[0];
      dirichlet.push_back({t.node, t.component, r.value / t.coef, r.load});
      continue;
    }
    left.push_back(std::move(r));
  }
  return left;
}

}  // namespace lunaster::engine
