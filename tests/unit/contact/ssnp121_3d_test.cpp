// End-to-end 3D contact solves on the committed SSNP121 meshes (two unit cubes
// stacked, E = 2e6, nu = 0, DZ = -0.1 imposed on top; exact answer LAGS_C =
// -1e5 Pa on every slave node, DZ = -0.05 m on the interface) with the
// engine's FE assembly and the minimal driver of two_blocks.hpp. Covers the 3D
// paths: projection on TRIA3/6 and QUAD4/8 masters, triangle and quadrangle
// integration rules, LAGS_C on quadratic slave mid-nodes; and the
// compatibility check of the two seed pairings that must warn.
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "engine/contact/compatibility.hpp"
#include "engine/contact/surface_element.hpp"
#include "engine/io/med_reader.hpp"
#include "two_blocks.hpp"

using namespace contact_test;

namespace {

struct Case {
  const char* mesh;  // testcases/<mesh>.med
  IntegrationScheme scheme;
  int order;
  ContactInit init;
  double tolerance;  // on every slave node
};

Mesh load_3d_case(const std::string& name) {
  return read_med(std::string(LUNASTER_SOURCE_DIR) + "/testcases/" + name + ".med");
}

FeModel solid_model(const Mesh& mesh) {
  FeModel model;
  model.mesh = &mesh;
  model.dim = 3;
  model.modelisation.assign(mesh.n_cells(), Modelisation::None);
  model.material.assign(mesh.n_cells(), -1);
  for (int c = 0; c < mesh.n_cells(); ++c)
    if (contact::topological_dim(mesh.cell_types[c]) == 3) model.modelisation[c] = Modelisation::Solid3D, model.material[c] = 0;
  model.materials.push_back({2.0e6, 0.0, 0.0});
  return model;
}

ContactZone zone_of(const Mesh& mesh, const Case& c) {
  ContactZone z;
  z.slave_cells = mesh.cell_groups.at("SURESC");
  z.master_cells = mesh.cell_groups.at("SURMAI");
  z.integration = c.scheme;
  z.integration_order = c.order;
  z.coef_cont = 1000.0;
  z.init = c.init;
  return z;
}

class Ssnp121_3d : public ::testing::TestWithParam<Case> {};

TEST_P(Ssnp121_3d, ReproducesTheUniformPressureOnEverySlaveNode) {
  const Case& c = GetParam();
  const Mesh mesh = load_3d_case(c.mesh);
  const FeModel model = solid_model(mesh);
  ContactDefinition def;
  def.method = ContactMethod::Continuous;
  def.zones.push_back(zone_of(mesh, c));
  EXPECT_TRUE(check_contact_zone_compatibility(mesh, def.zones[0], 0).empty()) << c.mesh;
  auto hook = make_contact_hook(def, mesh, 3);
  std::vector<Imposed> bcs;
  for (int n : mesh.nodes_of_cells(mesh.cell_groups.at("ENCAST")))
    for (int k : {DX, DY, DZ}) bcs.push_back({n, k, 0.0});
  for (int n : mesh.nodes_of_cells(mesh.cell_groups.at("SURCHA")))
    bcs.push_back({n, DX, 0.0}), bcs.push_back({n, DY, 0.0}), bcs.push_back({n, DZ, -0.1});
  const SolveResult r = solve(model, bcs, {}, *hook, quiet_log());
  double err_lambda = 0.0, err_dz = 0.0;
  for (int n : mesh.nodes_of_cells(mesh.cell_groups.at("SURESC"))) {
    err_lambda = std::max(err_lambda, std::abs(lags_c(r, n) / -1e5 - 1.0));
    err_dz = std::max(err_dz, std::abs(r.u[r.dofs.dof(n, DZ)] / -0.05 - 1.0));
  }
  std::printf("%s: max relative error on SURESC: LAGS_C %.2e, DZ %.2e\n", c.mesh, err_lambda, err_dz);
  EXPECT_LE(err_lambda, c.tolerance);
  EXPECT_LE(err_dz, c.tolerance);
}

// The deck settings of SSNP121 D, E, F, I, J, K (matching meshes, and I whose
// master edges fall on the Simpson panel boundaries) give the exact answer.
INSTANTIATE_TEST_SUITE_P(
    Decks, Ssnp121_3d,
    ::testing::Values(Case{"ssnp121d", IntegrationScheme::Simpson, 1, ContactInit::Interpenetrated, 1e-9},
                      Case{"ssnp121e", IntegrationScheme::Gauss, 4, ContactInit::Interpenetrated, 1e-9},
                      Case{"ssnp121f", IntegrationScheme::Auto, 0, ContactInit::No, 1e-9},
                      Case{"ssnp121i", IntegrationScheme::Simpson, 4, ContactInit::Interpenetrated, 1e-9},
                      Case{"ssnp121j", IntegrationScheme::NewtonCotes, 3, ContactInit::Interpenetrated, 1e-9},
                      Case{"ssnp121k", IntegrationScheme::NewtonCotes, 5, ContactInit::Yes, 1e-9}),
    [](const auto& info) { return std::string(info.param.mesh); });

TEST(Ssnp121_3dCompatibility, QuadrangleSlaveOnTria6MasterIsFlagged) {
  for (const char* name : {"ssnp121f_quad8_on_tria6", "ssnp121k_quad4_on_tria6"}) {
    const Mesh mesh = load_3d_case(name);
    const ContactZone z = zone_of(mesh, Case{name, IntegrationScheme::Auto, 0, ContactInit::Interpenetrated, 0});
    const auto messages = check_contact_zone_compatibility(mesh, z, 0);
    ASSERT_EQ(messages.size(), 1u) << name;
    EXPECT_NE(messages[0].find("TRIA6 slave on QUAD8 master"), std::string::npos) << messages[0];
  }
}

// A rule with fewer points than a slave cell has LAGS_C unknowns leaves the
// multipliers under-determined: the continuous method must say so.
TEST(Ssnp121_3dCompatibility, TooFewIntegrationPointsAreFlagged) {
  const Mesh mesh = load_3d_case("ssnp121e");  // TRIA6 slave: 6 LAGS_C per cell
  ContactZone z = zone_of(mesh, Case{"ssnp121e", IntegrationScheme::Gauss, 3, ContactInit::Interpenetrated, 0});
  auto messages = check_contact_zone_integration(mesh, z, 0);
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_EQ(messages[0].kind, IntegrationWarning::Kind::TooFewPoints);
  EXPECT_NE(messages[0].text.find("6 LAGS_C unknowns"), std::string::npos) << messages[0].text;
  z.integration_order = 4;  // the rule of SSNP121 E: 6 points, well posed
  EXPECT_TRUE(check_contact_zone_integration(mesh, z, 0).empty());
  z.integration = IntegrationScheme::Auto;
  z.integration_order = 0;
  EXPECT_TRUE(check_contact_zone_integration(mesh, z, 0).empty());
}

// A linear slave integrated at its vertices (AUTO) against a quadratic master leaves the
// master mid-side nodes unloaded wherever the vertices coincide: the continuous method says so.
TEST(Ssnp121_3dCompatibility, VertexRuleOnQuadraticMasterIsFlagged) {
  const Mesh mesh = load_3d_case("ssnp121i");  // QUAD4 slave SURESC on QUAD8 master SURMAI
  ContactZone z = zone_of(mesh, Case{"ssnp121i", IntegrationScheme::Auto, 0, ContactInit::Interpenetrated, 0});
  auto messages = check_contact_zone_integration(mesh, z, 0);
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_EQ(messages[0].kind, IntegrationWarning::Kind::VerticesOnlyOnQuadraticMaster);
  EXPECT_NE(messages[0].text.find("linear slave QUAD4"), std::string::npos) << messages[0].text;
  EXPECT_NE(messages[0].text.find("quadratic master QUAD8"), std::string::npos) << messages[0].text;
  z.integration = IntegrationScheme::Simpson;  // SSNP121 I's own rule: interior points
  z.integration_order = 4;
  EXPECT_TRUE(check_contact_zone_integration(mesh, z, 0).empty());
  z.integration = IntegrationScheme::Nodes;
  z.integration_order = 0;
  EXPECT_EQ(check_contact_zone_integration(mesh, z, 0).size(), 1u);
}

}  // namespace
