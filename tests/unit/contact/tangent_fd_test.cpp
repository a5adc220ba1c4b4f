// Finite-difference checks of the contact tangent against the contact residual
// for every method, at a random state (statuses frozen, or updated inside Newton).
#include <random>

#include <gtest/gtest.h>

#include "engine/contact/compatibility.hpp"
#include "engine/contact/contact_factory.hpp"
#include "engine/contact/contact_problem.hpp"
#include "two_blocks.hpp"

using namespace contact_test;
using lunaster::engine::contact::ContactProblem;

namespace {

/// The shared contact part of a method, never condensing its multipliers: the whole
/// tangent, multiplier rows included, is checked against finite differences.
std::unique_ptr<ContactProblem> make_problem(const ContactDefinition& def, const Mesh& mesh) {
  std::unique_ptr<ContactProblem> p(dynamic_cast<ContactProblem*>(make_contact_hook(def, mesh, 2).release()));
  p->allow_condensation(false);
  return p;
}

struct Fixture {
  TwoBlocks tb;
  FeModel model;
  DofMap dofs;
};

Fixture make_setup(bool quadratic) {
  Fixture s{make_two_blocks(3, 2, quadratic), {}, {}};
  s.model = make_model(s.tb.mesh, 2e6, 0.0);
  s.dofs = DofMap(s.tb.mesh, s.model.volume_cells(), 2);
  return s;
}

// Contact residual and tangent alone at u.
void evaluate(ContactHook& hook, const Vector& u, Vector& r, SparseMatrix& k) {
  std::vector<Triplet> trip;
  r = Vector::Zero(u.size());
  hook.add_to_system(u, trip, r);
  k.resize(u.size(), u.size());
  k.setFromTriplets(trip.begin(), trip.end());
}

// Max relative mismatch between K v and the central difference of r along v.
double fd_mismatch(ContactHook& hook, const Vector& u, std::mt19937& gen, double scale_u, double scale_l,
                   const DofMap& dofs) {
  std::uniform_real_distribution<double> d(-1, 1);
  Vector v(u.size());
  for (int i = 0; i < v.size(); ++i) v[i] = d(gen) * (dofs.component_of(i) == LAGS_C ? scale_l : scale_u);
  Vector r0, rp, rm;
  SparseMatrix k, tmp;
  evaluate(hook, u, r0, k);
  const double eps = 1e-4;
  evaluate(hook, u + eps * v, rp, tmp);
  evaluate(hook, u - eps * v, rm, tmp);
  const Vector fd = (rp - rm) / (2 * eps);
  const Vector kv = k * v;
  EXPECT_GT(kv.norm(), 0.0);
  return (fd - kv).norm() / std::max(kv.norm(), 1e-300);
}

Vector random_state(const DofMap& dofs, std::mt19937& gen, double scale_u, double lambda_mean) {
  std::uniform_real_distribution<double> d(-1, 1);
  Vector u(dofs.n_dofs());
  for (int i = 0; i < u.size(); ++i)
    u[i] = dofs.component_of(i) == LAGS_C ? lambda_mean * (1 + 0.5 * d(gen)) : scale_u * d(gen);
  return u;
}

ContactDefinition definition(const TwoBlocks& tb, ContactMethod method, bool continuous_roles) {
  ContactDefinition def;
  def.method = method;
  ContactZone z;
  z.slave_cells = continuous_roles ? tb.ab : tb.ef;
  z.master_cells = continuous_roles ? tb.ef : tb.ab;
  z.integration = IntegrationScheme::Gauss;
  z.integration_order = 3;
  z.coef_cont = 3e5;
  z.coef_pena = 1e7;
  def.zones.push_back(z);
  return def;
}

bool symmetric(ContactHook& hook, const Vector& u) {
  Vector r;
  SparseMatrix k;
  evaluate(hook, u, r, k);
  const SparseMatrix kt = k.transpose();
  return (SparseMatrix(k - kt)).norm() <= 1e-12 * k.norm();
}

}  // namespace

TEST(ContactTangent, ContinuousMatchesFiniteDifferences) {
  std::mt19937 gen(5);
  for (bool quadratic : {false, true})
    for (ContactMethod m : {ContactMethod::Continuous, ContactMethod::ContinuousPenalty})
      for (int active = 0; active < 2; ++active) {
        Fixture s = make_setup(quadratic);
        auto hook_owner = make_problem(definition(s.tb, m, true), s.tb.mesh);
        ContactProblem& hook = *hook_owner;
        hook.add_dofs(s.dofs);
        lunaster::Log log(std::cout, 0);
        hook.begin_step(Vector::Zero(s.dofs.n_dofs()), log);
        hook.set_all_active(active == 1);
        const Vector u = random_state(s.dofs, gen, 1e-3, -1e5);
        EXPECT_LT(fd_mismatch(hook, u, gen, 1e-3, 1e4, s.dofs), 1e-8) << "quadratic " << quadratic;
        if (m == ContactMethod::Continuous) {
          EXPECT_TRUE(symmetric(hook, u));
        }
      }
}

TEST(ContactTangent, GeneralisedNewtonStatusesMatchFiniteDifferences) {
  std::mt19937 gen(9);
  Fixture s = make_setup(false);
  ContactDefinition def = definition(s.tb, ContactMethod::Continuous, true);
  def.status_loop = FixedPointOrNewton::Newton;
  auto hook_owner = make_problem(def, s.tb.mesh);
  ContactProblem& hook = *hook_owner;
  hook.add_dofs(s.dofs);
  lunaster::Log log(std::cout, 0);
  hook.begin_step(Vector::Zero(s.dofs.n_dofs()), log);
  // Mixed statuses decided by u: lambda around 0 with gaps of both signs.
  const Vector u = random_state(s.dofs, gen, 1e-3, 0.0);
  EXPECT_LT(fd_mismatch(hook, u, gen, 1e-6, 1e-1, s.dofs), 1e-8);
  int n_active = 0;
  for (const auto& p : hook.points()) n_active += p.active;
  EXPECT_GT(n_active, 0);
  EXPECT_LT(n_active, static_cast<int>(hook.points().size()));
}

TEST(ContactTangent, DiscreteMatchesFiniteDifferences) {
  std::mt19937 gen(13);
  for (bool quadratic : {false, true})
    for (ContactMethod m : {ContactMethod::DiscreteLagrange, ContactMethod::DiscretePenalty})
      for (int active = 0; active < 2; ++active) {
        Fixture s = make_setup(quadratic);
        auto hook_owner = make_problem(definition(s.tb, m, false), s.tb.mesh);
        ContactProblem& hook = *hook_owner;
        hook.add_dofs(s.dofs);
        lunaster::Log log(std::cout, 0);
        hook.begin_step(Vector::Zero(s.dofs.n_dofs()), log);
        hook.set_all_active(active == 1);
        const Vector u = random_state(s.dofs, gen, 1e-3, -1e5);
        if (m == ContactMethod::DiscretePenalty && active == 0) continue;  // no contribution at all
        EXPECT_LT(fd_mismatch(hook, u, gen, 1e-3, 1e4, s.dofs), 1e-8);
        EXPECT_TRUE(symmetric(hook, u));
      }
}

TEST(ContactTangent, InactiveContinuousDrivesMultipliersToZeroWithoutNaN) {
  // CONTACT_INIT='NON' before contact: the LAGS_C block is -(1/rho) M, regular and finite.
  Fixture s = make_setup(false);
  auto hook_owner = make_problem(definition(s.tb, ContactMethod::Continuous, true), s.tb.mesh);
  ContactProblem& hook = *hook_owner;
  hook.add_dofs(s.dofs);
  lunaster::Log log(std::cout, 0);
  hook.begin_step(Vector::Zero(s.dofs.n_dofs()), log);
  hook.set_all_active(false);
  Vector r;
  SparseMatrix k;
  evaluate(hook, Vector::Zero(s.dofs.n_dofs()), r, k);
  EXPECT_TRUE(r.allFinite());
  for (int node : hook.multiplier_nodes()) {
    const int eq = s.dofs.dof(node, LAGS_C);
    EXPECT_LT(k.coeff(eq, eq), 0.0);
    EXPECT_TRUE(std::isfinite(k.coeff(eq, eq)));
  }
}

TEST(ContactCompatibility, QuadrangleSlaveFacingTria6MasterIsReported) {
  EXPECT_FALSE(contact_pairing_compatible(CellType::Quad8, CellType::Tria6));
  EXPECT_FALSE(contact_pairing_compatible(CellType::Quad4, CellType::Tria6));
  EXPECT_TRUE(contact_pairing_compatible(CellType::Tria6, CellType::Quad8));
  EXPECT_TRUE(contact_pairing_compatible(CellType::Quad8, CellType::Quad8));
  EXPECT_TRUE(contact_pairing_compatible(CellType::Tria3, CellType::Quad8));
  Mesh mesh;
  for (int i = 0; i < 8; ++i) mesh.add_node(i, 0, 1);
  ContactZone zone;
  zone.slave_cells = {mesh.add_cell(CellType::Quad8, {0, 1, 2, 3, 4, 5, 6, 7}, "SL1")};
  zone.master_cells = {mesh.add_cell(CellType::Tria6, {0, 1, 2, 3, 4, 5}, "MA7")};
  const auto msgs = check_contact_zone_compatibility(mesh, zone, 0);
  ASSERT_EQ(msgs.size(), 1u);
  EXPECT_NE(msgs[0].find("slave QUAD8 cell SL1 faces master TRIA6 cell MA7"), std::string::npos) << msgs[0];
  EXPECT_NE(msgs[0].find("TRIA6 slave on QUAD8 master"), std::string::npos);
  zone.master_cells = {mesh.add_cell(CellType::Quad8, {0, 1, 2, 3, 4, 5, 6, 7}, "MA8")};
  EXPECT_TRUE(check_contact_zone_compatibility(mesh, zone, 0).empty());
}
