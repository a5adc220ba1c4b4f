/// von Mises plasticity by radial return (von_mises.hpp).
#include "engine/material/von_mises.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "engine/core/error.hpp"
#include "engine/material/elasticity.hpp"

namespace lunaster::engine {
namespace {

using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat6 = Eigen::Matrix<double, 6, 6>;

/// s:s of a symmetric tensor stored (xx, yy, zz, xy, xz, yz) with tensor shears.
double contract(const Vec6& s) { return s.head<3>().squaredNorm() + 2.0 * s.tail<3>().squaredNorm(); }

/// K 1(x)1 + 2 mu theta I_dev - 2 mu theta_bar n(x)n, acting on engineering shear strains:
/// the symmetric identity is diag(1, 1, 1, 1/2, 1/2, 1/2) there, and n (a unit deviator in tensor
/// components) pairs with the strain as n:eps = n_i eps_i (normal) + n_ij gamma_ij (shear).
Mat6 isotropic_tangent(double bulk, double shear, double theta, double theta_bar, const Vec6& n) {
  Mat6 d = Mat6::Zero();
  const double deviatoric = 2.0 * shear * theta;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) d(i, j) = bulk - deviatoric / 3.0;
    d(i, i) += deviatoric;
    d(3 + i, 3 + i) = deviatoric / 2.0;
  }
  if (theta_bar != 0.0) d -= 2.0 * shear * theta_bar * n * n.transpose();
  return d;
}

}  // namespace

VonMises::VonMises(const ElasticMaterial& elastic, IsotropicHardening hardening, PlaneStressIteration local)
    : elastic_(elastic), hardening_(std::move(hardening)), local_(local) {
  if (!is_admissible(elastic)) throw InternalError("von Mises plasticity: material needs E > 0 and -1 < nu < 0.5");
  shear_ = elastic.young / (2.0 * (1.0 + elastic.poisson));
  bulk_ = elastic.young / (3.0 * (1.0 - 2.0 * elastic.poisson));
  elastic_tangent_ = isotropic_tangent(bulk_, shear_, 1.0, 0.0, Vec6::Zero());
}

const std::vector<std::string>& VonMises::variable_names() const {
  static const std::vector<std::string> names{"EPSPEQ", "INDIPLAS"};
  return names;
}

// Elastic predictor, then, outside the surface, the return along the trial deviator (R5.03.02,
// nmisot): s = s_trial (1 - 3 mu dp / q_trial) with q_trial - 3 mu dp = R(p + dp); the mean
// stress is elastic. Consistent tangent (Simo and Hughes, eq. 3.3.8; R5.03.16 with C = 0):
// K 1(x)1 + 2 mu theta I_dev - 2 mu theta_bar n(x)n, theta = 1 - 3 mu dp / q_trial,
// theta_bar = 3 mu / (3 mu + H) - 3 mu dp / q_trial, H = R'(p + dp), n = s_trial / |s_trial|.
bool VonMises::update_3d(const Vec6& stress_start, const Vec6& dstrain, double p_start, bool want_tangent,
                         Update& out) const {
  const double volume = dstrain.head<3>().sum();
  const double mean_start = stress_start.head<3>().sum() / 3.0;
  Vec6 deviator = stress_start;
  deviator.head<3>().array() += 2.0 * shear_ * (dstrain.head<3>().array() - volume / 3.0) - mean_start;
  deviator.tail<3>() += shear_ * dstrain.tail<3>();
  const double mean = mean_start + bulk_ * volume;
  const double trial = std::sqrt(1.5 * contract(deviator));
  const double radius = hardening_.radius(p_start);
  out.p = p_start;
  // A point left on the surface by the last converged step (trial = R to a few ulps) starts the
  // next step elastic, not elastic or plastic with the sign of its round-off.
  out.plastic = trial - radius > 1e-12 * radius;
  if (!out.plastic) {
    out.stress = deviator;
    out.stress.head<3>().array() += mean;
    if (want_tangent) out.tangent = elastic_tangent_;
    return true;
  }
  const double three_mu = 3.0 * shear_;
  double dp = 0.0, modulus = 0.0;
  if (!hardening_.return_increment(trial, three_mu, p_start, dp, modulus)) return false;
  out.p = p_start + dp;
  const double shrink = three_mu * dp / trial;
  out.stress = (1.0 - shrink) * deviator;
  out.stress.head<3>().array() += mean;
  if (want_tangent) {
    const Vec6 n = deviator / std::sqrt(contract(deviator));
    out.tangent = isotropic_tangent(bulk_, shear_, 1.0 - shrink, three_mu / (three_mu + modulus) - shrink, n);
  }
  return true;
}

// sigma_zz(dz) increases with the zz strain increment dz (its derivative is the tangent's zz
// diagonal, > 0), so Newton on it is kept inside the bracket of the signs seen so far and bisects
// when a step would leave it (the return is only piecewise smooth: a step can cross the surface).
bool VonMises::update_plane_stress(const TensorVector& stress_start, const Eigen::Vector3d& dstrain_plane,
                                   double p_start, Update& out) const {
  Vec6 start = Vec6::Zero(), increment = Vec6::Zero();
  start.head<4>() = stress_start.head<4>();
  increment(0) = dstrain_plane(0);
  increment(1) = dstrain_plane(1);
  increment(3) = dstrain_plane(2);
  const double lambda = bulk_ - 2.0 * shear_ / 3.0;
  double dz = -(start(2) + lambda * (increment(0) + increment(1))) / (lambda + 2.0 * shear_);  // elastic guess
  double low = -std::numeric_limits<double>::infinity(), high = std::numeric_limits<double>::infinity();
  for (int it = 0; it < local_.max_iterations; ++it) {
    increment(2) = dz;
    if (!update_3d(start, increment, p_start, true, out)) return false;
    const double szz = out.stress(2);
    const double scale = std::max(hardening_.radius(out.p), out.stress.cwiseAbs().maxCoeff());
    if (std::abs(szz) <= local_.tolerance * scale) return true;
    (szz < 0.0 ? low : high) = dz;
    double next = dz - szz / out.tangent(2, 2);
    if (!(next > low && next < high)) next = 0.5 * (low + high);
    if (!std::isfinite(next)) return false;
    dz = next;
  }
  return false;
}

IntegrationStatus VonMises::integrate(const PointInput& in, PointOutput& out) const {
  // Without a history (a caller that keeps no states) the step starts from the virgin state.
  const double p_start = in.variables_start ? in.variables_start[0] : 0.0;
  Update state;
  const TensorVector dstrain = in.strain_end - in.strain_start;
  switch (in.hypothesis) {
    case Modelisation::Solid3D:
      if (!update_3d(in.stress_start.head<6>(), dstrain.head<6>(), p_start, out.want_tangent, state))
        return IntegrationStatus::Failed;
      out.stress = state.stress;
      if (out.want_tangent) out.tangent = state.tangent;
      break;
    case Modelisation::PlaneStrain:
    case Modelisation::Axisymmetric: {  // the 3D return with zero xz, yz: the 4 components are exact
      Vec6 start = Vec6::Zero(), increment = Vec6::Zero();
      start.head<4>() = in.stress_start.head<4>();
      increment.head<4>() = dstrain.head<4>();
      if (!update_3d(start, increment, p_start, out.want_tangent, state)) return IntegrationStatus::Failed;
      out.stress = state.stress.head<4>();
      if (out.want_tangent) out.tangent = state.tangent.topLeftCorner<4, 4>();
      break;
    }
    case Modelisation::PlaneStress: {
      if (!update_plane_stress(in.stress_start, Eigen::Vector3d(dstrain(0), dstrain(1), dstrain(3)), p_start, state))
        return IntegrationStatus::Failed;
      out.stress.resize(4);
      out.stress << state.stress(0), state.stress(1), 0.0, state.stress(3);
      if (out.want_tangent) {  // condensed on sigma_zz = 0: D_ab - D_az D_zb / D_zz, row and column zz zero
        const int plane[3] = {0, 1, 3};
        out.tangent = TangentMatrix::Zero(4, 4);
        for (int a : plane)
          for (int b : plane)
            out.tangent(a, b) = state.tangent(a, b) - state.tangent(a, 2) * state.tangent(2, b) / state.tangent(2, 2);
      }
      break;
    }
    default:
      throw InternalError("von Mises plasticity: a point without a mechanical hypothesis");
  }
  if (out.variables_end) {
    out.variables_end[0] = state.p;
    out.variables_end[1] = state.plastic ? 1.0 : 0.0;
  }
  return IntegrationStatus::Ok;
}

}  // namespace lunaster::engine
