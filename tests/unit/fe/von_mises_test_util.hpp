#pragma once
// The material of the von Mises tests (SSNP159's E, nu, E_T, SY, and a traction curve from the
// same yield point) and the closed form of its monotonic uniaxial curve. The tests are compiled
// several files to a unit: their names live in namespaces of their own.
#include <memory>
#include <vector>

#include "engine/material/isotropic_hardening.hpp"
#include "engine/material/von_mises.hpp"

namespace lunaster::engine::von_mises_test {

// SSNP159's material: E, nu, E_T (D_SIGM_EPSI), SY; H = E E_T / (E - E_T).
constexpr double kE = 200000.0, kNu = 0.3, kEt = 2000.0, kSy = 1000.0;
inline const double kH = kE * kEt / (kE - kEt);
// A traction curve whose first point is SSNP159's yield point (so E = SY / eps_1 = kE), two
// hardening segments, constant past the last point.
inline const std::vector<double> kCurveStrain{0.005, 0.015, 0.035}, kCurveStress{1000.0, 1100.0, 1150.0};

enum class Law { Linear, Curve };

inline std::shared_ptr<VonMises> make_law(Law law) {
  if (law == Law::Linear)
    return std::make_shared<VonMises>(ElasticMaterial{kE, kNu, 0.0}, IsotropicHardening::linear(kSy, kH));
  TractionCurve curve = traction_curve(kCurveStrain, kCurveStress, CurveEnd::Constant);
  return std::make_shared<VonMises>(ElasticMaterial{curve.young, kNu, 0.0}, curve.hardening);
}

/// Uniaxial stress and p on the monotonic curve at axial strain eps.
struct Uniaxial {
  double stress, p;
};
/// The linear law: sigma = SY + E_T (eps - SY / E), p = (sigma - SY) / H past yield. The curve:
/// its broken line (in uniaxial stress eps = sigma / E + p, and p_i = eps_i - sigma_i / E), then
/// constant; p = eps - sigma / E.
inline Uniaxial closed_form(Law law, double eps) {
  if (law == Law::Linear) {
    if (eps <= kSy / kE) return {kE * eps, 0.0};
    const double stress = kSy + kEt * (eps - kSy / kE);
    return {stress, (stress - kSy) / kH};
  }
  double stress = eps < kCurveStrain[0] ? kE * eps : kCurveStress.back();
  for (size_t i = 0; i + 1 < kCurveStrain.size(); ++i)
    if (eps >= kCurveStrain[i] && eps < kCurveStrain[i + 1])
      stress = kCurveStress[i] + (kCurveStress[i + 1] - kCurveStress[i]) * (eps - kCurveStrain[i]) /
                                     (kCurveStrain[i + 1] - kCurveStrain[i]);
  return {stress, eps - stress / kE};
}

}  // namespace lunaster::engine::von_mises_test
