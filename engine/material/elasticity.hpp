#pragma once
/// Hooke matrices of linear isotropic elasticity in Voigt notation with
/// engineering shear strains (gamma_xy = 2 eps_xy). Units: Pa.
#include <Eigen/Core>

#include "engine/fe/fe_model.hpp"
#include "engine/material/behaviour.hpp"

namespace lunaster::engine {

/// 3D: order xx, yy, zz, xy, xz, yz.
Eigen::Matrix<double, 6, 6> elasticity_3d(const ElasticMaterial& mat);

/// In-plane 2D matrix, order xx, yy, xy: plane strain (eps_zz = 0) or plane
/// stress (sig_zz = 0) depending on `mod`.
Eigen::Matrix3d elasticity_2d(const ElasticMaterial& mat, Modelisation mod);

/// Out-of-plane stress of a 2D state: nu (sxx + syy) in plane strain, 0 in plane stress.
double sigma_zz_2d(const ElasticMaterial& mat, Modelisation mod, double sxx, double syy);

/// Full 2D matrix in order xx, yy, zz, xy acting on (exx, eyy, ezz, gxy); in
/// plane strain ezz = 0 is implied by the caller, in plane stress the row zz is zero.
Eigen::Matrix4d elasticity_2d_full(const ElasticMaterial& mat, Modelisation mod);

/// Axisymmetric (AXIS) matrix, order rr, zz (axial), tt (hoop), rz acting on
/// (e_rr, e_zz, e_tt, g_rz): the 3D matrix restricted to those components.
Eigen::Matrix4d elasticity_axis(const ElasticMaterial& mat);

/// True for E > 0 and -1 < nu < 0.5 (the matrices above throw InternalError otherwise).
bool is_admissible(const ElasticMaterial& mat);

/// Linear isotropic elasticity as a behaviour: stress = D strain with the matrices above for the
/// point's hypothesis (plane strain, plane stress, axisymmetric, 3D); no internal variables.
/// The matrices are built once here; a material that is not admissible throws the matrices'
/// InternalError when a point is integrated, not before (as when the matrices were built per cell).
class Elasticity final : public Behaviour {
 public:
  explicit Elasticity(const ElasticMaterial& mat);
  bool is_linear() const override { return true; }
  const std::vector<std::string>& variable_names() const override;
  IntegrationStatus integrate(const PointInput& in, PointOutput& out) const override;
  const ElasticMaterial& material() const { return mat_; }

 private:
  ElasticMaterial mat_;
  bool admissible_ = false;
  Eigen::Matrix<double, 6, 6> d3_;
  Eigen::Matrix3d plane_strain_, plane_stress_;           // in-plane (xx, yy, xy)
  Eigen::Matrix4d plane_strain_full_, plane_stress_full_, axis_;
};

}  // namespace lunaster::engine
