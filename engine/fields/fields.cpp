#include "engine/fields/fields.hpp"

namespace lunaster::engine {

NodalField::NodalField(std::vector<std::string> cmps, int nodes)
    : components(std::move(cmps)),
      n_nodes(nodes),
      values(static_cast<size_t>(nodes) * components.size(), 0.0),
      defined(static_cast<size_t>(nodes) * components.size(), 0) {}

int NodalField::component_index(const std::string& cmp) const {
  for (size_t i = 0; i < components.size(); ++i)
    if (components[i] == cmp) return static_cast<int>(i);
  return -1;
}

int ElnoField::component_index(const std::string& cmp) const {
  for (size_t i = 0; i < components.size(); ++i)
    if (components[i] == cmp) return static_cast<int>(i);
  return -1;
}

}  // namespace lunaster::engine
