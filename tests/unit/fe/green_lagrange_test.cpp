// Large rotations (the total Lagrangian kinematics) on blocks of cells, each against a closed
// form, solved by a Newton loop that sees only assembly's Tangent:
// - a rigid rotation to 90 degrees, imposed on one face in steps, leaves no strain, no stress and
//   no internal force (to round-off), where small strain finds a stress of the order of E;
// - a stretch s under a dead load in uniaxial strain (SSNV121's: s = 1.1, E = 200000, nu = 0.3),
//   also after a 90-degree rotation: the Green-Lagrange strain E = (s^2 - 1) / 2 along the
//   stretch, the Cauchy stress s (lambda + 2 mu) E along it and lambda E / s across, reached at
//   Newton's quadratic rate, whose constant is the scalar problem's;
// - the tangent (material and geometric parts) is the derivative of the internal force, by
//   central differences at a strained and rotated state, elastic and von Mises plastic;
// - an axisymmetric ring stretched radially (the hoop stretch u_r / R) gives its closed form.
// Uniform strains are linear fields, which isoparametric cells hold exactly, and uniform
// stresses are balanced exactly by their nodal forces: the discrete solutions are the closed
// forms, to the Newton tolerance.
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "engine/assembly/point_fields.hpp"
#include "engine/assembly/tangent.hpp"
#include "engine/material/cell_behaviours.hpp"
#include "fe_test_util.hpp"
#include "newton_test_util.hpp"
#include "von_mises_test_util.hpp"

namespace lunaster::engine::green_lagrange_test {

constexpr double kE = 200000.0, kNu = 0.3, kPi = 3.14159265358979323846;
const double kLambda = kE * kNu / ((1.0 + kNu) * (1.0 - 2.0 * kNu)), kMu = kE / (2.0 * (1.0 + kNu));

struct Case {
  const char* what;
  CellType type;
  Modelisation hyp;
};
/// GoogleTest prints a case by its name.
void PrintTo(const Case& c, std::ostream* os) { *os << c.what; }

std::string case_name(const char* what) {
  std::string n = what;
  for (char& ch : n)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return n;
}

/// Rotation of `angle` about the unit vector `axis` (Rodrigues).
Eigen::Matrix3d rotation(const Eigen::Vector3d& axis, double angle) {
  Eigen::Matrix3d k;
  k << 0.0, -axis(2), axis(1), axis(2), 0.0, -axis(0), -axis(1), axis(0), 0.0;
  return Eigen::Matrix3d::Identity() + std::sin(angle) * k + (1.0 - std::cos(angle)) * k * k;
}

/// The rotation axis of a case: oblique in 3D (every component of F), z in 2D.
Eigen::Vector3d rotation_axis(int dim) {
  return dim == 3 ? Eigen::Vector3d(Eigen::Vector3d(1.0, 2.0, 2.0) / 3.0) : Eigen::Vector3d(Eigen::Vector3d::UnitZ());
}

/// A block [0,1]^dim of cells (interior nodes distorted) of one material (E, nu), every volume
/// cell under `kinematics`, following `law` (the material's elasticity when null: under the total
/// Lagrangian kinematics, Saint-Venant-Kirchhoff). `shift` moves the block along x (an
/// axisymmetric block away from the axis).
struct Block {
  Case c;
  test::BlockBuilder builder;
  FeModel model;
  std::unique_ptr<DofMap> dofs;
  std::unique_ptr<CellBehaviours> behaviours;
  int dim;

  explicit Block(const Case& bc, Kinematics kinematics = Kinematics::TotalLagrangian,
                 std::shared_ptr<const Behaviour> law = nullptr, double shift = 0.0)
      : c(bc), builder(bc.type, 2, 0.3), dim(cell_dim(bc.type)) {
    builder.fill();
    for (int v = 0; v < builder.mesh().n_nodes(); ++v) builder.mesh().coords[3 * static_cast<size_t>(v)] += shift;
    model = test::make_model(builder.mesh(), dim, c.hyp, ElasticMaterial{kE, kNu, 0.0});
    dofs = std::make_unique<DofMap>(builder.mesh(), model.volume_cells(), dim);
    behaviours = std::make_unique<CellBehaviours>(model);
    if (law) behaviours->assign(model.volume_cells(), std::move(law));
    behaviours->set_kinematics(model.volume_cells(), kinematics);
  }
  const Mesh& mesh() const { return const_cast<test::BlockBuilder&>(builder).mesh(); }
  Eigen::Vector3d node(int v) const { return Eigen::Vector3d(mesh().node(v)[0], mesh().node(v)[1], mesh().node(v)[2]); }
  /// The displacement that takes every node X to motion(X).
  Vector displacement(const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& motion) const {
    Vector u = Vector::Zero(dofs->n_dofs());
    for (int v = 0; v < mesh().n_nodes(); ++v) {
      const Eigen::Vector3d x = motion(node(v)) - node(v);
      for (int k = 0; k < dim; ++k) u(dofs->dof(v, k)) = x(k);
    }
    return u;
  }
};

/// Turns the block rigidly to `angle` about `axis` in `steps` equal steps, the face x = 0 held at
/// each step's rotated position and the rest found by Newton from the last step's state (no
/// line search: 5-degree steps keep the quadratic cells within its reach, 15 degrees do not) (tolerance `tolerance` of E times a
/// unit area); `u` from its rest to the rotated displacement, each step committed. `check` runs
/// after each step with its rotation.
void rotate(Block& block, Tangent& tangent, Vector& u, const Eigen::Vector3d& axis, double angle, int steps,
            double tolerance, const std::function<void(const Eigen::Matrix3d&)>& check = {}) {
  std::vector<char> fixed(block.dofs->n_dofs(), 0);
  for (int v = 0; v < block.mesh().n_nodes(); ++v)
    if (block.node(v)(0) == 0.0)
      for (int k = 0; k < block.dim; ++k) fixed[block.dofs->dof(v, k)] = 1;
  const std::vector<int> free = test::free_equations(fixed);
  const Vector no_load = Vector::Zero(block.dofs->n_dofs());
  for (int step = 1; step <= steps; ++step) {
    const Eigen::Matrix3d r = rotation(axis, angle * step / steps);
    const Vector rigid = block.displacement([&](const Eigen::Vector3d& x) { return Eigen::Vector3d(r * x); });
    for (int eq = 0; eq < block.dofs->n_dofs(); ++eq)
      if (fixed[eq]) u(eq) = rigid(eq);
    std::printf("  %s, rotation %g degrees\n", block.c.what, angle * step / steps * 180.0 / kPi);
    const test::NewtonLog log = test::newton_step(tangent, free, no_load, kE, u, tolerance);
    ASSERT_TRUE(log.converged) << block.c.what << ": step " << step;
    if (check) check(r);
    tangent.commit();
  }
}

class RigidRotation : public ::testing::TestWithParam<Case> {};

TEST_P(RigidRotation, LeavesNoStressNorForceWhereSmallStrainFindsOne) {
  Block block(GetParam());
  Tangent tangent(*block.behaviours, *block.dofs);
  EXPECT_FALSE(tangent.constant()) << "the tangent of large rotations depends on u";
  Vector u = Vector::Zero(block.dofs->n_dofs());
  const Eigen::Vector3d axis = rotation_axis(block.dim);
  // Round-off: F's entries are of order 1, so E = (F^T F - I) / 2 is zero to a few 1e-16 and S to
  // a few 1e-16 E (about 1e-15 E measured). Newton stops below 1e-13 of E times a unit area, its
  // quadratic rate taking the last residual to round-off. Stresses and forces are held to 1e-12 E
  // (a unit area), and the displacement to 1e-12 of the block's size.
  const double zero = 1e-12 * kE;
  rotate(block, tangent, u, axis, kPi / 2.0, 18, 1e-13, [&](const Eigen::Matrix3d& r) {
    const Vector rigid = block.displacement([&](const Eigen::Vector3d& x) { return Eigen::Vector3d(r * x); });
    EXPECT_LE((u - rigid).lpNorm<Eigen::Infinity>(), 1e-12) << block.c.what << ": the motion is the rotation";
    double largest = 0.0;
    for (int cell : block.model.volume_cells())
      for (int q = 0; q < tangent.states().n_points(cell); ++q)
        for (int i = 0; i < tangent.states().tensor_size(); ++i)
          largest = std::max(largest, std::abs(tangent.states().stress(MaterialStates::Slot::End, cell, q)[i]));
    EXPECT_LE(largest, zero) << block.c.what << ": stress of a rigid rotation";
    Vector f_int;
    ASSERT_TRUE(tangent.assemble(u, nullptr, &f_int));
    EXPECT_LE(f_int.lpNorm<Eigen::Infinity>(), zero) << block.c.what << ": internal force of a rigid rotation";
    std::printf("    largest |S| = %.3g, largest |f_int| = %.3g\n", largest, f_int.lpNorm<Eigen::Infinity>());
  });
  // Small strain at the same displacement: eps = sym(R) - I (uniform), sigma = lambda tr(eps) I +
  // 2 mu eps, at 90 degrees of the order of E (about z: eps_xx = eps_yy = -1).
  Block small(GetParam(), Kinematics::SmallStrain);
  Tangent linear(*small.behaviours, *small.dofs);
  EXPECT_TRUE(linear.constant());
  Vector f_int;
  ASSERT_TRUE(linear.assemble(u, nullptr, &f_int));
  const Eigen::Matrix3d r = rotation(axis, kPi / 2.0);
  Eigen::Matrix3d eps = 0.5 * (r + r.transpose()) - Eigen::Matrix3d::Identity();
  if (block.dim == 2) eps.row(2).setZero(), eps.col(2).setZero();
  const Eigen::Matrix3d sigma = kLambda * eps.trace() * Eigen::Matrix3d::Identity() + 2.0 * kMu * eps;
  const std::vector<double> expected = block.dim == 3 ? std::vector<double>{sigma(0, 0), sigma(1, 1), sigma(2, 2),
                                                                            sigma(0, 1), sigma(0, 2), sigma(1, 2)}
                                                      : std::vector<double>{sigma(0, 0), sigma(1, 1), sigma(2, 2), sigma(0, 1)};
  std::printf("  small strain at 90 degrees: sigma_xx = %.6g (-2 (lambda + mu) about z = %.6g)\n", sigma(0, 0),
              -2.0 * (kLambda + kMu));
  for (int cell : small.model.volume_cells())
    for (int q = 0; q < linear.states().n_points(cell); ++q)
      for (int i = 0; i < linear.states().tensor_size(); ++i)
        test::expect_close(linear.states().stress(MaterialStates::Slot::End, cell, q)[i], expected[i], 1e-10, 1e-10 * kE,
                           std::string(block.c.what) + ": small-strain stress of the rotation");
}

INSTANTIATE_TEST_SUITE_P(Cases, RigidRotation,
                         ::testing::Values(Case{"HEXA8 3D", CellType::Hexa8, Modelisation::Solid3D},
                                           Case{"HEXA20 3D", CellType::Hexa20, Modelisation::Solid3D},
                                           Case{"QUAD4 plane strain", CellType::Quad4, Modelisation::PlaneStrain},
                                           Case{"TRIA6 plane strain", CellType::Tria6, Modelisation::PlaneStrain}),
                         [](const ::testing::TestParamInfo<Case>& info) { return case_name(info.param.what); });

struct StretchCase {
  const char* what;
  CellType type;
  Modelisation hyp;
  bool rotated;   ///< first turned by 90 degrees about z
  double stretch; ///< s along the block's y axis
};
void PrintTo(const StretchCase& c, std::ostream* os) { *os << c.what; }

/// The first Piola-Kirchhoff stress of a uniaxial strain stretch s of Saint-Venant-Kirchhoff's
/// material: P(s) = s S = s (lambda + 2 mu) (s^2 - 1) / 2, the dead load per unit initial area.
double nominal_stress(double s) { return s * (kLambda + 2.0 * kMu) * 0.5 * (s * s - 1.0); }

/// Newton's constant on P(s) = P* with residuals relative to P*: r_{k+1} ~ C r_k^2,
/// C = P* |P''| / (2 P'^2) = 3 s^2 (s^2 - 1) / (3 s^2 - 1)^2 (P' = (lambda + 2 mu) (3 s^2 - 1) / 2,
/// P'' = 3 (lambda + 2 mu) s).
double rate_constant(double s) { return 3.0 * s * s * (s * s - 1.0) / ((3.0 * s * s - 1.0) * (3.0 * s * s - 1.0)); }

class UniaxialStretch : public ::testing::TestWithParam<StretchCase> {};

TEST_P(UniaxialStretch, DeadLoadGivesTheClosedFormCauchyStressAtNewtonsQuadraticRate) {
  const StretchCase& sc = GetParam();
  Block block(Case{sc.what, sc.type, sc.hyp});
  const int dim = block.dim;
  Tangent tangent(*block.behaviours, *block.dofs);
  Vector u = Vector::Zero(block.dofs->n_dofs());
  Eigen::Matrix3d r = Eigen::Matrix3d::Identity();
  if (sc.rotated) {
    rotate(block, tangent, u, Eigen::Vector3d::UnitZ(), kPi / 2.0, 6, 1e-13);
    r = rotation(Eigen::Vector3d::UnitZ(), kPi / 2.0);
  }
  // The block's axes m turned: R e_m = +-e_{axis[m]} (exact at 90 degrees about z). Each face
  // x_m = 0 or 1 (m lateral) is held along R e_m, the face y = 0 along R e_y, all at the values of
  // the rotated rest state; the face y = 1 carries the dead load P along R e_y.
  int axis[3];
  double sign[3];
  for (int m = 0; m < 3; ++m) {
    const Eigen::Vector3d turned = r * Eigen::Vector3d::Unit(m);
    turned.cwiseAbs().maxCoeff(&axis[m]);
    sign[m] = turned(axis[m]) > 0 ? 1.0 : -1.0;
  }
  const double s = sc.stretch, p = nominal_stress(s);
  std::vector<char> fixed(block.dofs->n_dofs(), 0);
  Vector f_ext = Vector::Zero(block.dofs->n_dofs());
  const int n = 2;  // cells per side: the face y = 1's nodes carry 1/n (or 1/(2n) on its edges) per direction
  for (int v = 0; v < block.mesh().n_nodes(); ++v) {
    const Eigen::Vector3d x = block.node(v);
    for (int m = 0; m < dim; ++m)
      if (m != 1 && (x(m) == 0.0 || x(m) == 1.0)) fixed[block.dofs->dof(v, axis[m])] = 1;
    if (x(1) == 0.0) fixed[block.dofs->dof(v, axis[1])] = 1;
    if (x(1) == 1.0) {
      double area = 1.0;
      for (int m = 0; m < dim; ++m)
        if (m != 1) area *= (x(m) == 0.0 || x(m) == 1.0) ? 0.5 / n : 1.0 / n;
      f_ext(block.dofs->dof(v, axis[1])) += sign[1] * p * area;
    }
  }
  std::printf("  %s, stretch %g under P = %.8g\n", sc.what, s, p);
  const test::NewtonLog log = test::newton_step(tangent, test::free_equations(fixed), f_ext, f_ext.norm(), u);
  ASSERT_TRUE(log.converged);
  tangent.commit();

  // x = R diag(1, s, 1) X.
  const Eigen::Matrix3d stretch = Eigen::Vector3d(1.0, s, 1.0).asDiagonal();
  const Vector exact = block.displacement([&](const Eigen::Vector3d& x) { return Eigen::Vector3d(r * stretch * x); });
  EXPECT_LE((u - exact).lpNorm<Eigen::Infinity>(), 1e-10 * (s - 1.0)) << "displacement";
  // The states: E along the block's y axis (the initial configuration's frame, whatever the
  // rotation), S = lambda tr E I + 2 mu E.
  const double green = 0.5 * (s * s - 1.0);
  const int nt = tangent.states().tensor_size();
  for (int cell : block.model.volume_cells())
    for (int q = 0; q < tangent.states().n_points(cell); ++q)
      for (int i = 0; i < nt; ++i) {
        test::expect_close(tangent.states().strain(MaterialStates::Slot::End, cell, q)[i], i == 1 ? green : 0.0, 1e-10,
                           1e-12, "Green-Lagrange strain");
        const double pk2 = i == 1 ? (kLambda + 2.0 * kMu) * green : (i < 3 ? kLambda * green : 0.0);
        test::expect_close(tangent.states().stress(MaterialStates::Slot::End, cell, q)[i], pk2, 1e-10, 1e-10 * p,
                           "second Piola-Kirchhoff stress");
      }
  // Cauchy: s (lambda + 2 mu) E along R e_y, lambda E / s across (J = s, the lateral F = 1).
  const double axial = s * (kLambda + 2.0 * kMu) * green, lateral = kLambda * green / s;
  if (s == 1.1) {  // SSNV121's values, to their printed digits
    EXPECT_NEAR(axial, 31096.154, 5e-4);
    EXPECT_NEAR(lateral, 11013.986, 5e-4);
    EXPECT_NEAR(green, 0.105, 1e-15);
  }
  const Eigen::Matrix3d sigma = r * Eigen::Vector3d(lateral, axial, lateral).asDiagonal() * r.transpose();
  const ElgaField cauchy = stresses_at_points(*block.behaviours, *block.dofs, u, tangent.states());
  const int nc = cauchy.n_components();
  const std::vector<double> expected = dim == 3 ? std::vector<double>{sigma(0, 0), sigma(1, 1), sigma(2, 2),
                                                                      sigma(0, 1), sigma(0, 2), sigma(1, 2)}
                                                : std::vector<double>{sigma(0, 0), sigma(1, 1), sigma(2, 2), sigma(0, 1)};
  ASSERT_EQ(nc, static_cast<int>(expected.size()));
  for (int cell : block.model.volume_cells())
    for (int q = cauchy.cell_offsets[cell]; q < cauchy.cell_offsets[cell + 1]; ++q)
      for (int i = 0; i < nc; ++i)
        test::expect_close(cauchy.values[static_cast<size_t>(q) * nc + i], expected[i], 1e-10, 1e-10 * axial,
                           std::string(sc.what) + ": Cauchy stress " + cauchy.components[i]);
  std::printf("  Cauchy along the stretch %.8g, across %.8g\n", axial, lateral);

  // Quadratic rate: the iterates stay uniform stretches (a uniform start, a uniform load, a
  // uniform tangent), so this is Newton on P(s) = P*, the residual |P(s_k) - P*| / P* (the
  // load's distribution over the nodes is the internal force's). Every iteration with r_k below
  // 1e-2 (near enough for the asymptote) and r_{k+1} above round-off (1e-11) is held to 2 C, the
  // last to C within 5 %; a linear rate would give ratios growing as 1 / r_k.
  const double c = rate_constant(s);
  int rated = 0;
  double last = 0.0;
  for (size_t k = 0; k + 1 < log.residuals.size(); ++k) {
    if (log.residuals[k] > 1e-2 || log.residuals[k + 1] < 1e-11) continue;
    last = log.residuals[k + 1] / (log.residuals[k] * log.residuals[k]);
    std::printf("    r_k+1 / r_k^2 = %.4g (C = %.4g)\n", last, c);
    EXPECT_LE(last, 2.0 * c);
    ++rated;
  }
  ASSERT_GE(rated, 1) << "no iteration to rate";
  EXPECT_NEAR(last, c, 0.05 * c) << "the asymptotic rate";
}

INSTANTIATE_TEST_SUITE_P(
    Cases, UniaxialStretch,
    ::testing::Values(StretchCase{"HEXA8 3D", CellType::Hexa8, Modelisation::Solid3D, false, 1.1},
                      StretchCase{"HEXA8 3D rotated", CellType::Hexa8, Modelisation::Solid3D, true, 1.1},
                      StretchCase{"QUAD4 plane strain", CellType::Quad4, Modelisation::PlaneStrain, false, 1.1},
                      StretchCase{"QUAD4 plane strain rotated", CellType::Quad4, Modelisation::PlaneStrain, true, 1.1},
                      StretchCase{"HEXA8 3D rotated to 1.3", CellType::Hexa8, Modelisation::Solid3D, true, 1.3}),
    [](const ::testing::TestParamInfo<StretchCase>& info) { return case_name(info.param.what); });

struct TangentCase {
  const char* what;
  CellType type;
  Modelisation hyp;
  bool plastic;  ///< von Mises (SSNP159's linear hardening) loaded past yield, else elastic
};
void PrintTo(const TangentCase& c, std::ostream* os) { *os << c.what; }

class TangentByDifferences : public ::testing::TestWithParam<TangentCase> {};

/// A strained and rotated state: X -> R (X + t (A X + Q(X))), A a uniform strain of a few
/// percent, Q a quadratic field (non-uniform strains), R a large rotation (70 degrees; 0.3 rad in
/// the axisymmetric plane, whose hoop stretch x_r / X_r must stay positive).
Eigen::Vector3d strained(const Eigen::Vector3d& x, double t, int dim, bool axis) {
  Eigen::Matrix3d a;
  a << 0.03, 0.01, 0.004, -0.006, -0.012, 0.008, 0.005, 0.002, 0.02;
  if (dim == 2) a.row(2).setZero(), a.col(2).setZero();
  Eigen::Vector3d q(0.01 * x(1) * x(1), 0.008 * x(0) * x(1), dim == 3 ? 0.006 * x(0) * x(2) : 0.0);
  const Eigen::Matrix3d r = rotation(rotation_axis(dim), axis ? 0.3 : 70.0 * kPi / 180.0);
  return r * (x + t * (a * x + q));
}

TEST_P(TangentByDifferences, TheTangentIsTheDerivativeOfTheInternalForce) {
  const TangentCase& tc = GetParam();
  const bool axis = tc.hyp == Modelisation::Axisymmetric;
  std::shared_ptr<const Behaviour> law;
  if (tc.plastic) law = von_mises_test::make_law(von_mises_test::Law::Linear);
  Block block(Case{tc.what, tc.type, tc.hyp}, Kinematics::TotalLagrangian, law, axis ? 1.0 : 0.0);
  Tangent tangent(*block.behaviours, *block.dofs);
  if (tc.plastic) {  // a first plastic step, committed: the start of the step differentiated
    Vector f_int;
    ASSERT_TRUE(tangent.assemble(block.displacement([&](const Eigen::Vector3d& x) { return strained(x, 0.6, block.dim, axis); }),
                                 nullptr, &f_int));
    tangent.commit();
  }
  const Vector u = block.displacement([&](const Eigen::Vector3d& x) { return strained(x, 1.0, block.dim, axis); });
  SparseMatrix k;
  Vector f_int;
  ASSERT_TRUE(tangent.assemble(u, &k, &f_int));
  if (tc.plastic) {  // every point yields in this step (V2, the step's plastic indicator)
    for (int cell : block.model.volume_cells())
      for (int q = 0; q < tangent.states().n_points(cell); ++q)
        EXPECT_EQ(tangent.states().variables(MaterialStates::Slot::End, cell, q)[1], 1.0) << "cell " << cell << ", point " << q;
  }
  const Eigen::MatrixXd dense = Eigen::MatrixXd(k);
  // Central differences: truncation h^2 |f'''| and round-off 1e-16 |f| / h are both below 1e-9
  // of |K| at h = 1e-6 (|u| and the block of order 1): the check at 1e-6 sees the tangent's own error.
  const double h = 1e-6;
  double worst = 0.0;
  for (int j = 0; j < block.dofs->n_dofs(); ++j) {
    Vector up = u, um = u, fp, fm;
    up(j) += h;
    um(j) -= h;
    ASSERT_TRUE(tangent.assemble(up, nullptr, &fp));
    ASSERT_TRUE(tangent.assemble(um, nullptr, &fm));
    worst = std::max(worst, ((fp - fm) / (2.0 * h) - dense.col(j)).lpNorm<Eigen::Infinity>());
  }
  const double scale = dense.lpNorm<Eigen::Infinity>();
  std::printf("  %s: largest |K - dF/du| = %.3g of max |K| = %.3g\n", tc.what, worst / scale, scale);
  EXPECT_LE(worst, 1e-6 * scale) << tc.what;
  EXPECT_LE((dense - dense.transpose()).lpNorm<Eigen::Infinity>(), 1e-12 * scale) << "a symmetric tangent";
}

INSTANTIATE_TEST_SUITE_P(
    Cases, TangentByDifferences,
    ::testing::Values(TangentCase{"HEXA8 3D elastic", CellType::Hexa8, Modelisation::Solid3D, false},
                      TangentCase{"HEXA8 3D plastic", CellType::Hexa8, Modelisation::Solid3D, true},
                      TangentCase{"TETRA10 3D plastic", CellType::Tetra10, Modelisation::Solid3D, true},
                      TangentCase{"HEXA20 3D elastic", CellType::Hexa20, Modelisation::Solid3D, false},
                      TangentCase{"QUAD4 plane strain elastic", CellType::Quad4, Modelisation::PlaneStrain, false},
                      TangentCase{"QUAD8 plane strain plastic", CellType::Quad8, Modelisation::PlaneStrain, true},
                      TangentCase{"QUAD4 axisymmetric elastic", CellType::Quad4, Modelisation::Axisymmetric, false},
                      TangentCase{"QUAD4 axisymmetric plastic", CellType::Quad4, Modelisation::Axisymmetric, true}),
    [](const ::testing::TestParamInfo<TangentCase>& info) { return case_name(info.param.what); });

TEST(LargeRotations, AnInvertedCellFailsTheStepAndPlaneStressIsRefused) {
  Block block(Case{"HEXA8 3D", CellType::Hexa8, Modelisation::Solid3D});
  Tangent tangent(*block.behaviours, *block.dofs);
  // x = -X through the origin: det F = -1 at every point, no admissible state.
  Vector f_int;
  EXPECT_FALSE(tangent.assemble(block.displacement([](const Eigen::Vector3d& x) { return Eigen::Vector3d(-x); }),
                                nullptr, &f_int));
  EXPECT_THROW(Block(Case{"QUAD4 plane stress", CellType::Quad4, Modelisation::PlaneStress}), DeckError);
}

}  // namespace lunaster::engine::green_lagrange_test

namespace lunaster::engine::green_lagrange_test {

// An axisymmetric ring R in [1, 2], Z in [0, 1] (QUAD4, interior nodes distorted), the axial
// displacement held everywhere and u_r = (s - 1) R imposed on R = 1 and R = 2: the hoop stretch
// u_r / R equals the radial one, F = diag(s, 1, s) (rr, zz, tt), E_rr = E_tt = (s^2 - 1) / 2 = e.
// The uniform S (S_rr = S_tt = 2 (lambda + mu) e, S_zz = 2 lambda e) is in equilibrium
// (P_rr = P_tt, so dP_rr/dR + (P_rr - P_tt) / R = 0), and its nodal forces vanish at the interior
// nodes exactly (they integrate d(R N_a)/dR, a polynomial 2x2 Gauss points hold): the discrete
// solution is u_r = (s - 1) R. Cauchy: J = s^2, sigma_rr = sigma_tt = S_rr, sigma_zz = S_zz / s^2.
TEST(LargeRotations, AxisymmetricHoopStretchGivesTheClosedForm) {
  const double s = 1.1, e = 0.5 * (s * s - 1.0);
  Block block(Case{"QUAD4 axisymmetric", CellType::Quad4, Modelisation::Axisymmetric}, Kinematics::TotalLagrangian,
              nullptr, 1.0);
  Tangent tangent(*block.behaviours, *block.dofs);
  Vector u = Vector::Zero(block.dofs->n_dofs());
  std::vector<char> fixed(block.dofs->n_dofs(), 0);
  for (int v = 0; v < block.mesh().n_nodes(); ++v) {
    const double r = block.node(v)(0);
    fixed[block.dofs->dof(v, 1)] = 1;
    if (r == 1.0 || r == 2.0) {
      fixed[block.dofs->dof(v, 0)] = 1;
      u(block.dofs->dof(v, 0)) = (s - 1.0) * r;
    }
  }
  const test::NewtonLog log =
      test::newton_step(tangent, test::free_equations(fixed), Vector::Zero(block.dofs->n_dofs()), kE, u, 1e-13);
  ASSERT_TRUE(log.converged);
  for (int v = 0; v < block.mesh().n_nodes(); ++v)
    test::expect_close(u(block.dofs->dof(v, 0)), (s - 1.0) * block.node(v)(0), 1e-10, 1e-13, "u_r");
  const double srr = 2.0 * (kLambda + kMu) * e, szz = 2.0 * kLambda * e;
  const std::vector<double> pk2{srr, szz, srr, 0.0}, cauchy_exact{srr, szz / (s * s), srr, 0.0};
  const ElgaField cauchy = stresses_at_points(*block.behaviours, *block.dofs, u, tangent.states());
  for (int cell : block.model.volume_cells())
    for (int q = 0; q < tangent.states().n_points(cell); ++q)
      for (int i = 0; i < 4; ++i) {
        test::expect_close(tangent.states().stress(MaterialStates::Slot::End, cell, q)[i], pk2[i], 1e-10, 1e-10 * srr,
                           "second Piola-Kirchhoff stress");
        test::expect_close(cauchy.values[(static_cast<size_t>(cauchy.cell_offsets[cell]) + q) * 4 + i], cauchy_exact[i],
                           1e-10, 1e-10 * srr, "Cauchy stress " + cauchy.components[i]);
      }
  std::printf("  hoop stretch %g: Cauchy rr = tt = %.8g, zz = %.8g\n", s, srr, szz / (s * s));
}

}  // namespace lunaster::engine::green_lagrange_test
