#pragma once
/// The finite-element description a solve needs: which cells carry which
/// mechanical element, and their material. Built by AFFE_MODELE/AFFE_MATERIAU.
#include <limits>
#include <vector>

#include "engine/mesh/mesh.hpp"

namespace lunaster::engine {

/// Axisymmetric (AXIS): x is the radius r >= 0, y the axis of revolution; integrals are
/// per radian (weight r, as code_aster's AXIS elements), so nodal forces and reactions are
/// per radian of circumference.
enum class Modelisation { None, PlaneStrain, PlaneStress, Solid3D, Axisymmetric };

/// Linear isotropic elasticity. Units: Pa, -, kg/m^3.
struct ElasticMaterial {
  double young = 0.0;
  double poisson = 0.0;
  double density = std::numeric_limits<double>::quiet_NaN();  ///< kg/m3; NaN: not given
};

struct FeModel {
  const Mesh* mesh = nullptr;
  int dim = 0;                                ///< 2 (D_PLAN, C_PLAN, AXIS) or 3
  std::vector<Modelisation> modelisation;     ///< per mesh cell; None for cells not modelled
  std::vector<int> material;                  ///< per mesh cell: index into materials, -1 none
  std::vector<ElasticMaterial> materials;

  /// Cells of the model's own dimension carrying a mechanical element.
  std::vector<int> volume_cells() const;
  /// True when the model's cells are axisymmetric (AFFE_MODELE forbids mixing AXIS with
  /// plane modelisations): every measure is then per radian, weighted by r = x.
  bool axisymmetric() const;
};

}  // namespace lunaster::engine
