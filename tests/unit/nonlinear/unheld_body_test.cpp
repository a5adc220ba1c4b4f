// find_unheld_body: a body that no Dirichlet condition (or relation) holds in some rigid
// motion is named from the geometry alone, with the direction and the node where that
// motion is largest; a body held in every rigid motion is not, whatever its mesh.
#include <gtest/gtest.h>

#include <string>

#include "engine/nonlinear/rigid_body.hpp"

namespace lunaster::engine {
namespace {

struct Scene {
  Mesh mesh;
  FeModel model;
  DofMap dofs;
  std::vector<int> free_index;

  /// `cells` of `type` on the nodes given, all in group `group`, one modelisation.
  void finish(Modelisation kind, int dim) {
    mesh.detect_dimension();
    model.mesh = &mesh;
    model.dim = dim;
    model.modelisation.assign(mesh.n_cells(), kind);
    model.material.assign(mesh.n_cells(), 0);
    model.materials = {{1.0, 0.0, 0.0}};
    std::vector<int> all(mesh.n_cells());
    for (int c = 0; c < mesh.n_cells(); ++c) all[c] = c;
    dofs = DofMap(mesh, all, dim);
    free_index.assign(dofs.n_dofs(), 0);
  }
  void hold(int node, int component) { free_index[dofs.dof(node, component)] = -1; }
  std::optional<SolveError> check(const std::vector<int>& held = {}) const {
    return find_unheld_body(model, dofs, free_index, held, 1.0);
  }
};

/// Two QUAD4 side by side, [0, 2] x [0, 1], nodes N1..N6 (bottom row N1 N2 N3), group BLOCK;
/// with `second`, a separate copy shifted by 3 in x (nodes N7..N12), group OTHER.
Scene two_quads(Modelisation kind = Modelisation::PlaneStrain, bool second = false) {
  Scene s;
  for (int b = 0; b < (second ? 2 : 1); ++b) {
    const int first = s.mesh.n_nodes();
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i)
        s.mesh.add_node(3.0 * b + i, j, 0.0, "N" + std::to_string(first + 3 * j + i + 1));
    const int c0 = s.mesh.add_cell(CellType::Quad4, {first, first + 1, first + 4, first + 3});
    const int c1 = s.mesh.add_cell(CellType::Quad4, {first + 1, first + 2, first + 5, first + 4});
    s.mesh.cell_groups[b == 0 ? "BLOCK" : "OTHER"] = {c0, c1};
  }
  s.finish(kind, 2);
  return s;
}

std::string text(const std::optional<SolveError>& e) { return e ? e->message() : std::string("(held)"); }

TEST(UnheldBody, HeldInOneDirectionOnlyIsFreeInTheOther) {
  Scene s = two_quads();
  for (int n : {0, 1, 2}) s.hold(n, DY);
  const auto e = s.check();
  ASSERT_TRUE(e.has_value());
  EXPECT_EQ(e->failure().what, Failure::What::RigidBodyMode);
  EXPECT_NE(text(e).find("the body BLOCK (2 cells) has a rigid-body mode (free to move along DX, detected at node N1)"),
            std::string::npos)
      << text(e);
}

TEST(UnheldBody, APinnedBodyTurnsAboutItsPin) {
  Scene s = two_quads();
  s.hold(0, DX), s.hold(0, DY);  // N1 at (0, 0)
  // The free motion is the rotation about N1: largest along DY at N3 (2, 0) and N6 (2, 1),
  // the first of them named.
  EXPECT_NE(text(s.check()).find("(free to move along DY, detected at node N3)"), std::string::npos)
      << text(s.check());
  s.hold(2, DY);  // N3 at (2, 0): the rotation is held too
  EXPECT_FALSE(s.check().has_value()) << text(s.check());
}

TEST(UnheldBody, ARelationCountsAsHolding) {
  Scene s = two_quads();
  for (int n : {0, 1, 2}) s.hold(n, DY);
  EXPECT_TRUE(s.check().has_value());
  EXPECT_FALSE(s.check({s.dofs.dof(4, DX)}).has_value());
}

TEST(UnheldBody, EachBodyIsCheckedOnItsOwn) {
  Scene s = two_quads(Modelisation::PlaneStrain, true);
  for (int n : {0, 1, 2}) s.hold(n, DX), s.hold(n, DY);  // BLOCK clamped, OTHER held in DY only
  for (int n : {6, 7, 8}) s.hold(n, DY);
  EXPECT_NE(text(s.check()).find("the body OTHER (2 cells) has a rigid-body mode (free to move along DX, detected at node N7)"),
            std::string::npos)
      << text(s.check());
  s.hold(9, DX);
  EXPECT_FALSE(s.check().has_value()) << text(s.check());
}

TEST(UnheldBody, AxisymmetricBodiesMoveAlongTheAxisOnly) {
  Scene s = two_quads(Modelisation::Axisymmetric);
  EXPECT_NE(text(s.check()).find("(free to move along DY"), std::string::npos) << text(s.check());
  s.hold(5, DY);  // one node held axially: a radial motion is no rigid motion of a body of revolution
  EXPECT_FALSE(s.check().has_value()) << text(s.check());
}

TEST(UnheldBody, ACubeHeldOnAnEdgeTurnsAboutIt) {
  Scene s;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) s.mesh.add_node(i, j, k, "N" + std::to_string(4 * k + 2 * j + i + 1));
  s.mesh.cell_groups["CUBE"] = {s.mesh.add_cell(CellType::Hexa8, {0, 1, 3, 2, 4, 5, 7, 6})};
  s.finish(Modelisation::Solid3D, 3);
  for (int n : {0, 1})  // the edge y = z = 0
    for (int c : {DX, DY, DZ}) s.hold(n, c);
  // The rotation about X moves N3 (0, 1, 0) along DZ by 1, as far as any node moves along
  // one direction: N3 is the first such node.
  EXPECT_NE(text(s.check()).find("the body CUBE (1 cells) has a rigid-body mode (free to move along DZ, detected at node N3)"),
            std::string::npos)
      << text(s.check());
  s.hold(2, DY);  // N3 at (0, 1, 0): the rotation about X moves it along DZ only
  EXPECT_TRUE(s.check().has_value());
  s.hold(2, DZ);
  EXPECT_FALSE(s.check().has_value()) << text(s.check());
}

}  // namespace
}  // namespace lunaster::engine
