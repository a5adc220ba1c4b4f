#pragma once
/// The history of every integration point of a model: strain, stress and internal variables at
/// the start of the current step (committed) and at its end (trial). A Newton iteration writes
/// the trial slot; commit() makes it the start of the next step when the step converged,
/// restore() brings the trial slot back to the step's start when the step is subdivided.
#include <cstddef>
#include <vector>

namespace lunaster::engine {

/// Flat per-point storage, cell by cell, points in quadrature order. Lifetime: one run (a
/// result's history); the layout is fixed at construction.
class MaterialStates {
 public:
  /// Which slot a view reads: the step's start (committed) or its end (trial).
  enum class Slot { Start = 0, End = 1 };

  MaterialStates() = default;
  /// Zero states for `points_per_cell[c]` points of `variables_per_cell[c]` internal variables
  /// each (0 points for cells without a behaviour), tensors of `tensor_size` entries.
  MaterialStates(int tensor_size, const std::vector<int>& points_per_cell, const std::vector<int>& variables_per_cell);

  int tensor_size() const { return tensor_size_; }
  int n_cells() const { return static_cast<int>(point_offset_.size()) - 1; }
  int n_points(int cell) const { return point_offset_[cell + 1] - point_offset_[cell]; }
  int n_variables(int cell) const { return n_variables_[cell]; }

  double* strain(Slot s, int cell, int q) { return &strain_[slot(s)][tensor_at(cell, q)]; }
  const double* strain(Slot s, int cell, int q) const { return &strain_[slot(s)][tensor_at(cell, q)]; }
  double* stress(Slot s, int cell, int q) { return &stress_[slot(s)][tensor_at(cell, q)]; }
  const double* stress(Slot s, int cell, int q) const { return &stress_[slot(s)][tensor_at(cell, q)]; }
  /// The n_variables(cell) internal variables of point q (nullptr when there are none).
  double* variables(Slot s, int cell, int q) { return variables_at(s, cell, q); }
  const double* variables(Slot s, int cell, int q) const {
    return const_cast<MaterialStates*>(this)->variables_at(s, cell, q);
  }

  /// The step converged: its end becomes the next step's start.
  void commit();
  /// The step is abandoned (subdivided): its end is reset to its start.
  void restore();

 private:
  static int slot(Slot s) { return static_cast<int>(s); }
  std::size_t tensor_at(int cell, int q) const { return (static_cast<std::size_t>(point_offset_[cell]) + q) * tensor_size_; }
  double* variables_at(Slot s, int cell, int q);

  int tensor_size_ = 0;
  std::vector<int> point_offset_{0};      ///< n_cells + 1, in points
  std::vector<int> n_variables_;          ///< per cell
  std::vector<std::size_t> variable_offset_{0};  ///< n_cells + 1, in values
  std::vector<double> strain_[2], stress_[2], variables_[2];
};

}  // namespace lunaster::engine
