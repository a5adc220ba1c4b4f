/// Isotropic hardening curves (isotropic_hardening.hpp).
#include "engine/material/isotropic_hardening.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "engine/core/error.hpp"

namespace lunaster::engine {
namespace {

std::string point(std::size_t i) { return "point " + std::to_string(i + 1); }

/// p_i = eps_i - sigma_i / E, exactly 0 at the first point (where E is its secant).
double plastic_strain(const std::vector<double>& strain, const std::vector<double>& stress, double young,
                      std::size_t i) {
  return i == 0 ? 0.0 : strain[i] - stress[i] / young;
}

}  // namespace

IsotropicHardening IsotropicHardening::linear(double yield, double modulus) {
  if (!(yield > 0.0) || !(modulus >= 0.0) || !std::isfinite(yield) || !std::isfinite(modulus))
    throw InternalError("linear hardening needs a yield stress > 0 and a plastic modulus >= 0");
  IsotropicHardening h;
  h.p_ = {0.0};
  h.radius_ = {yield};
  h.tail_slope_ = modulus;
  return h;
}

IsotropicHardening IsotropicHardening::piecewise(std::vector<double> p, std::vector<double> radius, CurveEnd end) {
  bool ok = p.size() >= 2 && p.size() == radius.size() && p[0] == 0.0 && radius[0] > 0.0;
  for (std::size_t i = 1; ok && i < p.size(); ++i) ok = p[i] > p[i - 1] && radius[i] >= radius[i - 1];
  if (!ok)
    throw InternalError("piecewise hardening needs two points or more from p = 0, p increasing, R > 0 non-decreasing");
  IsotropicHardening h;
  h.p_ = std::move(p);
  h.radius_ = std::move(radius);
  h.excluded_ = end == CurveEnd::Excluded;
  h.tail_slope_ = end == CurveEnd::Constant ? 0.0 : h.segment_slope(static_cast<int>(h.p_.size()) - 2);
  return h;
}

int IsotropicHardening::segment(double p) const {
  const auto after = std::upper_bound(p_.begin(), p_.end(), p);
  return std::max(0, static_cast<int>(after - p_.begin()) - 1);
}

double IsotropicHardening::segment_slope(int k) const {
  if (k + 1 >= static_cast<int>(p_.size())) return tail_slope_;
  return (radius_[k + 1] - radius_[k]) / (p_[k + 1] - p_[k]);
}

double IsotropicHardening::radius(double p) const {
  const int k = segment(p);
  return radius_[k] + segment_slope(k) * (p - p_[k]);
}

double IsotropicHardening::slope(double p) const { return segment_slope(segment(p)); }

// R5.03.02's annex: g(dp) = trial - 3 mu dp - R(p0 + dp) decreases (R non-decreasing), so its root
// is in the first segment whose end leaves g <= 0; on that segment R is linear and the root is
// the closed form of linear hardening with that segment's R_k and slope.
bool IsotropicHardening::return_increment(double trial, double three_mu, double p0, double& dp,
                                          double& slope) const {
  const int n = static_cast<int>(p_.size());
  for (int k = segment(p0);; ++k) {
    const bool tail = k + 1 >= n;
    if (tail && excluded_) return false;
    if (!tail && trial - three_mu * (p_[k + 1] - p0) - radius_[k + 1] > 0.0) continue;
    slope = segment_slope(k);
    dp = (trial - radius_[k] - slope * (p0 - p_[k])) / (three_mu + slope);
    return true;
  }
}

double plastic_modulus(double young, double tangent_modulus) {
  if (!(tangent_modulus >= 0.0 && tangent_modulus < young))
    throw InternalError("plastic modulus: the tangent modulus must be in [0, E)");
  return young * tangent_modulus / (young - tangent_modulus);
}

std::string check_linear_hardening(double young, double tangent_modulus, double yield) {
  if (!(yield > 0.0) || !std::isfinite(yield)) return "the yield stress must be > 0";
  if (!(tangent_modulus >= 0.0)) return "the slope after yield must be >= 0";
  // As code_aster's test, E - E_T below the machine epsilon is refused (then E E_T / (E - E_T)
  // has no meaning); a linear elastic law is the same law with a large yield stress.
  if (!(young - tangent_modulus > 0.0) || young - tangent_modulus <= 1e-15 * young)
    return "the slope after yield must be below Young's modulus " + std::to_string(young) +
           ", got " + std::to_string(tangent_modulus);
  return {};
}

std::string check_traction_curve(const std::vector<double>& strain, const std::vector<double>& stress) {
  if (strain.size() != stress.size()) return "as many strains as stresses are needed";
  if (strain.size() < 2) return "at least two points are needed";
  if (!(strain[0] > 0.0) || !(stress[0] > 0.0))
    return "the first point (the yield point) must have a strain > 0 and a stress > 0";
  const double young = stress[0] / strain[0];
  for (std::size_t i = 1; i < strain.size(); ++i) {
    if (!(strain[i] > strain[i - 1])) return "the strains must increase strictly: " + point(i);
    if (!(stress[i] >= stress[i - 1])) return "the stresses must not decrease: " + point(i);
    if (!(plastic_strain(strain, stress, young, i) > plastic_strain(strain, stress, young, i - 1)))
      return "each segment's slope must be below the first point's secant modulus " + std::to_string(young) +
             ": " + point(i);
  }
  return {};
}

TractionCurve traction_curve(const std::vector<double>& strain, const std::vector<double>& stress, CurveEnd end) {
  const std::string why = check_traction_curve(strain, stress);
  if (!why.empty()) throw InternalError("traction curve: " + why);
  const double young = stress[0] / strain[0];
  std::vector<double> p(strain.size());
  for (std::size_t i = 0; i < strain.size(); ++i) p[i] = plastic_strain(strain, stress, young, i);
  return TractionCurve{young, IsotropicHardening::piecewise(std::move(p), stress, end)};
}

}  // namespace lunaster::engine
