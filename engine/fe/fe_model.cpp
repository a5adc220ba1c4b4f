/// FeModel helpers.
#include "engine/fe/fe_model.hpp"

#include "engine/fe/reference_element.hpp"

namespace lunaster::engine {

std::vector<int> FeModel::volume_cells() const {
  std::vector<int> out;
  if (!mesh) return out;
  const int n = mesh->n_cells();
  for (int c = 0; c < n; ++c) {
    if (c >= static_cast<int>(modelisation.size()) || modelisation[c] == Modelisation::None) continue;
    if (cell_dim(mesh->cell_types[c]) == dim) out.push_back(c);
  }
  return out;
}

bool FeModel::axisymmetric() const {
  for (Modelisation m : modelisation)
    if (m == Modelisation::Axisymmetric) return true;
  return false;
}

}  // namespace lunaster::engine
