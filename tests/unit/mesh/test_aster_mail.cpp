// code_aster text meshes (.mail): every supported cell type in code_aster's node order
// converted to MED's, names and groups, the format's variants, errors with their line.
#include <gtest/gtest.h>

#include <sstream>

#include "engine/core/error.hpp"
#include "engine/io/aster_mail_reader.hpp"
#include "engine/mesh/orientation.hpp"
#include "test_helpers.hpp"
#include "tools/aster_mail_writer.hpp"

namespace lunaster::engine {
namespace {

using Vec3 = std::array<double, 3>;

/// A reference cell in code_aster's numbering (code_aster's documentation of its cells,
/// R3.01.01): the base counter-clockwise seen from the top for the 3D cells, then the
/// mid-side nodes edge by edge.
struct AsterCell {
  const char* name;
  CellType type;
  std::vector<Vec3> vertices;
  std::vector<std::pair<int, int>> edges;  ///< mid-side nodes, 0-based vertex pairs
};

std::vector<AsterCell> aster_cells() {
  const std::vector<Vec3> seg{{0, 0, 0}, {1, 0, 0}}, tri{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
      quad{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, tet{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
      pyr{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 1}},
      pen{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}},
      hex{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  return {
      {"POI1", CellType::Point1, {{0, 0, 0}}, {}},
      {"SEG2", CellType::Seg2, seg, {}},
      {"SEG3", CellType::Seg3, seg, {{0, 1}}},
      {"TRIA3", CellType::Tria3, tri, {}},
      {"TRIA6", CellType::Tria6, tri, {{0, 1}, {1, 2}, {2, 0}}},
      {"QUAD4", CellType::Quad4, quad, {}},
      {"QUAD8", CellType::Quad8, quad, {{0, 1}, {1, 2}, {2, 3}, {3, 0}}},
      {"TETRA4", CellType::Tetra4, tet, {}},
      {"TETRA10", CellType::Tetra10, tet, {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}}},
      {"PYRAM5", CellType::Pyram5, pyr, {}},
      {"PENTA6", CellType::Penta6, pen, {}},
      {"PENTA15", CellType::Penta15, pen,
       {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 4}, {2, 5}, {3, 4}, {4, 5}, {5, 3}}},
      {"HEXA8", CellType::Hexa8, hex, {}},
      {"HEXA20", CellType::Hexa20, hex,
       {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 5}, {2, 6}, {3, 7}, {4, 5}, {5, 6}, {6, 7}, {7, 4}}},
  };
}

/// One .mail file holding one cell of the type, nodes named A1.., the cell C<type>; the cell's
/// node names are written four to a line, as code_aster's files wrap long cells.
std::string one_cell_file(const AsterCell& c) {
  std::vector<Vec3> nodes = c.vertices;
  for (const auto& [a, b] : c.edges)
    nodes.push_back({0.5 * (nodes[a][0] + nodes[b][0]), 0.5 * (nodes[a][1] + nodes[b][1]),
                     0.5 * (nodes[a][2] + nodes[b][2])});
  std::ostringstream os;
  os << "TITRE\n one " << c.name << "\nFINSF\n%\nCOOR_3D\n";
  for (size_t k = 0; k < nodes.size(); ++k)
    os << "  A" << k + 1 << "  " << nodes[k][0] << " " << nodes[k][1] << " " << nodes[k][2] << "\n";
  os << "FINSF\n" << c.name << "\n  C" << c.name;
  for (size_t k = 0; k < nodes.size(); ++k) os << (k && k % 4 == 0 ? "\n     " : " ") << "A" << k + 1;
  os << "\nFINSF\nFIN\n";
  return os.str();
}

TEST(AsterMail, EveryCellTypeIsConvertedToMedOrder) {
  for (const auto& c : aster_cells()) {
    SCOPED_TRACE(c.name);
    const Mesh mesh = read_aster_mail_text(one_cell_file(c), "one.mail");
    ASSERT_EQ(mesh.n_cells(), 1);
    EXPECT_EQ(mesh.cell_types[0], c.type);
    EXPECT_EQ(mesh.cell_names[0], std::string("C") + c.name);
    // The MED reference cell node by node (mid-side nodes included).
    const auto expected = testing::reference_nodes(c.type);
    ASSERT_EQ(static_cast<int>(expected.size()), mesh.cell_n_nodes(0));
    for (int k = 0; k < mesh.cell_n_nodes(0); ++k) {
      const int n = mesh.cell(0)[k];
      EXPECT_NEAR(mesh.coords[3 * n], expected[k][0], 1e-12) << "node " << k;
      EXPECT_NEAR(mesh.coords[3 * n + 1], expected[k][1], 1e-12) << "node " << k;
      EXPECT_NEAR(mesh.coords[3 * n + 2], expected[k][2], 1e-12) << "node " << k;
    }
    if (cell_info(c.type).dim == 3) {
      EXPECT_GT(cell_measure(mesh, 0), 0.0);
    }
  }
}

TEST(AsterMail, NamesGroupsAndTheFormatsVariants) {
  const std::string text =
      "TITRE    NOM=PATCH\n"
      "         AUTEUR= SOMEONE  DATE=01/01/26\n"
      "a title line\n"
      "FINSF\n"
      "% a comment line\n"
      "coor_2d    NOM=\n"
      "  NO1  0.0  0.0   % a comment after the node\n"
      "  NO2  2.0D0 0.0\n"
      "  NO3  2.0  1.0E+00\n"
      "  NO4  0.0  1.0\n"
      "  NO5  3.0  1.0\n"
      "finsf\n"
      "QUAD4   NOM=INDEFINI   NBOBJ=1\n"
      "        AUTEUR=X       DATE=08/07/**\n"
      "  Q1  NO1 NO2 NO3 NO4\n"
      "FINSF\n"
      "SEG2\n"
      "  S1 = NO1 NO2\n"
      "  S2 , NO3 NO5\n"
      "FINSF\n"
      "FINSF\n"
      "GROUP_MA NOM = BAS\n S1\nFINSF\n"
      "GROUP_MA\n  ALL\n  Q1 S1\n  S2\nFINSF\n"
      "GROUP_NO   COINS\n NO1 NO3 NO1\nFINSF\n"
      "GROUP_NO NOM=VIDE\nFINSF\n"
      "FIN\n"
      "anything after FIN is not read\n";
  const Mesh mesh = read_aster_mail_text(text, "patch.mail");
  EXPECT_EQ(mesh.dim, 2);
  ASSERT_EQ(mesh.n_nodes(), 5);
  EXPECT_EQ(mesh.node_names[1], "NO2");
  EXPECT_DOUBLE_EQ(mesh.coords[3 * 1], 2.0);
  EXPECT_DOUBLE_EQ(mesh.coords[3 * 2 + 1], 1.0);
  ASSERT_EQ(mesh.n_cells(), 3);
  EXPECT_EQ(mesh.cell_names, (std::vector<std::string>{"Q1", "S1", "S2"}));
  EXPECT_NEAR(cell_measure(mesh, 0), 2.0, 1e-14);
  EXPECT_EQ(mesh.cell_groups.at("BAS"), std::vector<int>{1});
  EXPECT_EQ(mesh.cell_groups.at("ALL"), (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(mesh.node_groups.at("COINS"), (std::vector<int>{0, 2}));
  EXPECT_TRUE(mesh.node_groups.at("VIDE").empty());
}

TEST(AsterMail, FinClosesAnOpenBlockAsInCodeAster) {
  const Mesh mesh =
      read_aster_mail_text("COOR_3D\n P1 0 0 0\n P2 1 0 0\nFINSF\nPOI1\n E1 P1\n E2 P2\nFIN\n", "points.mail");
  EXPECT_EQ(mesh.n_cells(), 2);
}

TEST(AsterMail, WriterRoundTripsEveryCellTypeWithNamesAndGroups) {
  const std::string dir = ::testing::TempDir();
  for (const auto& c : aster_cells()) {
    SCOPED_TRACE(c.name);
    Mesh mesh;
    for (const auto& x : testing::reference_nodes(c.type)) mesh.add_node(x[0], x[1], x[2] + 0.25, {});
    std::vector<int> nodes(static_cast<size_t>(mesh.n_nodes()));
    for (int k = 0; k < mesh.n_nodes(); ++k) nodes[k] = k;
    mesh.add_cell(c.type, nodes, "CELL1");
    mesh.add_to_cell_group("ALL", {0});
    mesh.add_to_node_group("ENDS", {0, mesh.n_nodes() - 1});
    mesh.detect_dimension();
    const std::string path = dir + "/round.mail";
    tools::write_aster_mail(path, mesh);
    const Mesh back = read_aster_mail(path);
    EXPECT_EQ(back.coords, mesh.coords);
    EXPECT_EQ(back.cell_nodes, mesh.cell_nodes);
    EXPECT_EQ(back.node_names, mesh.node_names);
    EXPECT_EQ(back.cell_names, mesh.cell_names);
    EXPECT_EQ(back.cell_groups, mesh.cell_groups);
    EXPECT_EQ(back.node_groups, mesh.node_groups);
  }
  Mesh bad;
  bad.add_node(0, 0, 0, "A NODE");
  bad.add_cell(CellType::Point1, {0}, "P");
  EXPECT_THROW(tools::write_aster_mail(dir + "/bad.mail", bad), DeckError);
}

std::string mail_error_of(const std::string& text) {
  try {
    read_aster_mail_text(text, "bad.mail");
  } catch (const DeckError& e) {
    return e.what();
  }
  return "(no DeckError)";
}

TEST(AsterMail, ErrorsNameTheFileAndLine) {
  const std::string nodes = "COOR_2D\n N1 0 0\n N2 1 0\n N3 1 1\n N4 0 1\nFINSF\n";  // lines 1-6
  auto expect = [](const std::string& text, const std::string& what) {
    const std::string message = mail_error_of(text);
    EXPECT_NE(message.find("'bad.mail'"), std::string::npos) << message;
    EXPECT_NE(message.find(what), std::string::npos) << message;
  };
  expect(nodes + "QUAD5\n M1 N1 N2 N3 N4\nFINSF\nFIN\n", "line 7: unknown block 'QUAD5'");
  expect(nodes + "QUAD9\n M1 N1 N2 N3 N4\nFINSF\nFIN\n", "line 7: cell type QUAD9 is not supported");
  expect(nodes + "QUAD4\n M1 N1 N2 N3\n M2 N1 N2 N3 N4\nFINSF\nFIN\n",
         "line 8: cell 'M1': QUAD4 takes 4 nodes, line 8 gives 3 (then 'M2' of line 9 was read as its node)");
  expect(nodes + "QUAD4\n M1 N1 N2 N3\n M2\nFINSF\nFIN\n",
         "line 9: cell 'M1' (QUAD4, line 8) refers to unknown node 'M2' (a QUAD4 takes 4 nodes: too few on its line?)");
  expect(nodes + "TRIA3\n M1 N1 N2 N3 N4\nFINSF\nFIN\n", "line 8: 'N4' does not start a line: TRIA3 takes 3 nodes");
  expect(nodes + "TRIA3\n M1 N1 N2\nFINSF\nFIN\n", "line 8: cell 'M1': TRIA3 takes 3 nodes, 2 given");
  expect(nodes + "TRIA3\n M1 N1 N2 N9\nFINSF\nFIN\n", "line 8: cell 'M1' (TRIA3, line 8) refers to unknown node 'N9'");
  expect(nodes + "COOR_2D\n N2 5 5\nFINSF\nSEG2\n S N1 N2\nFINSF\nFIN\n",
         "line 8: node 'N2' defined twice (first at line 3)");
  expect(nodes + "SEG2\n S N1 N2\n S N2 N3\nFINSF\nFIN\n", "line 9: cell 'S' defined twice (first at line 8)");
  expect(nodes + "SEG2\n S N1 N2\nGROUP_MA\n G S\nFINSF\nFIN\n",
         "line 9: SEG2 block opened at line 7 has no FINSF before 'GROUP_MA'");
  expect(nodes + "SEG2\n S N1 N2\n", "line 7: SEG2 block has no FINSF (the file ends inside it)");
  expect(nodes + "SEG2\n S N1 N2\nFINSF\n", "no FIN at the end of the file");
  expect(nodes + "SEG2\n S N1 N2\nFINSF\nGROUP_MA\n G S T\nFINSF\nFIN\n",
         "line 11: GROUP_MA 'G' (line 10) names unknown cell 'T'");
  expect(nodes + "SEG2\n S N1 N2\nFINSF\nGROUP_NO NOM=G\n N1 S\nFINSF\nFIN\n",
         "line 11: GROUP_NO 'G' (line 10) names unknown node 'S'");
  expect("COOR_2D\n N1 0 zero\nFINSF\nFIN\n", "line 2: node 'N1': coordinate 'zero' is not a number");
  expect("COOR_3D\n N1 0 0\n N2 0 0 0\nFINSF\nFIN\n", "line 2: node 'N1': COOR_3D takes 3 coordinates, 2 given");
  expect(nodes + "FIN\n", "no cell");
  expect("", "no FIN");
  EXPECT_THROW(read_aster_mail("/nonexistent/file.mail"), DeckError);
  // Every truncation of a good file is a DeckError naming the file, never a crash (but for a cut
  // inside FINSF that leaves FIN, which closes the block and the file).
  const std::string good = nodes + "QUAD4\n M1 N1 N2 N3 N4\nFINSF\nGROUP_MA NOM=G\n M1\nFINSF\nFIN\n";
  for (size_t cut = 0; cut + 4 < good.size(); ++cut) {
    if (cut >= 3 && good.compare(cut - 3, 3, "FIN") == 0) continue;
    const std::string message = mail_error_of(good.substr(0, cut));
    EXPECT_NE(message.find("'bad.mail'"), std::string::npos) << cut << ": " << message;
  }
}

}  // namespace
}  // namespace lunaster::engine
