// RenumberedHook (engine/nonlinear/renumbered_hook.hpp): the driver numbers the unknowns its way
// (on a mesh in parts, a rank's owned ones first) while the hook keeps the numbering it added its
// multipliers in. Every vector, triplet and equation list crosses the adapter renumbered.
#include <gtest/gtest.h>

#include "engine/nonlinear/renumbered_hook.hpp"

namespace lunaster::engine {
namespace {

/// A hook on four unknowns in its own numbering: it reads u[0] and u[1], writes into equations
/// 1 and 2, condenses 3 (recovered as u[0] + u[2]) and eliminates 1 by du[1] = 0.5 du[2] + 0.25.
class FourUnknowns final : public ContactHook {
 public:
  void add_dofs(DofMap&) override {}
  void begin_step(const Vector& u, const Log&) override { seen = u; }
  void add_to_system(const Vector& u, std::vector<Triplet>& tangent, Vector& residual) override {
    seen = u;
    tangent.emplace_back(1, 2, u[0]);
    residual[2] += u[1];
  }
  bool add_residual(const Vector& u, Vector& residual) override {
    residual[1] += 10.0 * u[0];
    return true;
  }
  const std::vector<int>& condensed_equations() const override { return condensed_; }
  void recover(Vector& u) override { u[3] = u[0] + u[2]; }
  const std::vector<Elimination>& eliminations() const override { return eliminations_; }
  std::vector<int> surface_equations() const override { return {0, 3}; }
  bool settle(const Vector& u, const Log&) override {
    seen = u;
    return true;
  }
  MatrixKind matrix_kind() const override { return MatrixKind::SymmetricPositiveDefinite; }
  int n_active() const override { return 1; }
  void write_fields(const Vector& u, ResultStep&) const override { written = u; }

  Vector seen;
  mutable Vector written;

 private:
  std::vector<int> condensed_{3};
  std::vector<Elimination> eliminations_{{1, {{2, 0.5}}, 0.25}};
};

TEST(RenumberedHook, GivesTheHookItsNumberingAndTheDriverItsOwn) {
  FourUnknowns hook;
  const std::vector<int> new_of_old = {2, 0, 3, 1};  // the hook's equation e is the driver's new_of_old[e]
  RenumberedHook seen_by_driver(hook, new_of_old);
  Vector u(4);  // the driver's: u[new_of_old[e]] = 100 + e
  for (int e = 0; e < 4; ++e) u[new_of_old[e]] = 100.0 + e;

  std::vector<Triplet> tangent{Triplet(0, 0, 7.0)};  // a term already there stays as it is
  Vector residual = Vector::Zero(4);
  seen_by_driver.add_to_system(u, tangent, residual);
  for (int e = 0; e < 4; ++e) EXPECT_EQ(hook.seen[e], 100.0 + e);
  ASSERT_EQ(tangent.size(), 2u);
  EXPECT_EQ(tangent[0].row(), 0);
  EXPECT_EQ(tangent[1].row(), new_of_old[1]);
  EXPECT_EQ(tangent[1].col(), new_of_old[2]);
  EXPECT_EQ(tangent[1].value(), 100.0);
  EXPECT_EQ(residual[new_of_old[2]], 101.0);
  EXPECT_EQ(residual.cwiseAbs().sum(), 101.0);
  EXPECT_EQ(seen_by_driver.condensed_equations(), std::vector<int>{new_of_old[3]});
  ASSERT_EQ(seen_by_driver.eliminations().size(), 1u);
  const Elimination& e = seen_by_driver.eliminations()[0];
  EXPECT_EQ(e.eq, new_of_old[1]);
  ASSERT_EQ(e.terms.size(), 1u);
  EXPECT_EQ(e.terms[0].first, new_of_old[2]);
  EXPECT_EQ(e.terms[0].second, 0.5);
  EXPECT_EQ(e.value, 0.25);

  Vector r = Vector::Zero(4);
  EXPECT_TRUE(seen_by_driver.add_residual(u, r));
  EXPECT_EQ(r[new_of_old[1]], 1000.0);

  seen_by_driver.recover(u);
  EXPECT_EQ(u[new_of_old[3]], 100.0 + 102.0);
  EXPECT_EQ(u[new_of_old[0]], 100.0);

  EXPECT_EQ(seen_by_driver.surface_equations(), (std::vector<int>{1, 2}));  // {0, 3} renumbered, sorted
  ResultStep step;
  seen_by_driver.write_fields(u, step);
  EXPECT_EQ(hook.written[3], 202.0);
}

}  // namespace
}  // namespace lunaster::engine
