#pragma once
/// Locating points in cells of the model's dimension (volumes in 3D, faces in 2D): the cell
/// that holds a point and the point's reference coordinates in it, or, for a point outside
/// every cell, the nearest cell and the point of it nearest in reference coordinates. Used to
/// tie nodes to a mesh they do not belong to (LIAISON_MAIL: u(node) = sum N_a(xi) u_a).
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "engine/mesh/mesh.hpp"

namespace lunaster::engine {

/// Where a point lies in a set of cells.
struct PointLocation {
  int cell = -1;                ///< mesh cell index; -1 when the set is empty
  double xi[3] = {0, 0, 0};     ///< reference coordinates, inside the cell (clamped when outside)
  double distance = 0.0;        ///< |point - x(xi)|: 0 inside, m
  bool inside = false;          ///< the point lies in the cell (to 1e-10 in reference units)
};

/// Reference coordinates xi of `point` in a cell of type `type` (dimension 2 or 3, node
/// coordinates `xyz`, 3 per node): Newton on x(xi) = point from the cell's centre. Returns
/// false when Newton does not converge (a point far outside a strongly curved cell).
bool reference_coordinates(CellType type, const double* xyz, const double* point, double* xi);

/// Whether reference coordinates lie in the reference cell, to `tolerance`.
bool inside_reference(CellType type, const double* xi, double tolerance);

/// Moves reference coordinates into the reference cell (the nearest point of it for
/// QUAD/HEXA and along each axis for the simplices' faces).
void clamp_to_reference(CellType type, double* xi);

/// A set of cells of one dimension with a uniform grid over their bounding boxes, so that a
/// point is tried against nearby cells only.
class CellLocator {
 public:
  /// `cells`: mesh cells of dimension 2 (QUAD4/8, TRIA3/6) or 3 (HEXA8/20, PENTA6/15,
  /// TETRA4/10), all of one dimension.
  CellLocator(const Mesh& mesh, std::vector<int> cells);

  /// The cell holding `point`; among several (a point on a shared face), the lowest cell
  /// index; outside every cell, the nearest (by |point - x(clamped xi)|, then lowest index; a
  /// cell where Newton gives up, the point far away, is measured by its nearest node, whose
  /// reference coordinates `xi` then are). Never -1 when the set has cells.
  PointLocation locate(const double* point) const;

 private:
  std::int64_t key(const int* ijk) const;
  void bucket_of(const double* point, int* ijk) const;
  /// Cell k of `cells_` against the point (`out`); false only for a cell without nodes.
  bool try_cell(int k, const double* point, PointLocation& out) const;

  const Mesh& mesh_;
  std::vector<int> cells_;
  std::vector<double> boxes_;  ///< per cell: min xyz then max xyz, widened by a tenth of the box
  double origin_[3] = {0, 0, 0};
  double spacing_ = 1.0;
  int n_[3] = {1, 1, 1};
  std::unordered_map<std::int64_t, std::vector<int>> grid_;
};

}  // namespace lunaster::engine
