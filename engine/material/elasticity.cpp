/// Isotropic Hooke matrices (Lame form).
#include "engine/material/elasticity.hpp"

#include "engine/core/error.hpp"

namespace lunaster::engine {
namespace {

void check(const ElasticMaterial& mat) {
  if (!is_admissible(mat))
    throw InternalError("elasticity: material needs E > 0 and -1 < nu < 0.5");
}

}  // namespace

bool is_admissible(const ElasticMaterial& mat) {
  return mat.young > 0.0 && mat.poisson > -1.0 && mat.poisson < 0.5;
}

Eigen::Matrix<double, 6, 6> elasticity_3d(const ElasticMaterial& mat) {
  check(mat);
  const double e = mat.young, nu = mat.poisson;
  const double lambda = e * nu / ((1 + nu) * (1 - 2 * nu)), mu = e / (2 * (1 + nu));
  Eigen::Matrix<double, 6, 6> d = Eigen::Matrix<double, 6, 6>::Zero();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) d(i, j) = lambda;
    d(i, i) = lambda + 2 * mu;
    d(3 + i, 3 + i) = mu;
  }
  return d;
}

Eigen::Matrix3d elasticity_2d(const ElasticMaterial& mat, Modelisation mod) {
  check(mat);
  const double e = mat.young, nu = mat.poisson;
  Eigen::Matrix3d d = Eigen::Matrix3d::Zero();
  if (mod == Modelisation::PlaneStress) {
    const double c = e / (1 - nu * nu);
    d << c, c * nu, 0, c * nu, c, 0, 0, 0, c * (1 - nu) / 2;
  } else {
    const double lambda = e * nu / ((1 + nu) * (1 - 2 * nu)), mu = e / (2 * (1 + nu));
    d << lambda + 2 * mu, lambda, 0, lambda, lambda + 2 * mu, 0, 0, 0, mu;
  }
  return d;
}

double sigma_zz_2d(const ElasticMaterial& mat, Modelisation mod, double sxx, double syy) {
  return mod == Modelisation::PlaneStress ? 0.0 : mat.poisson * (sxx + syy);
}

Eigen::Matrix4d elasticity_2d_full(const ElasticMaterial& mat, Modelisation mod) {
  Eigen::Matrix4d d = Eigen::Matrix4d::Zero();
  if (mod == Modelisation::PlaneStress) {
    const Eigen::Matrix3d d2 = elasticity_2d(mat, mod);
    const int map[3] = {0, 1, 3};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) d(map[i], map[j]) = d2(i, j);
    return d;
  }
  const Eigen::Matrix<double, 6, 6> d3 = elasticity_3d(mat);
  d.topLeftCorner<3, 3>() = d3.topLeftCorner<3, 3>();
  d(3, 3) = d3(3, 3);
  return d;
}

Eigen::Matrix4d elasticity_axis(const ElasticMaterial& mat) {
  const Eigen::Matrix<double, 6, 6> d3 = elasticity_3d(mat);
  Eigen::Matrix4d d = Eigen::Matrix4d::Zero();
  d.topLeftCorner<3, 3>() = d3.topLeftCorner<3, 3>();
  d(3, 3) = d3(3, 3);
  return d;
}

Elasticity::Elasticity(const ElasticMaterial& mat) : mat_(mat), admissible_(is_admissible(mat)) {
  if (!admissible_) return;
  d3_ = elasticity_3d(mat);
  plane_strain_ = elasticity_2d(mat, Modelisation::PlaneStrain);
  plane_stress_ = elasticity_2d(mat, Modelisation::PlaneStress);
  plane_strain_full_ = elasticity_2d_full(mat, Modelisation::PlaneStrain);
  plane_stress_full_ = elasticity_2d_full(mat, Modelisation::PlaneStress);
  axis_ = elasticity_axis(mat);
}

const std::vector<std::string>& Elasticity::variable_names() const {
  static const std::vector<std::string> none;
  return none;
}

// The stress is the total form D strain_end (not stress_start + D increment): a linear law's
// stress then does not depend on the path, and the plane products are the in-plane 3x3 ones,
// so the stresses and forces are those of the matrices applied directly.
IntegrationStatus Elasticity::integrate(const PointInput& in, PointOutput& out) const {
  if (!admissible_) check(mat_);
  const TensorVector& e = in.strain_end;
  switch (in.hypothesis) {
    case Modelisation::PlaneStrain:
    case Modelisation::PlaneStress: {
      const bool strain = in.hypothesis == Modelisation::PlaneStrain;
      const Eigen::Vector3d s = (strain ? plane_strain_ : plane_stress_) * Eigen::Vector3d(e(0), e(1), e(3));
      out.stress.resize(4);
      out.stress << s(0), s(1), sigma_zz_2d(mat_, in.hypothesis, s(0), s(1)), s(2);
      if (out.want_tangent) out.tangent = strain ? plane_strain_full_ : plane_stress_full_;
      break;
    }
    case Modelisation::Axisymmetric:
      out.stress = axis_ * Eigen::Vector4d(e.head<4>());
      if (out.want_tangent) out.tangent = axis_;
      break;
    default:
      out.stress = d3_ * Eigen::Matrix<double, 6, 1>(e.head<6>());
      if (out.want_tangent) out.tangent = d3_;
      break;
  }
  return IntegrationStatus::Ok;
}

}  // namespace lunaster::engine
