// von Mises plasticity with isotropic hardening (engine/material/von_mises.hpp), linear and from a
// traction curve, at the point (the block of cells: von_mises_block_test.cpp), each value against
// a closed form:
// - the uniaxial stress path (3D, axisymmetric, plane stress) integrated in increments is the
//   uniaxial curve: sigma = SY + E_T (eps - SY / E), p = (sigma - SY) / H for the linear law
//   (code_aster's SSNP159 PETIT: 1570 and 0.28215 at eps = 0.29), the curve itself for the
//   piecewise law (in uniaxial stress eps = sigma / E + p and p_i = eps_i - sigma_i / E, so the
//   path is the curve's broken line);
// - tension and shear along a radial stress path (code_aster's SSNP15A at t = 1), stress-driven by
//   Newton on the law's tangent: p = (q - SY) / H and the strains of the flow rule;
// - the consistent tangent is the central difference of the stress update;
// - unloading keeps p and has Young's slope, and reverse yielding starts at -R(p);
// - the hardening data are refused as the law needs (E_T < E, a curve that does not soften).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "engine/assembly/tangent.hpp"
#include "engine/core/error.hpp"
#include "engine/material/cell_behaviours.hpp"
#include "engine/material/elasticity.hpp"
#include "fe_test_util.hpp"
#include "von_mises_test_util.hpp"

namespace lunaster::engine::von_mises_test::point {

const char* name(Modelisation hyp) {
  switch (hyp) {
    case Modelisation::Solid3D: return "3D";
    case Modelisation::PlaneStrain: return "plane strain";
    case Modelisation::PlaneStress: return "plane stress";
    default: return "axisymmetric";
  }
}

/// One point's committed history, and a step of the law from it.
struct Point {
  Modelisation hyp;
  TensorVector strain, stress;
  double vari[2] = {0.0, 0.0};
  explicit Point(Modelisation h) : hyp(h) {
    strain = TensorVector::Zero(h == Modelisation::Solid3D ? 6 : 4);
    stress = strain;
  }
  /// Integrates to `strain_end`; commits when `commit`.
  PointOutput step(const Behaviour& law, const TensorVector& strain_end, bool commit = true) {
    PointInput in;
    in.hypothesis = hyp;
    in.strain_start = strain;
    in.strain_end = strain_end;
    in.stress_start = stress;
    in.variables_start = vari;
    double end[2] = {-1.0, -1.0};
    PointOutput out;
    out.variables_end = end;
    EXPECT_EQ(law.integrate(in, out), IntegrationStatus::Ok) << name(hyp);
    out.variables_end = nullptr;
    last_vari[0] = end[0];
    last_vari[1] = end[1];
    if (commit) {
      strain = strain_end;
      stress = out.stress;
      vari[0] = end[0];
      vari[1] = end[1];
    }
    return out;
  }
  double last_vari[2] = {0.0, 0.0};
};

/// The strain of uniaxial stress along the axis (x; the axial y in an axisymmetric model), axial
/// eps and lateral `lateral`; plane stress leaves zz at 0 (the law finds it).
TensorVector uniaxial_strain(Modelisation hyp, double eps, double lateral) {
  TensorVector e = TensorVector::Zero(hyp == Modelisation::Solid3D ? 6 : 4);
  e.head<3>().setConstant(lateral);
  e(hyp == Modelisation::Axisymmetric ? 1 : 0) = eps;
  if (hyp == Modelisation::PlaneStress) e(2) = 0.0;
  return e;
}

int axial(Modelisation hyp) { return hyp == Modelisation::Axisymmetric ? 1 : 0; }

void expect_uniaxial(const Point& point, double stress, double p, const char* what) {
  const int a = axial(point.hyp);
  for (int i = 0; i < point.stress.size(); ++i)
    test::expect_close(point.stress(i), i == a ? stress : 0.0, 1e-12, 1e-12 * std::abs(stress),
                       std::string(what) + ", " + name(point.hyp) + ", stress " + std::to_string(i));
  test::expect_close(point.vari[0], p, 1e-12, 1e-16, std::string(what) + ", " + name(point.hyp) + ", p");
}

const Modelisation kUniaxialHypotheses[] = {Modelisation::Solid3D, Modelisation::Axisymmetric,
                                            Modelisation::PlaneStress};

TEST(VonMises, UniaxialPathInIncrementsIsTheClosedForm) {
  // 23 increments to eps = 0.04: the yield point and both curve points are crossed inside a step;
  // then the same end in one step (the curve's search walks every segment at once).
  for (Law law : {Law::Linear, Law::Curve})
    for (Modelisation hyp : kUniaxialHypotheses)
      for (int n_steps : {23, 1}) {
        const auto vm = make_law(law);
        Point point(hyp);
        for (int k = 1; k <= n_steps; ++k) {
          const double eps = 0.04 * k / n_steps;
          const Uniaxial exact = closed_form(law, eps);
          const double p_before = point.vari[0];
          point.step(*vm, uniaxial_strain(hyp, eps, -kNu * exact.stress / kE - exact.p / 2.0));
          expect_uniaxial(point, exact.stress, exact.p, law == Law::Linear ? "linear" : "curve");
          EXPECT_EQ(point.vari[1], exact.p > p_before ? 1.0 : 0.0) << "INDIPLAS at eps = " << eps;
        }
      }
  // SSNP159 (PETIT): 29 % in one step gives sigma = 1570 and p = 0.28215.
  const auto vm = make_law(Law::Linear);
  Point point(Modelisation::Solid3D);
  point.step(*vm, uniaxial_strain(Modelisation::Solid3D, 0.29, -kNu * 1570.0 / kE - 0.28215 / 2.0));
  expect_uniaxial(point, 1570.0, 0.28215, "SSNP159");
}

TEST(VonMises, UnloadingKeepsPAndHasYoungsSlopeThenReverseYieldIsAtMinusR) {
  for (Law law : {Law::Linear, Law::Curve})
    for (Modelisation hyp : kUniaxialHypotheses) {
      const auto vm = make_law(law);
      Point point(hyp);
      const double eps_max = 0.02;
      const Uniaxial top = closed_form(law, eps_max);
      const double lateral_top = -kNu * top.stress / kE - top.p / 2.0;
      point.step(*vm, uniaxial_strain(hyp, eps_max, lateral_top));
      ASSERT_EQ(point.vari[1], 1.0);
      const double p_loaded = point.vari[0];
      // Elastic unloading by 0.003: sigma drops by E 0.003 (the lateral strain by nu times less).
      const double d_eps = -0.003, stress = top.stress + kE * d_eps;
      const PointOutput out = point.step(*vm, uniaxial_strain(hyp, eps_max + d_eps, lateral_top - kNu * d_eps));
      expect_uniaxial(point, stress, top.p, "unloading");
      EXPECT_EQ(point.vari[0], p_loaded) << "p is kept exactly";
      EXPECT_EQ(point.vari[1], 0.0);
      // The tangent of an elastic step is the linear law's.
      Point elastic(hyp);
      const PointOutput linear = elastic.step(Elasticity(ElasticMaterial{kE, kNu, 0.0}), point.strain, false);
      EXPECT_LE((out.tangent - linear.tangent).cwiseAbs().maxCoeff(), 1e-12 * kE) << name(hyp);
      // Compression past -R(p_top) (isotropic hardening): the axial plastic strain eps_p_top - dp
      // (eps_p_top = p_top after the monotonic loading), sigma = -R(p_top + dp), eps = sigma / E +
      // eps_p. For the linear law at eps = 0: dp = (eps_p_top - eps - R(p_top) / E) / (1 + H / E).
      if (law != Law::Linear) continue;
      const double eps = eps_max - 0.02, eps_p_top = eps_max - top.stress / kE;
      const double dp = (eps_p_top - eps - top.stress / kE) / (1.0 + kH / kE);
      const double reverse = -(top.stress + kH * dp);
      point.step(*vm, uniaxial_strain(hyp, eps, -kNu * reverse / kE - (top.p - dp) / 2.0));
      expect_uniaxial(point, reverse, top.p + dp, "reverse yield");
      EXPECT_EQ(point.vari[1], 1.0);
    }
}

/// Drives `point` to the stress `target` by Newton on the strain with the law's tangent, and
/// commits; returns the relative residuals |sigma - target| / scale of the iterations.
std::vector<double> drive_to_stress(const Behaviour& law, Point& point, const TensorVector& target, double scale) {
  TensorVector strain = point.strain;
  std::vector<double> residuals;
  for (int it = 0; it < 30; ++it) {
    const PointOutput out = point.step(law, strain, false);
    const TensorVector r = out.stress - target;
    residuals.push_back(r.norm() / scale);
    if (residuals.back() < 1e-13) {
      point.step(law, strain);
      return residuals;
    }
    strain -= Eigen::MatrixXd(out.tangent).lu().solve(Eigen::VectorXd(r));
  }
  ADD_FAILURE() << "no convergence to the stress asked";
  return residuals;
}

TEST(VonMises, RadialTensionShearIsSsnp15sClosedForm) {
  // code_aster's SSNP15A at t = 1 (E = 195000, NU = 0.3, E_T = 1930, SY = 181): tension 151.2 and
  // shear 93.1 applied radially (here in 10 stress increments, the first yield inside the 9th).
  // On a radial path the flow direction is fixed, so the backward Euler return is exact: p =
  // (q - SY) / H with q = sqrt(s^2 + 3 t^2), eps_xx = s / E + p s / q, eps_yy = eps_zz = -NU s / E -
  // p s / (2 q), eps_xy = t / (2 G) + 1.5 p t / q (SSNP15's 0.0205473, 0.0148297, 0.0136014).
  // Then unloaded to zero stress: elastic (one Newton iteration), p kept, the strain is the
  // plastic strain p s / q, 3 p t / q (engineering shear).
  const double e = 195000.0, nu = 0.3, et = 1930.0, sy = 181.0, sxx = 151.2, sxy = 93.1;
  const double h = plastic_modulus(e, et), g = e / (2.0 * (1.0 + nu));
  const VonMises law(ElasticMaterial{e, nu, 0.0}, IsotropicHardening::linear(sy, h));
  const double q = std::sqrt(sxx * sxx + 3.0 * sxy * sxy), p = (q - sy) / h;
  const double exx = sxx / e + p * sxx / q, eyy = -nu * sxx / e - 0.5 * p * sxx / q;
  const double exy = sxy / (2.0 * g) + 1.5 * p * sxy / q;
  test::expect_close(p, 0.0205473, 5e-6, 0.0, "SSNP15A p");  // the printed digits
  test::expect_close(exx, 0.0148297, 5e-6, 0.0, "SSNP15A EPXX");
  test::expect_close(exy, 0.0136014, 5e-6, 0.0, "SSNP15A EPXY");
  Point point(Modelisation::Solid3D);
  TensorVector target = TensorVector::Zero(6);
  for (int k = 1; k <= 10; ++k) {
    target(0) = sxx * k / 10.0;
    target(3) = sxy * k / 10.0;
    drive_to_stress(law, point, target, sy);
  }
  EXPECT_EQ(point.vari[1], 1.0);
  test::expect_close(point.vari[0], p, 1e-10, 0.0, "p");
  const double expected[6] = {exx, eyy, eyy, 2.0 * exy, 0.0, 0.0};
  for (int i = 0; i < 6; ++i)
    test::expect_close(point.strain(i), expected[i], 1e-10, 1e-14, "strain " + std::to_string(i));
  const std::vector<double> unload = drive_to_stress(law, point, TensorVector::Zero(6), sy);
  EXPECT_EQ(unload.size(), 2u) << "an elastic unloading is one linear solve";
  EXPECT_EQ(point.vari[1], 0.0);
  test::expect_close(point.vari[0], p, 1e-10, 0.0, "p after unloading");
  const double plastic[6] = {p * sxx / q, -0.5 * p * sxx / q, -0.5 * p * sxx / q, 3.0 * p * sxy / q, 0.0, 0.0};
  for (int i = 0; i < 6; ++i)
    test::expect_close(point.strain(i), plastic[i], 1e-10, 1e-14, "plastic strain " + std::to_string(i));
}

/// Central differences of the stress at the end of one step from `point`, per strain component.
TangentMatrix finite_difference(const Behaviour& law, Point point, const TensorVector& strain_end, double h) {
  const int n = static_cast<int>(strain_end.size());
  TangentMatrix d = TangentMatrix::Zero(n, n);
  for (int j = 0; j < n; ++j) {
    TensorVector plus = strain_end, minus = strain_end;
    plus(j) += h;
    minus(j) -= h;
    d.col(j) = (point.step(law, plus, false).stress - point.step(law, minus, false).stress) / (2.0 * h);
  }
  return d;
}

TEST(VonMises, ConsistentTangentIsTheCentralDifferenceOfTheStressUpdate) {
  // From a plastic state reached along `a`, steps along the different direction `b` (plastic,
  // the return's direction turning: the tangent's n(x)n and theta terms are all exercised), back
  // along -a (unloading: elastic) and from zero a small step (elastic). h = 1e-7: the central
  // difference's truncation (h^2 sigma''' / 6, sigma''' ~ E / eps^2 with eps ~ 1e-2) and its
  // round-off (1e-16 sigma / h) are both below 1e-9 of E: the tangent is held to 1e-8 of its
  // largest entry. In plane stress the local iteration may stop at 1e-12 of sigma on sigma_zz,
  // which allows 1e-12 sigma / h = 5e-8 E: that tangent is held to 1e-6.
  const double a[6] = {1.0, -0.4, 0.15, 0.3, -0.2, 0.1}, b[6] = {0.3, 0.8, -0.5, -0.4, 0.6, 0.2};
  const double scale = kSy / kE;
  for (Law law : {Law::Linear, Law::Curve})
    for (Modelisation hyp : {Modelisation::Solid3D, Modelisation::PlaneStrain, Modelisation::Axisymmetric,
                             Modelisation::PlaneStress}) {
      const auto vm = make_law(law);
      const int n = hyp == Modelisation::Solid3D ? 6 : 4;
      TensorVector along_a(n), along_b(n);
      for (int i = 0; i < n; ++i) {
        along_a(i) = a[i];
        along_b(i) = b[i];
      }
      if (hyp == Modelisation::PlaneStress) along_a(2) = along_b(2) = 0.0;
      Point loaded(hyp);
      loaded.step(*vm, 4.0 * scale * along_a);
      ASSERT_EQ(loaded.vari[1], 1.0) << name(hyp);
      struct Case {
        const char* what;
        Point start;
        TensorVector strain_end;
        double plastic;
      };
      const Case cases[] = {{"elastic", Point(hyp), 0.3 * scale * along_a, 0.0},
                            {"plastic", loaded, loaded.strain + 2.0 * scale * along_b, 1.0},
                            {"unloading", loaded, loaded.strain - 0.5 * scale * along_a, 0.0}};
      for (const Case& c : cases) {
        Point start = c.start;
        const PointOutput out = start.step(*vm, c.strain_end, false);
        const std::string what = std::string(c.what) + ", " + name(hyp) + (law == Law::Linear ? ", linear" : ", curve");
        ASSERT_EQ(start.last_vari[1], c.plastic) << what;
        // The curve's kinks: p at the step's end is away from its points (the tangent is one-sided there).
        if (c.plastic == 1.0) {
          for (double node : {0.0, 0.015 - 1100.0 / kE, 0.035 - 1150.0 / kE})
            EXPECT_GT(std::abs(start.last_vari[0] - node), 1e-4) << what;
        }
        const TangentMatrix fd = finite_difference(*vm, c.start, c.strain_end, 1e-7);
        const double error = (fd - out.tangent).cwiseAbs().maxCoeff(), size = out.tangent.cwiseAbs().maxCoeff();
        std::printf("  %-36s |D_fd - D| / |D| = %.2e\n", what.c_str(), error / size);
        EXPECT_LE(error, (hyp == Modelisation::PlaneStress ? 1e-6 : 1e-8) * size) << what;
        EXPECT_LE((out.tangent - out.tangent.transpose()).cwiseAbs().maxCoeff(), 1e-12 * size) << what << ": symmetric";
      }
    }
}

TEST(VonMises, HardeningDataAreCheckedAsTheLawNeedsThem) {
  EXPECT_EQ(check_linear_hardening(kE, kEt, kSy), "");
  EXPECT_EQ(check_linear_hardening(kE, 0.0, kSy), "");  // perfect plasticity
  EXPECT_NE(check_linear_hardening(kE, kE, kSy), "");
  EXPECT_NE(check_linear_hardening(kE, 2.0 * kE, kSy), "");
  EXPECT_NE(check_linear_hardening(kE, kEt, 0.0), "");
  EXPECT_EQ(check_traction_curve(kCurveStrain, kCurveStress), "");
  EXPECT_NE(check_traction_curve({0.005}, {1000.0}), "");
  EXPECT_NE(check_traction_curve({0.005, 0.004}, {1000.0, 1100.0}), "");  // strains decrease
  EXPECT_NE(check_traction_curve({0.005, 0.01}, {1000.0, 900.0}), "");   // stresses decrease
  EXPECT_NE(check_traction_curve({0.005, 0.01}, {1000.0, 2000.0}), "");  // slope E: p would not grow
  EXPECT_THROW(traction_curve({0.005, 0.01}, {1000.0, 900.0}, CurveEnd::Constant), InternalError);
  // Past an excluded end no state exists: the integration fails (a step to subdivide).
  const TractionCurve curve = traction_curve(kCurveStrain, kCurveStress, CurveEnd::Excluded);
  const VonMises vm(ElasticMaterial{curve.young, kNu, 0.0}, curve.hardening);
  Point point(Modelisation::Solid3D);
  point.step(vm, uniaxial_strain(Modelisation::Solid3D, 0.03, 0.0));
  PointInput in;
  in.hypothesis = Modelisation::Solid3D;
  in.strain_start = point.strain;
  in.strain_end = uniaxial_strain(Modelisation::Solid3D, 0.1, 0.0);  // p about 2/3 of it: past the curve
  in.stress_start = point.stress;
  in.variables_start = point.vari;
  double end[2];
  PointOutput out;
  out.variables_end = end;
  EXPECT_EQ(vm.integrate(in, out), IntegrationStatus::Failed);
  // Linear extension past the last point: the last slope goes on.
  const TractionCurve linear = traction_curve(kCurveStrain, kCurveStress, CurveEnd::Linear);
  const double p_last = 0.035 - 1150.0 / kE, slope = 50.0 / (0.02 - 50.0 / kE);
  test::expect_close(linear.hardening.radius(p_last + 0.1), 1150.0 + slope * 0.1, 1e-14, 0.0, "linear extension");
  test::expect_close(curve.hardening.radius(p_last), 1150.0, 1e-14, 0.0, "last point");
}

TEST(VonMises, APlaneStressIterationThatDoesNotConvergeFailsTheStep) {
  // The elastic guess of the zz strain is exact in an elastic step: one evaluation suffices. A
  // plastic step needs Newton iterations: allowed one evaluation, it fails (a step to subdivide);
  // by default it converges.
  const VonMises one(ElasticMaterial{kE, kNu, 0.0}, IsotropicHardening::linear(kSy, kH), PlaneStressIteration{1e-12, 1});
  const auto usual = make_law(Law::Linear);
  auto integrate = [](const VonMises& law, double eps) {
    PointInput in;
    in.hypothesis = Modelisation::PlaneStress;
    in.strain_start = in.stress_start = TensorVector::Zero(4);
    in.strain_end = uniaxial_strain(Modelisation::PlaneStress, eps, -kNu * eps);
    const double start[2] = {0.0, 0.0};
    double end[2];
    in.variables_start = start;
    PointOutput out;
    out.variables_end = end;
    return law.integrate(in, out);
  };
  EXPECT_EQ(integrate(one, 0.5 * kSy / kE), IntegrationStatus::Ok);
  EXPECT_EQ(integrate(one, 3.0 * kSy / kE), IntegrationStatus::Failed);
  EXPECT_EQ(integrate(*usual, 3.0 * kSy / kE), IntegrationStatus::Ok);
}

}  // namespace lunaster::engine::von_mises_test::point
