#pragma once
/// Isotropic hardening of a von Mises yield surface: its radius R(p) (the uniaxial yield stress,
/// Pa) as a function of the cumulated plastic strain p, linear or piecewise linear, and the two
/// ways a material gives it: a uniaxial curve's slope after yield, or a uniaxial traction curve.
#include <string>
#include <vector>

namespace lunaster::engine {

/// What a piecewise-linear hardening does past its last point.
enum class CurveEnd {
  Constant,  ///< R stays at its last value (perfect plasticity)
  Linear,    ///< the last segment's slope goes on
  Excluded,  ///< no state exists past the last point (an integration there fails)
};

/// R(p), piecewise linear through points (p_i, R_i) with p_0 = 0, then a straight tail. Immutable.
class IsotropicHardening {
 public:
  /// R(p) = yield + modulus p (yield > 0, modulus >= 0; InternalError otherwise).
  static IsotropicHardening linear(double yield, double modulus);
  /// Through (p_i, R_i): p_0 = 0, p strictly increasing, R_0 > 0 and R non-decreasing (at least
  /// two points; InternalError otherwise); past the last point as `end` says.
  static IsotropicHardening piecewise(std::vector<double> p, std::vector<double> radius, CurveEnd end);

  /// R(0), Pa.
  double yield() const { return radius_[0]; }
  /// R(p), Pa (p >= 0; past an excluded end, the last segment's line).
  double radius(double p) const;
  /// dR/dp at p: the slope of the segment that starts at or before p, Pa.
  double slope(double p) const;
  /// The plastic increment of a radial return from p0 with a trial equivalent stress `trial` >
  /// R(p0): dp > 0 with trial - three_mu dp = R(p0 + dp), exact on each segment (the segment
  /// holding the root is found by walking from p0's); `slope` gets that segment's slope. False
  /// when the root lies past an excluded end.
  bool return_increment(double trial, double three_mu, double p0, double& dp, double& slope) const;

 private:
  IsotropicHardening() = default;
  int segment(double p) const;          ///< index k of the last point with p_k <= p
  double segment_slope(int k) const;    ///< slope from point k to k + 1, or the tail's
  std::vector<double> p_, radius_;
  double tail_slope_ = 0.0;
  bool excluded_ = false;
};

/// Plastic modulus of a linear hardening whose uniaxial curve has slope `tangent_modulus` after
/// yield: E E_T / (E - E_T) (InternalError unless 0 <= E_T < E).
double plastic_modulus(double young, double tangent_modulus);

/// Empty when the uniaxial data (Young's modulus, tangent modulus after yield, yield stress)
/// make a linear hardening; otherwise what is wrong, in words.
std::string check_linear_hardening(double young, double tangent_modulus, double yield);

/// A uniaxial traction curve as a von Mises law reads it: Young's modulus is the first point's
/// secant sigma_1 / eps_1, the first point is the yield point, and each point (eps_i, sigma_i)
/// becomes (p_i = eps_i - sigma_i / E, R_i = sigma_i).
struct TractionCurve {
  double young;                    ///< sigma_1 / eps_1, Pa
  IsotropicHardening hardening;    ///< R(p) through the converted points
};

/// Empty when (strain, stress) is a traction curve TractionCurve accepts: at least two points,
/// the first with eps_1 > 0 and sigma_1 > 0, strains strictly increasing, stresses
/// non-decreasing, each later segment's slope below the first point's secant (so that p grows);
/// otherwise what is wrong, naming the point (1-based).
std::string check_traction_curve(const std::vector<double>& strain, const std::vector<double>& stress);

/// The curve converted (InternalError when check_traction_curve is not empty).
TractionCurve traction_curve(const std::vector<double>& strain, const std::vector<double>& stress, CurveEnd end);

}  // namespace lunaster::engine
