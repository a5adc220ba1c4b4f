#pragma once
// One QUAD4 with a single free unknown (node 2, DY) loaded by a nodal force F t, plus a
// saturating spring c atan(u / s) added through the contact hook, so that the production
// Newton driver (StaticSolver) solves r(u) = k u + c atan(u / s) - F t = 0: a small, truly
// nonlinear problem with a root known by bisection. Shared by the nonlinear unit tests.
#include <cmath>
#include <sstream>
#include <string>

#include "engine/core/log.hpp"
#include "engine/nonlinear/static_solver.hpp"

namespace lunaster::engine::one_quad {

constexpr double kSpring = 1.0;     // c, N
constexpr double kKnee = 0.01;      // s, m
constexpr double kForce = 1.5;      // F at t = 1, N (default)
constexpr int kFreeNode = 2;

/// The saturating spring c atan(u/s) on one unknown, seen by the solver as a "contact".
class AtanSpring : public ContactHook {
 public:
  explicit AtanSpring(double c) : c_(c) {}
  void add_dofs(DofMap& dofs) override { eq_ = dofs.dof(kFreeNode, DY); }
  void begin_step(const Vector&, const Log&) override {}
  void add_to_system(const Vector& u, std::vector<Triplet>& tangent, Vector& residual) override {
    const double x = u[eq_] / kKnee;
    residual[eq_] += c_ * std::atan(x);
    tangent.emplace_back(eq_, eq_, c_ / kKnee / (1.0 + x * x));
  }
  bool settle(const Vector&, const Log&) override { return true; }
  MatrixKind matrix_kind() const override { return MatrixKind::SymmetricPositiveDefinite; }
  int n_active() const override { return 1; }
  void write_fields(const Vector&, ResultStep&) const override {}

 private:
  double c_;
  int eq_ = -1;
};

struct Problem {
  Mesh mesh;
  FeModel model;
  MechanicalLoads loads;
  explicit Problem(double force = kForce) {
    mesh.add_node(0, 0, 0);
    mesh.add_node(1, 0, 0);
    mesh.add_node(1, 1, 0);
    mesh.add_node(0, 1, 0);
    mesh.add_cell(CellType::Quad4, {0, 1, 2, 3});
    mesh.detect_dimension();
    model.mesh = &mesh;
    model.dim = 2;
    model.modelisation = {Modelisation::PlaneStrain};
    model.material = {0};
    model.materials = {{0.01, 0.0, 0.0}};  // soft: the spring dominates
    for (int node : {0, 1, 3})
      for (int cmp : {DX, DY}) loads.dirichlet.push_back({node, cmp, 0.0, 0});
    loads.dirichlet.push_back({kFreeNode, DX, 0.0, 0});
    loads.forces.push_back({kFreeNode, DY, force, 0});
    loads.multipliers.push_back([](double t) { return t; });
  }
};

inline double dy(const ResultStep& step) { return step.nodal.at("DEPL").value(kFreeNode, 1); }

inline std::string all_text(const Error& e) {
  std::string text = e.message();
  for (const auto& h : e.hints()) text += "\n" + h;
  return text;
}

/// Elastic stiffness of the free unknown, from a linear solve (no spring).
inline double elastic_stiffness() {
  Problem p;
  std::ostringstream sink;
  Log log(sink, 0);
  StaticSolver solver(p.model, p.loads, NewtonOptions{}, nullptr, log);
  const auto steps = solver.run({0.0, 1.0});
  return kForce / dy(steps.back());
}

/// Root of k u + c atan(u/s) = F by bisection (independent of the solver).
inline double exact_root(double k, double force) {
  double lo = 0.0, hi = force / k;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (k * mid + kSpring * std::atan(mid / kKnee) < force ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace lunaster::engine::one_quad
