// Inverted-cell detection and ORIE_PEAU outward orientation of boundary cells.
#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "engine/mesh/orientation.hpp"
#include "test_helpers.hpp"
#include "tools/ssnp121_mesh.hpp"

namespace lunaster::engine {
namespace {

double dot(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

TEST(Orientation, ReferenceCellsAreValidAndSwappedOnesAreInverted) {
  for (CellType t : testing::all_cell_types()) {
    const int dim = cell_info(t).dim;
    if (dim < 2) continue;
    Mesh good;
    testing::add_reference_cell(good, t);
    good.detect_dimension();
    EXPECT_TRUE(find_inverted_cells(good).empty()) << cell_info(t).name;
    // VTK/Gmsh order for 3D cells (first face inward) must be flagged; 2D: clockwise
    Mesh bad;
    const auto x = testing::reference_nodes(t);
    std::vector<int> nodes;
    for (const auto& p : x) nodes.push_back(bad.add_node(p[0], p[1], p[2]));
    std::swap(nodes[1], nodes[2]);
    if (cell_info(t).order == 2) {
      // keep mid-side nodes consistent with the swapped vertices: rebuild them
      Mesh tmp;
      std::vector<std::array<double, 3>> v;
      for (int k = 0; k < cell_info(t).n_vertices; ++k) v.push_back(x[nodes[k]]);
      nodes.resize(cell_info(t).n_vertices);
      for (const auto& [a, b] : cell_mid_edges(t))
        nodes.push_back(bad.add_node(0.5 * (v[a][0] + v[b][0]), 0.5 * (v[a][1] + v[b][1]), 0.5 * (v[a][2] + v[b][2])));
    }
    if (t == CellType::Quad4 || t == CellType::Quad8 || t == CellType::Hexa8 || t == CellType::Hexa20 ||
        t == CellType::Pyram5) {
      // a swap of 1 and 2 makes a bow-tie; reverse instead: 0 3 2 1
      std::swap(nodes[1], nodes[2]);
      std::swap(nodes[1], nodes[3]);
      if (dim == 3 && t != CellType::Pyram5) std::swap(nodes[5], nodes[7]);
      if (cell_info(t).order == 2) continue;  // linear reversal is enough for these
    }
    bad.add_cell(t, nodes, "BAD");
    bad.detect_dimension();
    ASSERT_EQ(find_inverted_cells(bad).size(), 1u) << cell_info(t).name;
    EXPECT_EQ(inverted_cell_names(bad).front(), "BAD");
    try {
      check_cell_orientation(bad, "file.med");
      ADD_FAILURE() << "no error for " << cell_info(t).name;
    } catch (const DeckError& e) {
      EXPECT_NE(std::string(e.what()).find("file.med"), std::string::npos);
      EXPECT_NE(std::string(e.what()).find("BAD"), std::string::npos);
    }
  }
}

TEST(Orientation, DegenerateCellIsReported) {
  Mesh mesh;
  const int a = mesh.add_node(0, 0, 0), b = mesh.add_node(1, 0, 0), c = mesh.add_node(2, 0, 0), d = mesh.add_node(0, 1, 0);
  mesh.add_cell(CellType::Tria3, {a, b, d}, "OK");
  mesh.add_cell(CellType::Tria3, {a, b, c}, "FLAT");
  mesh.detect_dimension();
  ASSERT_EQ(inverted_cell_names(mesh), std::vector<std::string>{"FLAT"});
}

TEST(Orientation, DistortedHexaWithFoldedCornerIsInverted) {
  Mesh mesh;
  testing::add_reference_cell(mesh, CellType::Hexa8);
  mesh.detect_dimension();
  mesh.coords[3 * 6 + 0] = -0.5;  // node 6 (1,1,1) pulled through the x=0 face
  mesh.coords[3 * 6 + 1] = -0.5;
  EXPECT_EQ(find_inverted_cells(mesh).size(), 1u);
}

std::vector<int> reverse_cells(Mesh& mesh, const std::vector<int>& cells) {
  for (int c : cells) {
    const auto& perm = cell_reverse_permutation(mesh.cell_types[c]);
    std::vector<int> old(mesh.cell(c), mesh.cell(c) + mesh.cell_n_nodes(c));
    for (size_t k = 0; k < perm.size(); ++k) mesh.cell_nodes[mesh.cell_offsets[c] + k] = old[perm[k]];
  }
  return cells;
}

TEST(Orientation, OrientBoundaryOutward2d) {
  tools::Ssnp121Options2d opt;
  opt.lower = tools::parse_block_cells("quad8:5", 2);
  opt.upper = tools::parse_block_cells("quad4:4", 2);
  Mesh mesh = tools::make_ssnp121_2d(opt);
  const auto ab = mesh.cell_groups.at("AB"), ef = mesh.cell_groups.at("EF"), cd = mesh.cell_groups.at("CD");
  // the generator already orients outward: nothing to flip
  EXPECT_EQ(orient_boundary_outward(mesh, ab), 0);
  for (int c : ab) EXPECT_GT(dot(boundary_normal(mesh, c), {0, -1, 0}), 0.0);
  for (int c : ef) EXPECT_GT(dot(boundary_normal(mesh, c), {0, 1, 0}), 0.0);
  reverse_cells(mesh, {ab[0], ab[2], ef[1]});
  reverse_cells(mesh, cd);
  EXPECT_EQ(orient_boundary_outward(mesh, ab), 2);
  EXPECT_EQ(orient_boundary_outward(mesh, ef), 1);
  EXPECT_EQ(orient_boundary_outward(mesh, cd), static_cast<int>(cd.size()));
  for (int c : ab) EXPECT_GT(dot(boundary_normal(mesh, c), {0, -1, 0}), 0.0);
  for (int c : ef) EXPECT_GT(dot(boundary_normal(mesh, c), {0, 1, 0}), 0.0);
  for (int c : cd) EXPECT_GT(dot(boundary_normal(mesh, c), {0, 1, 0}), 0.0);
  // SEG3 mid node stays in the middle after the flip
  const int c = ef[1];
  EXPECT_EQ(mesh.cell_types[c], CellType::Seg3);
  for (int d = 0; d < 2; ++d)
    EXPECT_DOUBLE_EQ(mesh.node(mesh.cell(c)[2])[d], 0.5 * (mesh.node(mesh.cell(c)[0])[d] + mesh.node(mesh.cell(c)[1])[d]));
}

TEST(Orientation, OrientBoundaryOutward3dAllFaceTypes) {
  for (const char* v1 : {"hexa8:2x2x1", "hexa20:2x2x1", "penta6:2x2x1", "penta15:2x2x1", "tetra4:2x2x1", "tetra10:1x1x1"}) {
    tools::Ssnp121Options3d opt;
    opt.v1 = tools::parse_block_cells(v1, 3);
    opt.v2 = tools::parse_block_cells("hexa8:1x1x1", 3);
    Mesh mesh = tools::make_ssnp121_3d(opt);
    const auto esc = mesh.cell_groups.at("SURESC"), enc = mesh.cell_groups.at("ENCAST");
    reverse_cells(mesh, esc);
    reverse_cells(mesh, {enc[0]});
    EXPECT_EQ(orient_boundary_outward(mesh, esc), static_cast<int>(esc.size())) << v1;
    EXPECT_EQ(orient_boundary_outward(mesh, enc), 1) << v1;
    for (int c : esc) EXPECT_GT(dot(boundary_normal(mesh, c), {0, 0, 1}), 0.0) << v1;
    for (int c : enc) EXPECT_GT(dot(boundary_normal(mesh, c), {0, 0, -1}), 0.0) << v1;
  }
}

TEST(Orientation, OrientBoundaryErrors) {
  tools::Ssnp121Options2d opt;
  opt.upper = opt.lower = tools::parse_block_cells("quad4:2", 2);
  opt.glued = true;
  Mesh mesh = tools::make_ssnp121_2d(opt);
  // glued interface: AB is shared by a cell of each block
  EXPECT_THROW(orient_boundary_outward(mesh, mesh.cell_groups.at("AB")), DeckError);
  // a volume cell is not a boundary cell
  EXPECT_THROW(orient_boundary_outward(mesh, {mesh.cell_groups.at("PLAQUE1")[0]}), DeckError);
  // a segment across the domain bounds no cell
  const int far = mesh.add_node(5, 5, 0);
  const int lost = mesh.add_cell(CellType::Seg2, {0, far}, "LOST");
  try {
    orient_boundary_outward(mesh, {lost});
    ADD_FAILURE() << "no error";
  } catch (const DeckError& e) {
    EXPECT_NE(std::string(e.what()).find("LOST"), std::string::npos);
  }
}

}  // namespace
}  // namespace lunaster::engine
