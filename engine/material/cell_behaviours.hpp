#pragma once
/// Which behaviour each cell of a model follows.
#include <memory>
#include <vector>

#include "engine/fe/fe_model.hpp"
#include "engine/material/behaviour.hpp"

namespace lunaster::engine {

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
  /// True when every cell's behaviour is linear (Behaviour::is_linear).
  bool all_linear() const;
  const FeModel& model() const { return *model_; }

 private:
  const FeModel* model_;
  std::vector<std::shared_ptr<const Behaviour>> owned_;
  std::vector<const Behaviour*> of_cell_;  ///< per mesh cell, nullptr: none
};

}  // namespace lunaster::engine
