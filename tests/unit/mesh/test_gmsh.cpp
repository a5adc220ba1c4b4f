// Gmsh 2.2 and 4.1 ASCII reading, node order conversion to MED, errors.
#include <gtest/gtest.h>

#include <sstream>

#include "engine/core/error.hpp"
#include "engine/io/gmsh_reader.hpp"
#include "engine/mesh/orientation.hpp"
#include "test_helpers.hpp"
#include "tools/gmsh_writer.hpp"
#include "tools/ssnp121_mesh.hpp"

namespace lunaster::engine {
namespace {

using Vec3 = std::array<double, 3>;

/// Gmsh reference nodes (Gmsh manual, node ordering section).
std::vector<Vec3> gmsh_hexa20() {
  std::vector<Vec3> v{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const int edges[12][2] = {{0, 1}, {0, 3}, {0, 4}, {1, 2}, {1, 5}, {2, 3},
                            {2, 6}, {3, 7}, {4, 5}, {4, 7}, {5, 6}, {6, 7}};
  const auto verts = v;
  for (const auto& e : edges)
    v.push_back({0.5 * (verts[e[0]][0] + verts[e[1]][0]), 0.5 * (verts[e[0]][1] + verts[e[1]][1]),
                 0.5 * (verts[e[0]][2] + verts[e[1]][2])});
  return v;
}
std::vector<Vec3> gmsh_tetra10() {
  std::vector<Vec3> v{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const int edges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {3, 0}, {3, 2}, {3, 1}};
  const auto verts = v;
  for (const auto& e : edges)
    v.push_back({0.5 * (verts[e[0]][0] + verts[e[1]][0]), 0.5 * (verts[e[0]][1] + verts[e[1]][1]),
                 0.5 * (verts[e[0]][2] + verts[e[1]][2])});
  return v;
}
std::vector<Vec3> gmsh_prism15() {
  std::vector<Vec3> v{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
  const int edges[9][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 4}, {2, 5}, {3, 4}, {3, 5}, {4, 5}};
  const auto verts = v;
  for (const auto& e : edges)
    v.push_back({0.5 * (verts[e[0]][0] + verts[e[1]][0]), 0.5 * (verts[e[0]][1] + verts[e[1]][1]),
                 0.5 * (verts[e[0]][2] + verts[e[1]][2])});
  return v;
}

/// Expects the cell's nodes, in MED order, at the MED reference coordinates
/// (vertices mapped by `vertex_map`, a placement of the reference vertices).
void expect_med_order(const Mesh& mesh, int cell, CellType type) {
  const auto expected = testing::reference_nodes(type);
  ASSERT_EQ(mesh.cell_n_nodes(cell), static_cast<int>(expected.size()));
  for (size_t k = 0; k < expected.size(); ++k)
    for (int d = 0; d < 3; ++d)
      EXPECT_DOUBLE_EQ(mesh.node(mesh.cell(cell)[k])[d], expected[k][d]) << cell_info(type).name << " node " << k;
}

/// A 2.2 file with one 3D element plus a physical boundary triangle/point.
std::string file22(int gmsh_type, const std::vector<Vec3>& nodes) {
  std::ostringstream os;
  os << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n2\n0 7 \"TIP\"\n3 1 \"SOLID\"\n$EndPhysicalNames\n";
  os << "$Nodes\n" << nodes.size() << "\n";
  for (size_t i = 0; i < nodes.size(); ++i)
    os << i + 101 << " " << nodes[i][0] << " " << nodes[i][1] << " " << nodes[i][2] << "\n";
  os << "$EndNodes\n$Elements\n2\n5 15 2 7 1 101\n9 " << gmsh_type << " 2 1 4";
  for (size_t i = 0; i < nodes.size(); ++i) os << " " << i + 101;
  os << "\n$EndElements\n";
  return os.str();
}

TEST(Gmsh, Version22Hexa20ConvertedToMedOrder) {
  const Mesh mesh = read_gmsh_text(file22(17, gmsh_hexa20()), "hexa20.msh");
  ASSERT_EQ(mesh.n_cells(), 2);
  EXPECT_EQ(mesh.dim, 3);
  EXPECT_EQ(mesh.cell_types[1], CellType::Hexa20);
  EXPECT_EQ(mesh.cell_names[1], "M9");
  EXPECT_EQ(mesh.node_names[0], "N101");
  expect_med_order(mesh, 1, CellType::Hexa20);
  EXPECT_EQ(mesh.cell_groups.at("SOLID"), std::vector<int>{1});
  EXPECT_EQ(mesh.cell_groups.at("TIP"), std::vector<int>{0});
  EXPECT_EQ(mesh.node_groups.at("TIP"), std::vector<int>{0});
  EXPECT_NEAR(cell_measure(mesh, 1), 1.0, 1e-14);
}

TEST(Gmsh, Version22Prism15ConvertedToMedOrder) {
  const Mesh mesh = read_gmsh_text(file22(18, gmsh_prism15()), "prism.msh");
  EXPECT_EQ(mesh.cell_types[1], CellType::Penta15);
  // MED PENTA6 reference: (0,0,0) (0,1,0) (1,0,0): Gmsh's nodes 1 and 2 swapped
  expect_med_order(mesh, 1, CellType::Penta15);
  EXPECT_TRUE(find_inverted_cells(mesh).empty());
}

TEST(Gmsh, Version41Tetra10WithEntitiesAndPhysicalNames) {
  const auto nodes = gmsh_tetra10();
  std::ostringstream os;
  os << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  os << "$PhysicalNames\n2\n2 5 \"BASE\"\n3 3 \"BODY\"\n$EndPhysicalNames\n";
  os << "$Entities\n0 0 1 1\n";
  os << "1 0 0 0 1 1 0 1 5 0\n";          // surface 1: bbox, 1 physical (5), 0 bounding curves
  os << "1 0 0 0 1 1 1 1 3 1 1\n";        // volume 1: 1 physical (3), bounded by surface 1
  os << "$EndEntities\n";
  os << "$Nodes\n2 10 1 10\n";
  os << "2 1 0 3\n1\n2\n3\n0 0 0\n1 0 0\n0 1 0\n";  // base vertices on surface 1
  os << "3 1 0 7\n";
  for (int i = 4; i <= 10; ++i) os << i << "\n";
  for (int i = 3; i < 10; ++i) os << nodes[i][0] << " " << nodes[i][1] << " " << nodes[i][2] << "\n";
  os << "$EndNodes\n$Elements\n2 2 1 2\n";
  os << "2 1 2 1\n1 1 3 2\n";  // triangle on z=0, normal -z (outward)
  os << "3 1 11 1\n2 1 2 3 4 5 6 7 8 9 10\n";
  os << "$EndElements\n";
  const Mesh mesh = read_gmsh_text(os.str(), "tet10.msh");
  ASSERT_EQ(mesh.n_cells(), 2);
  EXPECT_EQ(mesh.cell_types[1], CellType::Tetra10);
  expect_med_order(mesh, 1, CellType::Tetra10);
  EXPECT_EQ(mesh.cell_groups.at("BODY"), std::vector<int>{1});
  EXPECT_EQ(mesh.cell_groups.at("BASE"), std::vector<int>{0});
  EXPECT_NEAR(cell_measure(mesh, 1), 1.0 / 6.0, 1e-14);
  EXPECT_EQ(boundary_normal(mesh, 0)[2] < 0, true);
}

TEST(Gmsh, Version22TwoDimensionalQuad8) {
  const std::string text =
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n8\n"
      "1 0 0 0\n2 2 0 0\n3 2 1 0\n4 0 1 0\n5 1 0 0\n6 2 0.5 0\n7 1 1 0\n8 0 0.5 0\n$EndNodes\n"
      "$Elements\n2\n1 16 2 3 1 1 2 3 4 5 6 7 8\n2 8 2 4 2 1 2 5\n$EndElements\n";
  const Mesh mesh = read_gmsh_text(text, "q8.msh");
  EXPECT_EQ(mesh.dim, 2);
  EXPECT_EQ(mesh.cell_types[0], CellType::Quad8);
  EXPECT_NEAR(cell_measure(mesh, 0), 2.0, 1e-14);
  EXPECT_EQ(mesh.cell_groups.at("GM3"), std::vector<int>{0});
  EXPECT_EQ(mesh.cell_groups.at("GM4"), std::vector<int>{1});
}

std::string gmsh_error_of(const std::string& text) {
  try {
    read_gmsh_text(text, "bad.msh");
  } catch (const DeckError& e) {
    return e.what();
  }
  return "(no DeckError)";
}

TEST(Gmsh, ErrorsAreDeckErrors) {
  const std::string good = file22(17, gmsh_hexa20());
  EXPECT_NE(gmsh_error_of("$MeshFormat\n2.2 1 8\n$EndMeshFormat\n").find("binary"), std::string::npos);
  EXPECT_NE(gmsh_error_of("$MeshFormat\n3.0 0 8\n$EndMeshFormat\n").find("version"), std::string::npos);
  EXPECT_NE(gmsh_error_of("hello\n").find("not a Gmsh file"), std::string::npos);
  EXPECT_NE(gmsh_error_of("").find("bad.msh"), std::string::npos);
  for (size_t cut : {good.size() / 4, good.size() / 2, good.size() - 20})
    EXPECT_NE(gmsh_error_of(good.substr(0, cut)).find("bad.msh"), std::string::npos) << cut;
  std::string unknown_node = good;
  unknown_node.replace(unknown_node.find("5 15 2 7 1 101"), 14, "5 15 2 7 1 999");
  EXPECT_NE(gmsh_error_of(unknown_node).find("unknown node 999"), std::string::npos);
  std::string quad9 = good;
  quad9.replace(quad9.find("9 17 2"), 6, "9 10 2");
  EXPECT_NE(gmsh_error_of(quad9).find("unsupported element type 10"), std::string::npos);
  EXPECT_THROW(read_gmsh("/nonexistent/file.msh"), DeckError);
}

TEST(Gmsh, MirroredTetraIsReorientedAndATangledQuadIsNamed) {
  // A VTK-ordered tetra written as a Gmsh tetra (nodes 2 and 3 swapped) is the
  // mirror image of a valid one: read as such, then reoriented by orient_cells.
  const std::string mirrored =
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 0 1 0\n3 1 0 0\n4 0 0 1\n$EndNodes\n"
      "$Elements\n1\n77 4 0 1 2 3 4\n$EndElements\n";
  Mesh mesh = read_gmsh_text(mirrored, "tet.msh");
  EXPECT_NEAR(cell_measure(mesh, 0), -1.0 / 6.0, 1e-14);
  EXPECT_EQ(inverted_cell_names(mesh), std::vector<std::string>{"M77"});
  EXPECT_EQ(orient_cells(mesh, "tet.msh"), std::vector<int>{0});
  EXPECT_NEAR(cell_measure(mesh, 0), 1.0 / 6.0, 1e-14);
  EXPECT_TRUE(find_inverted_cells(mesh).empty());
  // A 4.1 file with a bow-tie QUAD4 (nodes 1 2 4 3 of a unit square): no node
  // order makes it valid, so orient_cells names the file and the cell.
  const std::string tangled =
      "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 4 1 4\n2 1 0 4\n1\n2\n3\n4\n"
      "0 0 0\n1 0 0\n1 1 0\n0 1 0\n$EndNodes\n$Elements\n1 1 8 8\n2 1 3 1\n8 1 2 4 3\n$EndElements\n";
  Mesh bow_tie = read_gmsh_text(tangled, "bow_tie.msh");
  const Mesh before = bow_tie;
  try {
    orient_cells(bow_tie, "bow_tie.msh");
    ADD_FAILURE() << "no error for a bow-tie QUAD4";
  } catch (const DeckError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("mesh file 'bow_tie.msh': 1 tangled or degenerate cell(s)"), std::string::npos) << msg;
    EXPECT_NE(msg.find("M8 (QUAD4)"), std::string::npos) << msg;
  }
  EXPECT_EQ(bow_tie.cell_nodes, before.cell_nodes);
}

TEST(Gmsh, WriterRoundTripsEveryCellTypeInBothVersions) {
  Mesh mesh;
  double shift = 0.0;
  for (CellType t : testing::all_cell_types()) {
    const int c = testing::add_reference_cell(mesh, t, {shift, 0.0, 0.5});
    shift += 2.0;
    mesh.add_to_cell_group(std::string(cell_info(t).name) + "_CELLS", {c});
  }
  mesh.add_to_node_group("FIRST", {0, 1, 2});
  mesh.detect_dimension();
  const std::string dir = testing::scratch_dir("gmsh_writer");
  for (const std::string version : {"2.2", "4.1"}) {
    Mesh copy = mesh;
    if (version == "4.1") copy.add_to_cell_group("ALSO_HEXA", {copy.cell_groups.at("HEXA20_CELLS")});
    const std::string path = dir + "/all" + version + ".msh";
    tools::write_gmsh(path, copy, version);
    const Mesh back = read_gmsh(path);
    EXPECT_EQ(back.dim, 3);
    ASSERT_EQ(back.n_nodes(), copy.n_nodes()) << version;
    for (size_t k = 0; k < copy.coords.size(); ++k) EXPECT_EQ(back.coords[k], copy.coords[k]) << version;
    // the node group comes back as point elements after the cells
    ASSERT_EQ(back.n_cells(), copy.n_cells() + 3) << version;
    for (int c = 0; c < copy.n_cells(); ++c) {
      EXPECT_EQ(back.cell_names[c], "M" + std::to_string(c + 1));
      ASSERT_EQ(back.cell_types[c], copy.cell_types[c]) << version;
      for (int k = 0; k < copy.cell_n_nodes(c); ++k) EXPECT_EQ(back.cell(c)[k], copy.cell(c)[k]) << version;
    }
    for (const auto& [name, cells] : copy.cell_groups) EXPECT_EQ(back.cell_groups.at(name), cells) << name;
    EXPECT_EQ(back.node_groups.at("FIRST"), (std::vector<int>{0, 1, 2})) << version;
    EXPECT_EQ(back.node_names[4], "N5");
  }
  // a cell in two groups cannot be written in 2.2
  Mesh twice = mesh;
  twice.add_to_cell_group("ALSO_HEXA", {twice.cell_groups.at("HEXA20_CELLS")});
  EXPECT_THROW(tools::write_gmsh(dir + "/twice.msh", twice, "2.2"), DeckError);
  EXPECT_THROW(tools::write_gmsh(dir + "/v3.msh", mesh, "3.0"), DeckError);
}

TEST(Gmsh, MirroredSceneIsTheSameSceneInTheOtherOrientation) {
  // tools::mirror_cell_groups, used to write the clockwise test meshes: the
  // lower block clockwise with its boundary edges along the clockwise loop.
  tools::Ssnp121Options2d opt;
  opt.upper = tools::parse_block_cells("quad4:2", 2);
  opt.lower = tools::parse_block_cells("tria6:2", 2);
  const Mesh ccw = tools::make_ssnp121_2d(opt);
  Mesh cw = ccw;
  tools::mirror_cell_groups(cw, {"PLAQUE2"});
  EXPECT_EQ(cw.coords, ccw.coords);
  EXPECT_EQ(cw.cell_groups, ccw.cell_groups);
  EXPECT_EQ(find_inverted_cells(cw), ccw.cell_groups.at("PLAQUE2"));
  for (int c : ccw.cell_groups.at("PLAQUE2")) EXPECT_NEAR(cell_measure(cw, c), -cell_measure(ccw, c), 1e-15);
  for (int c : ccw.cell_groups.at("EF")) EXPECT_LT(boundary_normal(cw, c)[1], 0.0) << "EF runs along the loop";
  for (int c : ccw.cell_groups.at("AB")) EXPECT_EQ(boundary_normal(cw, c), boundary_normal(ccw, c));
  EXPECT_THROW(tools::mirror_cell_groups(cw, {"EF"}), DeckError);
  EXPECT_THROW(tools::mirror_cell_groups(cw, {"NOPE"}), DeckError);
  // written and read back in Gmsh 2.2, then oriented: the counter-clockwise cells again
  const std::string path = testing::scratch_dir("gmsh_mirror") + "/cw.msh";
  tools::write_gmsh(path, cw, "2.2");
  Mesh back = read_gmsh(path);
  EXPECT_EQ(orient_cells(back, path), ccw.cell_groups.at("PLAQUE2"));
  for (int c : ccw.cell_groups.at("PLAQUE2"))
    for (int k = 0; k < ccw.cell_n_nodes(c); ++k) EXPECT_EQ(back.cell(c)[k], ccw.cell(c)[k]);
}

}  // namespace
}  // namespace lunaster::engine
