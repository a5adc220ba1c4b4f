/// Storage of the integration points' history (material_states.hpp).
#include "engine/material/material_states.hpp"

#include "engine/core/error.hpp"

namespace lunaster::engine {

MaterialStates::MaterialStates(int tensor_size, const std::vector<int>& points_per_cell,
                               const std::vector<int>& variables_per_cell)
    : tensor_size_(tensor_size), n_variables_(variables_per_cell) {
  LUNASTER_ASSERT(points_per_cell.size() == variables_per_cell.size(), "material states: per-cell sizes differ");
  const size_t n = points_per_cell.size();
  point_offset_.assign(n + 1, 0);
  variable_offset_.assign(n + 1, 0);
  for (size_t c = 0; c < n; ++c) {
    point_offset_[c + 1] = point_offset_[c] + points_per_cell[c];
    variable_offset_[c + 1] = variable_offset_[c] + static_cast<size_t>(points_per_cell[c]) * variables_per_cell[c];
  }
  for (int s = 0; s < 2; ++s) {
    strain_[s].assign(static_cast<size_t>(point_offset_[n]) * tensor_size_, 0.0);
    stress_[s].assign(strain_[s].size(), 0.0);
    variables_[s].assign(variable_offset_[n], 0.0);
  }
}

double* MaterialStates::variables_at(Slot s, int cell, int q) {
  if (n_variables_[cell] == 0) return nullptr;
  return &variables_[slot(s)][variable_offset_[cell] + static_cast<size_t>(q) * n_variables_[cell]];
}

void MaterialStates::commit() {
  strain_[0] = strain_[1];
  stress_[0] = stress_[1];
  variables_[0] = variables_[1];
}

void MaterialStates::restore() {
  strain_[1] = strain_[0];
  stress_[1] = stress_[0];
  variables_[1] = variables_[0];
}

}  // namespace lunaster::engine
