#pragma once
/// What is imposed on a mechanical model, in engine terms (filled by commands/).
#include <array>
#include <functional>
#include <vector>

#include "engine/assembly/linear_relations.hpp"

namespace lunaster::engine {

/// Pressure on boundary cells (PRES_REP), Pa.
struct PressureLoad { std::vector<int> cells; double pressure; int load; };
/// Force density on cells of dimension `cells_dim` (N/m on edges, N/m2 on faces, N/m3 on the
/// model's cells: FORCE_CONTOUR, FORCE_ARETE, FORCE_FACE, FORCE_INTERNE). `per_mass`: the
/// force is per unit mass (m/s2, PESANTEUR), multiplied by each cell's material density.
struct DistributedForce {
  std::vector<int> cells;
  int cells_dim;
  std::array<double, 3> force;
  bool per_mass;
  int load;
};
/// Nodal force (FORCE_NODALE), N.
struct NodalForce { int node; int component; double value; int load; };

/// Everything imposed on the model; value(t) = value * multipliers[load](t).
struct MechanicalLoads {
  std::vector<DirichletValue> dirichlet;
  std::vector<PressureLoad> pressures;
  std::vector<NodalForce> forces;
  std::vector<DistributedForce> distributed;
  /// Relations between displacement components of two terms or more (LIAISON_DDL; a
  /// one-term relation is a Dirichlet value, split_dirichlet in linear_relations.hpp).
  std::vector<LinearRelation> relations;
  std::vector<std::function<double(double)>> multipliers;  ///< one per load index
};

}  // namespace lunaster::engine
