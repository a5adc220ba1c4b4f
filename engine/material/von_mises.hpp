#pragma once
/// Small-strain von Mises plasticity with isotropic hardening, integrated by the implicit radial
/// return (Simo and Hughes, Computational Inelasticity, 1998, box 3.2; code_aster R5.03.02),
/// with the consistent (algorithmic) tangent. The law is incremental: the stress at a step's end
/// is the stress at its start plus the return of the strain increment, so it needs no plastic
/// strain tensor, only the cumulated plastic strain.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "engine/fe/fe_model.hpp"
#include "engine/material/behaviour.hpp"
#include "engine/material/isotropic_hardening.hpp"

namespace lunaster::engine {

/// The plane stress iteration of a von Mises law on the zz strain: converged when |sigma_zz| <=
/// tolerance times the stress scale (the larger of R(p) and the largest stress component), failed
/// (the step is to be subdivided) after max_iterations.
struct PlaneStressIteration {
  double tolerance = 1e-12;
  int max_iterations = 100;
};

/// von Mises plasticity, isotropic hardening R(p), isotropic elasticity (E, nu). Internal
/// variables: the cumulated plastic strain p, then the step's plastic indicator (1 when the step
/// yielded, 0 when it stayed elastic), as code_aster's EPSPEQ and INDIPLAS. Every hypothesis: 3D,
/// plane strain, axisymmetric (the 3D return on the 4 components) and plane stress (the 3D
/// return with the zz strain increment found by a local Newton iteration that brings the zz
/// stress to 0, the tangent condensed on the in-plane components).
class VonMises final : public Behaviour {
 public:
  /// `elastic`: E > 0, -1 < nu < 0.5 (InternalError otherwise); its density is not used.
  VonMises(const ElasticMaterial& elastic, IsotropicHardening hardening, PlaneStressIteration local = {});
  bool is_linear() const override { return false; }
  const std::vector<std::string>& variable_names() const override;
  /// Failed when the return has no solution (past a curve's excluded end) or when the plane
  /// stress iteration does not converge.
  IntegrationStatus integrate(const PointInput& in, PointOutput& out) const override;

  const ElasticMaterial& elastic() const { return elastic_; }
  const IsotropicHardening& hardening() const { return hardening_; }

  /// The 3D state at a step's end: stress (xx, yy, zz, xy, xz, yz), p, whether the step yielded
  /// and the consistent tangent (with respect to engineering shear strains).
  struct Update {
    Eigen::Matrix<double, 6, 1> stress;
    double p = 0.0;
    bool plastic = false;
    Eigen::Matrix<double, 6, 6> tangent;
  };
  /// The radial return of the 3D strain increment `dstrain` (engineering shears) from the
  /// state (stress_start, p_start); false when the return has no solution.
  bool update_3d(const Eigen::Matrix<double, 6, 1>& stress_start, const Eigen::Matrix<double, 6, 1>& dstrain,
                 double p_start, bool want_tangent, Update& out) const;

 private:
  bool update_plane_stress(const TensorVector& stress_start, const Eigen::Vector3d& dstrain_plane, double p_start,
                           Update& out) const;

  ElasticMaterial elastic_;
  IsotropicHardening hardening_;
  PlaneStressIteration local_;
  double shear_ = 0.0, bulk_ = 0.0;  ///< mu, K (Pa)
  Eigen::Matrix<double, 6, 6> elastic_tangent_;
};

}  // namespace lunaster::engine
