#pragma once
// A toy nonlinear behaviour for the unit tests (the fe tests' hand-written Newton loop and the
// production driver's): the xx component follows a 1D plasticity with the nonlinear isotropic
// hardening R(p) = sy + Q (1 - exp(-b p)), return mapping solved by a local Newton, consistent
// tangent E R'/(E + R'); yy and xy are linear (E, E/2: no Poisson coupling), zz carries no stress.
// Internal variables EPSPEQ (p) and EPSPXX (the plastic xx strain). Plane models only (4 entries).
//
// Under a uniform traction t along x (u_x = 0 on one side) the solution is uniform: sigma_xx = t
// on the yield surface t = R(p), p = exact_p(t), eps_xx = t / E + p; the hardening saturates at
// sy + Q, above which no equilibrium exists.
#include <cmath>
#include <string>
#include <vector>

#include "engine/material/behaviour.hpp"

namespace lunaster::engine::hardening_bar {

constexpr double kE = 200e3, kSy = 200.0, kQ = 100.0, kB = 20.0;

class HardeningBar final : public Behaviour {
 public:
  bool is_linear() const override { return false; }
  const std::vector<std::string>& variable_names() const override { return names_; }
  IntegrationStatus integrate(const PointInput& in, PointOutput& out) const override {
    const double p0 = in.variables_start[0], ep0 = in.variables_start[1];
    const double trial = kE * (in.strain_end(0) - ep0);
    double p = p0, ep = ep0, sxx = trial, et = kE;
    // Plastic when the trial stress is outside the surface by more than its round-off: a point
    // left on the surface by the last converged step (|trial| = R(p0) to a few ulps) starts the
    // next step elastic at every point, not elastic or plastic with the sign of its round-off.
    if (std::abs(trial) - radius(p0) > 1e-12 * radius(p0)) {
      const double sign = trial > 0 ? 1.0 : -1.0;
      double dp = 0.0;
      for (int it = 0;; ++it) {  // g(dp) = |trial| - E dp - R(p0 + dp) = 0, g' = -(E + R')
        const double g = std::abs(trial) - kE * dp - radius(p0 + dp);
        if (std::abs(g) <= 1e-14 * std::abs(trial)) break;  // |g| at the round-off of |trial|
        if (it == 50) return IntegrationStatus::Failed;
        dp += g / (kE + slope(p0 + dp));
      }
      p = p0 + dp;
      ep = ep0 + sign * dp;
      sxx = trial - sign * kE * dp;
      et = kE * slope(p) / (kE + slope(p));
    }
    out.variables_end[0] = p;
    out.variables_end[1] = ep;
    out.stress = TensorVector::Zero(4);
    out.stress(0) = sxx;
    out.stress(1) = kE * in.strain_end(1);
    out.stress(3) = 0.5 * kE * in.strain_end(3);
    if (out.want_tangent) {
      out.tangent = TangentMatrix::Zero(4, 4);
      out.tangent(0, 0) = et;
      out.tangent(1, 1) = kE;
      out.tangent(3, 3) = 0.5 * kE;
    }
    return IntegrationStatus::Ok;
  }
  static double radius(double p) { return kSy + kQ * (1.0 - std::exp(-kB * p)); }
  static double slope(double p) { return kQ * kB * std::exp(-kB * p); }

 private:
  std::vector<std::string> names_{"EPSPEQ", "EPSPXX"};
};

/// Cumulated plastic strain on the yield surface at stress t (uniaxial, monotonic).
double exact_p(double t) { return t <= kSy ? 0.0 : -std::log(1.0 - (t - kSy) / kQ) / kB; }

/// Newton's asymptotic constant on sigma(eps) = t along the hardening branch, relative residuals:
/// t |sigma''| / (2 sigma'^2), with sigma' = E R' / (E + R') and sigma'' = E^3 R'' / (E + R')^3
/// (d eps = d sigma / E + dp, R'' = -b R').
double rate_constant(double t) {
  const double p = exact_p(t), r1 = HardeningBar::slope(p), r2 = -kB * r1;
  const double s1 = kE * r1 / (kE + r1), s2 = kE * kE * kE * r2 / ((kE + r1) * (kE + r1) * (kE + r1));
  return t * std::abs(s2) / (2.0 * s1 * s1);
}

}  // namespace lunaster::engine::hardening_bar
