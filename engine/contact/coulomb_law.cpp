#include "engine/contact/coulomb_law.hpp"

#include <cmath>

#include "engine/assembly/dof_map.hpp"

namespace lunaster::engine::contact {

namespace {

class CoulombLaw final : public PointLaw {
 public:
  CoulombLaw(const ContactLaw& normal, FrictionEnforcement how, bool nodal_forces)
      : normal_(normal), how_(how), nodal_(nodal_forces) {}

  const char* name() const override {
    return how_ == FrictionEnforcement::AugmentedLagrangian ? "Coulomb (augmented Lagrangian)" : "Coulomb (penalty)";
  }
  std::vector<int> multipliers(int dim) const override {
    std::vector<int> m = normal_.multipliers(dim);
    if (how_ == FrictionEnforcement::AugmentedLagrangian) {
      m.push_back(LAGS_F1);
      if (dim == 3) m.push_back(LAGS_F2);
    }
    return m;
  }
  int n_tangents(int dim) const override { return dim - 1; }
  int n_history(int dim) const override { return how_ == FrictionEnforcement::Penalty ? dim - 1 : 0; }
  bool symmetric() const override { return false; }

  PointResponse evaluate(const PointKinematics& in, const PointState& start, PointState& state) const override {
    PointKinematics normal_in = in;
    normal_in.n_tangents = 0;
    PointResponse r = normal_.evaluate(normal_in, start, state);
    const int nt = in.n_tangents, n_normal_z = r.n_z;
    r.n_q = 1 + nt;
    if (how_ == FrictionEnforcement::AugmentedLagrangian) r.n_z = n_normal_z + nt;
    const double w = in.weight, w_t = nodal_ ? 1.0 : w;
    const bool closed = state.status != PointStatus::Open && w_t > 0.0;
    // The pressure (or the node's force) and its derivatives, from the normal law's response.
    const double p = closed ? -r.r_q[0] / w_t : 0.0;
    const double dp_dg = closed ? -r.k_qq[0][0] / w_t : 0.0, dp_dl = closed && n_normal_z ? -r.k_qz[0][0] / w_t : 0.0;
    // A closed point at zero pressure (the first iterate of a first contact) keeps its stick
    // stiffness: its bound is zero, but an unslipped point is not yet outside it.
    if (how_ == FrictionEnforcement::AugmentedLagrangian)
      multipliers_branch(in, n_normal_z, closed && p >= 0.0, p, dp_dg, dp_dl, w_t, r);
    else
      penalty(in, start, closed && p >= 0.0, p, dp_dg, dp_dl, w_t, r, state);
    state.status = r.status;
    return r;
  }

 private:
  /// Projection of v (n values) on the ball of radius `radius`: P(v) and dP/dv; true when v
  /// is outside (slip).
  static bool project(const double* v, int n, double radius, double* pv, double dpv[2][2]) {
    double norm2 = 0.0;
    for (int k = 0; k < n; ++k) norm2 += v[k] * v[k];
    const double norm = std::sqrt(norm2);
    const bool outside = norm > radius;
    for (int k = 0; k < n; ++k) {
      pv[k] = outside ? radius * v[k] / norm : v[k];
      for (int l = 0; l < n; ++l)
        dpv[k][l] = outside ? radius / norm * ((k == l ? 1.0 : 0.0) - v[k] * v[l] / norm2) : (k == l ? 1.0 : 0.0);
    }
    return outside;
  }

  void multipliers_branch(const PointKinematics& in, int z0, bool closed, double p, double dp_dg, double dp_dl,
                          double w_t, PointResponse& r) const {
    const int nt = in.n_tangents;
    const double w = in.weight, c = in.coefficient_t, mu = in.mu;
    const double* lt = in.z + z0;
    if (!closed) {
      for (int k = 0; k < nt; ++k) {
        r.r_z[z0 + k] = -w / c * lt[k];
        r.k_zz[z0 + k][z0 + k] = -w / c;
      }
      r.status = PointStatus::Open;
      return;
    }
    // v = lambda_t + c ds, t = P_{mu p}(v): r_q,t = w_t t, r_z,t = (w / c)(t - lambda_t).
    double v[2], t[2], dt[2][2];
    for (int k = 0; k < nt; ++k) v[k] = lt[k] + c * in.dq_step[1 + k];
    const bool slip = project(v, nt, mu * p, t, dt);
    r.status = slip ? PointStatus::Slip : PointStatus::Stick;
    double norm = 0.0;
    for (int k = 0; k < nt; ++k) norm += v[k] * v[k];
    norm = std::sqrt(norm);
    for (int k = 0; k < nt; ++k) {
      // In slip the bound mu p follows the normal unknowns: dt/dp = mu v / |v|.
      const double dt_dp = slip ? mu * v[k] / norm : 0.0;
      r.r_q[1 + k] = w_t * t[k];
      r.r_z[z0 + k] = w / c * (t[k] - lt[k]);
      r.k_qq[1 + k][0] = w_t * dt_dp * dp_dg;
      r.k_zq[z0 + k][0] = w / c * dt_dp * dp_dg;
      if (z0 > 0) {
        r.k_qz[1 + k][0] = w_t * dt_dp * dp_dl;
        r.k_zz[z0 + k][0] = w / c * dt_dp * dp_dl;
      }
      for (int l = 0; l < nt; ++l) {
        r.k_qq[1 + k][1 + l] = w_t * c * dt[k][l];
        r.k_qz[1 + k][z0 + l] = w_t * dt[k][l];
        r.k_zq[z0 + k][1 + l] = w * dt[k][l];
        r.k_zz[z0 + k][z0 + l] = w / c * (dt[k][l] - (k == l ? 1.0 : 0.0));
      }
    }
  }

  void penalty(const PointKinematics& in, const PointState& start, bool closed, double p, double dp_dg, double dp_dl,
               double w_t, PointResponse& r, PointState& state) const {
    const int nt = in.n_tangents;
    if (!closed) {
      for (int k = 0; k < nt; ++k) state.history[k] = 0.0;
      r.status = PointStatus::Open;
      return;
    }
    const double k_t = in.coefficient_t, mu = in.mu;
    double trial[2], t[2], dt[2][2];
    // A point that was open at the step's start carries no traction yet.
    const bool was_closed = start.status != PointStatus::Open;
    for (int k = 0; k < nt; ++k) trial[k] = (was_closed ? start.history[k] : 0.0) + k_t * in.dq_step[1 + k];
    const bool slip = project(trial, nt, mu * p, t, dt);
    r.status = slip ? PointStatus::Slip : PointStatus::Stick;
    double norm = 0.0;
    for (int k = 0; k < nt; ++k) norm += trial[k] * trial[k];
    norm = std::sqrt(norm);
    for (int k = 0; k < nt; ++k) {
      state.history[k] = t[k];
      r.r_q[1 + k] = w_t * t[k];
      for (int l = 0; l < nt; ++l) r.k_qq[1 + k][1 + l] = w_t * k_t * dt[k][l];
      if (slip) {  // t = mu p trial / |trial|: the bound follows the pressure
        const double n_k = trial[k] / norm;
        r.k_qq[1 + k][0] = w_t * mu * n_k * dp_dg;
        if (r.n_z > 0) r.k_qz[1 + k][0] = w_t * mu * n_k * dp_dl;
      }
    }
  }

  const ContactLaw& normal_;
  const FrictionEnforcement how_;
  const bool nodal_;
};

}  // namespace

std::unique_ptr<PointLaw> make_coulomb_law(const ContactLaw& normal, FrictionEnforcement how, bool nodal_forces) {
  return std::make_unique<CoulombLaw>(normal, how, nodal_forces);
}

}  // namespace lunaster::engine::contact
