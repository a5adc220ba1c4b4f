#pragma once
/// Which behaviour each cell of a model follows.
#include <memory>
#include <string>
#include <vector>

#include "engine/fe/fe_model.hpp"
#include "engine/material/behaviour.hpp"

namespace lunaster::engine {

/// How a cell's displacement becomes the strain its behaviour sees.
enum class Kinematics : unsigned char {
  SmallStrain,      ///< linearised strain on the initial configuration, the stress Cauchy's
  TotalLagrangian,  ///< large rotations: Green-Lagrange strain on the initial configuration, the
                    ///< stress the second Piola-Kirchhoff (small strains, any rotation)
};

/// The behaviour of every cell of a model, shared (one behaviour object serves all the cells of
/// a material). Lifetime: that of the model it was built from (it keeps a pointer to it).
class CellBehaviours {
 public:
  /// Linear elasticity (Elasticity) for every cell carrying a material, one object per material.
  explicit CellBehaviours(const FeModel& model);
  /// `behaviour` for `cells` instead (not owned alone: shared with the caller).
  void assign(const std::vector<int>& cells, std::shared_ptr<const Behaviour> behaviour);
  /// The behaviour of `cell`; DeckError naming the cell if it carries an element but no material.
  const Behaviour& of(int cell) const;
  /// `kinematics` for `cells` (small strain until set). DeckError naming a plane stress cell
  /// under the total Lagrangian kinematics.
  void set_kinematics(const std::vector<int>& cells, Kinematics kinematics);
  /// The kinematics of `cell`.
  Kinematics kinematics(int cell) const {
    return cell < static_cast<int>(kinematics_.size()) ? kinematics_[cell] : Kinematics::SmallStrain;
  }
  /// True when every cell's response is linear in the displacement: its behaviour linear
  /// (Behaviour::is_linear) and its kinematics small strain. The tangent is then the stiffness.
  bool all_linear() const;
  /// True when every cell's behaviour keeps a positive definite tangent
  /// (Behaviour::tangent_positive_definite).
  bool tangents_positive_definite() const;
  const FeModel& model() const { return *model_; }

 private:
  std::string cell_name(int cell) const;

  const FeModel* model_;
  std::vector<std::shared_ptr<const Behaviour>> owned_;
  std::vector<const Behaviour*> of_cell_;  ///< per mesh cell, nullptr: none
  std::vector<Kinematics> kinematics_;     ///< per mesh cell once set, else all small strain
};

}  // namespace lunaster::engine
