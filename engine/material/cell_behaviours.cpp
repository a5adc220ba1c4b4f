/// Behaviours per cell (cell_behaviours.hpp).
#include "engine/material/cell_behaviours.hpp"

#include <string>

#include "engine/core/error.hpp"
#include "engine/material/elasticity.hpp"

namespace lunaster::engine {

CellBehaviours::CellBehaviours(const FeModel& model) : model_(&model) {
  LUNASTER_ASSERT(model.mesh != nullptr, "cell behaviours: model without mesh");
  std::vector<const Behaviour*> of_material;
  for (const ElasticMaterial& mat : model.materials) {
    owned_.push_back(std::make_shared<Elasticity>(mat));
    of_material.push_back(owned_.back().get());
  }
  of_cell_.assign(model.mesh->n_cells(), nullptr);
  for (int c = 0; c < model.mesh->n_cells() && c < static_cast<int>(model.material.size()); ++c) {
    const int m = model.material[c];
    if (m >= 0 && m < static_cast<int>(of_material.size())) of_cell_[c] = of_material[m];
  }
}

void CellBehaviours::assign(const std::vector<int>& cells, std::shared_ptr<const Behaviour> behaviour) {
  LUNASTER_ASSERT(behaviour != nullptr, "cell behaviours: no behaviour to assign");
  for (int c : cells) of_cell_.at(c) = behaviour.get();
  owned_.push_back(std::move(behaviour));
}

const Behaviour& CellBehaviours::of(int cell) const {
  const Behaviour* b = cell < static_cast<int>(of_cell_.size()) ? of_cell_[cell] : nullptr;
  if (!b) throw DeckError("cell " + cell_name(cell) + " carries an element but no material");
  return *b;
}

std::string CellBehaviours::cell_name(int cell) const {
  const Mesh& mesh = *model_->mesh;
  return cell < static_cast<int>(mesh.cell_names.size()) ? mesh.cell_names[cell] : "#" + std::to_string(cell + 1);
}

void CellBehaviours::set_kinematics(const std::vector<int>& cells, Kinematics kinematics) {
  kinematics_.resize(of_cell_.size(), Kinematics::SmallStrain);
  for (int c : cells) {
    // The thickness stretch of a plane stress cell is its behaviour's, unknown to the kinematics.
    if (kinematics == Kinematics::TotalLagrangian && model_->modelisation.at(c) == Modelisation::PlaneStress)
      throw DeckError("cell " + cell_name(c) + ": large rotations (total Lagrangian) are not available in plane stress");
    kinematics_.at(c) = kinematics;
  }
}

bool CellBehaviours::all_linear() const {
  for (int c : model_->volume_cells())
    if ((of_cell_[c] && !of_cell_[c]->is_linear()) || kinematics(c) != Kinematics::SmallStrain) return false;
  return true;
}

bool CellBehaviours::tangents_positive_definite() const {
  for (int c : model_->volume_cells())
    if (of_cell_[c] && !of_cell_[c]->tangent_positive_definite()) return false;
  return true;
}

}  // namespace lunaster::engine
