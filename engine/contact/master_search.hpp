#pragma once
/// Pairing of points with a master surface: orthogonal projection onto one
/// master cell (Newton on the cell parametrisation with fallbacks) and a
/// uniform-grid spatial index over the master cells' bounding boxes so that a
/// point is only projected on nearby cells (no all-pairs loop).
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "engine/mesh/mesh.hpp"

namespace lunaster::engine::contact {

/// Result of projecting a point on one cell.
struct CellProjection {
  double xi[2] = {0.0, 0.0};  ///< minimiser of |x(xi) - p| (may lie outside the cell)
  double outside = 0.0;       ///< outside_distance(xi), 0 inside
  bool converged = false;
};

/// Orthogonal projection of `point` on the cell of type `type` with node
/// coordinates `xyz` (3 per node): Newton on grad(|x(xi)-p|^2/2) = 0 from the
/// cell centre, then from every node if needed; keeps the closest converged
/// result. Never returns NaN (a degenerate cell gives converged = false).
CellProjection project_on_cell(CellType type, const double* xyz, const double* point);

/// Pairing of a point with the master surface.
struct MasterProjection {
  bool found = false;          ///< false: no master cell within the tolerance
  int cell = -1;               ///< mesh cell index
  double xi[2] = {0.0, 0.0};   ///< reference coordinates on `cell`, clamped into the cell
  double x[3] = {0.0, 0.0, 0.0};       ///< projected point, m
  double normal[3] = {0.0, 0.0, 0.0};  ///< outward unit master normal at the projection
  double distance = 0.0;       ///< |point - x|, m
  double outside = 0.0;        ///< reference distance outside the cell before clamping
};

/// Master surface with its spatial index. Coordinates are given per use
/// (current configuration); the index is rebuilt by `update`.
class MasterSurface {
 public:
  /// `cells`: master surface cells (SEG2/SEG3 or TRIA3/6, QUAD4/8). `linearise`
  /// treats quadratic cells as their vertex-only linear type (discrete methods).
  /// Orientation: each cell's normal is compared with the vector from the
  /// centroid of the adjacent volume cell; cells whose normal points inwards are
  /// flipped (counted in `n_flipped()`).
  MasterSurface(const Mesh& mesh, std::vector<int> cells, bool linearise);

  /// Rebuilds the grid for the coordinates `xyz` (3 per mesh node).
  void update(const std::vector<double>& xyz);

  /// Projects `point` on the nearest master cell. A projection outside a cell by
  /// more than `tolerance` (reference units, TOLE_PROJ_EXT) is rejected; within
  /// it, the projection is clamped into the cell. Reads the surface only: several threads
  /// may project at once.
  MasterProjection project(const double* point, double tolerance) const;

  const std::vector<int>& cells() const { return cells_; }
  /// Cell type used for the master geometry (linear type when linearised).
  CellType geometry_type(int k) const { return types_[k]; }
  /// Nodes used for cell k (vertices only when linearised).
  const std::vector<int>& cell_nodes(int k) const { return nodes_[k]; }
  /// Position of a mesh cell in `cells()`, -1 if absent.
  int local_index(int cell) const;
  int n_flipped() const { return n_flipped_; }
  /// +1 or -1: orientation applied to the geometric normal of cell k.
  double orientation(int k) const { return sign_[k]; }

 private:
  /// Cells whose boxes share a bucket with the point or its rings; a cell may be listed twice.
  std::vector<int> candidates(const double* point) const;
  void gather(const double* xyz, int k, double* out) const;
  std::int64_t key(int i, int j, int l) const;

  const Mesh& mesh_;
  std::vector<int> cells_;
  std::vector<CellType> types_;
  std::vector<std::vector<int>> nodes_;
  std::vector<double> sign_;
  std::unordered_map<int, int> local_;
  int n_flipped_ = 0;
  const std::vector<double>* xyz_ = nullptr;
  double origin_[3] = {0, 0, 0};
  double spacing_ = 1.0;
  int n_grid_[3] = {1, 1, 1};
  std::unordered_map<std::int64_t, std::vector<int>> grid_;
  std::vector<double> boxes_;  ///< per cell: min xyz, max xyz (widened for quadratic cells)
};

}  // namespace lunaster::engine::contact
