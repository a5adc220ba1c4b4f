// MED write -> read round trips, results, and error handling of the reader/writer.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <algorithm>

#include "engine/core/error.hpp"
#include "engine/io/med_reader.hpp"
#include "engine/io/med_writer.hpp"
#include "engine/mesh/orientation.hpp"
#include "test_helpers.hpp"
#include "tools/ssnp121_mesh.hpp"

namespace lunaster::engine {
namespace {

namespace fs = std::filesystem;

/// Expects `b` to hold the same nodes, cells (matched by name), names and groups as `a`.
void expect_same_mesh(const Mesh& a, const Mesh& b) {
  ASSERT_EQ(a.n_nodes(), b.n_nodes());
  ASSERT_EQ(a.n_cells(), b.n_cells());
  EXPECT_EQ(a.dim, b.dim);
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.node_names, b.node_names);
  for (size_t k = 0; k < a.coords.size(); ++k) EXPECT_DOUBLE_EQ(a.coords[k], b.coords[k]);
  std::vector<int> b_of_a(a.n_cells());
  for (int c = 0; c < a.n_cells(); ++c) {
    const int d = b.find_cell(a.cell_names[c]);
    ASSERT_GE(d, 0) << a.cell_names[c];
    b_of_a[c] = d;
    ASSERT_EQ(a.cell_types[c], b.cell_types[d]);
    for (int k = 0; k < a.cell_n_nodes(c); ++k) EXPECT_EQ(a.cell(c)[k], b.cell(d)[k]);
  }
  EXPECT_EQ(a.node_groups, b.node_groups);
  ASSERT_EQ(a.cell_groups.size(), b.cell_groups.size());
  for (const auto& [name, cells] : a.cell_groups) {
    ASSERT_TRUE(b.cell_groups.count(name)) << name;
    std::vector<int> mapped;
    for (int c : cells) mapped.push_back(b_of_a[c]);
    std::sort(mapped.begin(), mapped.end());
    EXPECT_EQ(mapped, b.cell_groups.at(name)) << name;
  }
}

TEST(MedIo, RoundTripOfEveryCellTypeWithGroupsAndNames) {
  Mesh mesh;
  mesh.name = "ALLTYPES";
  double shift = 0.0;
  // 3D cells first, then lower-dimensional ones: the file order differs from this one
  for (auto it = testing::all_cell_types().rbegin(); it != testing::all_cell_types().rend(); ++it) {
    const int c = testing::add_reference_cell(mesh, *it, {shift, 0.0, 0.5});
    mesh.cell_names[c] = "C_" + std::string(cell_info(*it).name);
    shift += 2.0;
    mesh.add_to_cell_group(cell_info(*it).order == 2 ? "QUADRATIC" : "LINEAR", {c});
    if (cell_info(*it).dim == 3) mesh.add_to_cell_group("VOLUMES", {c});
  }
  mesh.node_names[0] = "TOP_NODE";
  mesh.add_to_node_group("FIRST", {0, 1, 2});
  mesh.add_to_node_group("SECOND", {2, 3});  // node 2 in two groups: one family lists both
  mesh.add_to_cell_group("A_VERY_LONG_GROUP_NAME_OF_SEVENTY_CHARACTERS_XXXXXXXXXXXXXXXXXXXXXXXXXXXXX", {0});
  mesh.detect_dimension();
  ASSERT_EQ(mesh.dim, 3);
  const std::string path = testing::scratch_dir("roundtrip") + "/all.med";
  write_med(path, mesh);
  const Mesh back = read_med(path);
  expect_same_mesh(mesh, back);
  // cells are numbered type by type in the fixed MED order
  for (int c = 1; c < back.n_cells(); ++c)
    EXPECT_LT(med_type_rank(back.cell_types[c - 1]), med_type_rank(back.cell_types[c]));
  EXPECT_EQ(med_mesh_names(path), std::vector<std::string>{"ALLTYPES"});
  EXPECT_EQ(read_med(path, "ALLTYPES").n_nodes(), mesh.n_nodes());
}

TEST(MedIo, RoundTripOfGeneratedMeshes2dAnd3d) {
  const std::string dir = testing::scratch_dir("generated");
  tools::Ssnp121Options2d o2;
  o2.upper = tools::parse_block_cells("quad4:3", 2);
  o2.lower = tools::parse_block_cells("tria6:2", 2);
  const Mesh m2 = tools::make_ssnp121_2d(o2);
  write_med(dir + "/m2.med", m2);
  const Mesh b2 = read_med(dir + "/m2.med");
  EXPECT_EQ(b2.dim, 2);
  expect_same_mesh(m2, b2);
  tools::Ssnp121Options3d o3;
  o3.v1 = tools::parse_block_cells("penta15:2x2x1", 3);
  o3.v2 = tools::parse_block_cells("tetra10:1x1x1", 3);
  const Mesh m3 = tools::make_ssnp121_3d(o3);
  write_med(dir + "/m3.med", m3);
  expect_same_mesh(m3, read_med(dir + "/m3.med"));
}

TEST(MedIo, NamesDefaultToFileOrderWhenAbsent) {
  // names written by the writer are read back; default names follow file order
  Mesh mesh;
  testing::add_reference_cell(mesh, CellType::Quad4);
  testing::add_reference_cell(mesh, CellType::Seg2, {0, 2, 0});
  mesh.detect_dimension();
  EXPECT_EQ(mesh.cell_names, (std::vector<std::string>{"M1", "M2"}));
  const std::string path = testing::scratch_dir("names") + "/n.med";
  write_med(path, mesh);
  const Mesh back = read_med(path);
  EXPECT_EQ(back.cell_types[0], CellType::Seg2);  // SEG2 comes before QUAD4 in the file
  EXPECT_EQ(back.cell_names[0], "M2");
  EXPECT_EQ(back.find_cell("M1"), 1);
}

TEST(MedIo, ResultFieldsRoundTrip) {
  Mesh mesh;
  testing::add_reference_cell(mesh, CellType::Quad4);
  testing::add_reference_cell(mesh, CellType::Quad4, {2, 0, 0});
  mesh.detect_dimension();
  std::vector<ResultStep> steps(2);
  for (int s = 0; s < 2; ++s) {
    steps[s].nume_ordre = s;
    steps[s].inst = 0.5 * s;
    NodalField depl({"DX", "DY", "LAGS_C"}, mesh.n_nodes());
    for (int n = 0; n < mesh.n_nodes(); ++n) {
      depl.set(n, 0, 0.1 * n + s);
      depl.set(n, 1, -0.2 * n);
      if (n < 2) depl.set(n, 2, -1e5 * (s + 1));
      else depl.values[n * 3 + 2] = 123.0;  // undefined: must be written as 0
    }
    steps[s].nodal["DEPL"] = depl;
    ElnoField sig;
    sig.components = {"SIXX", "SIYY"};
    sig.cell_offsets = {0, 4, 4};  // only the first cell carries values: a profile is written
    for (int r = 0; r < 4; ++r) {
      sig.values.push_back(r + 10.0 * s);
      sig.values.push_back(-r);
    }
    steps[s].elno["SIGM_ELNO"] = sig;
  }
  const std::string path = testing::scratch_dir("result") + "/r.med";
  write_med(path, mesh, {{"RESU", &steps}});
  const auto names = med_field_names(path);
  EXPECT_NE(std::find(names.begin(), names.end(), "RESU____DEPL"), names.end());
  EXPECT_NE(std::find(names.begin(), names.end(), "RESU____SIGM_ELNO"), names.end());
  const auto read = read_med_nodal_field(path, "RESU____DEPL");
  ASSERT_EQ(read.size(), 2u);
  for (int s = 0; s < 2; ++s) {
    EXPECT_EQ(read[s].numdt, s);
    EXPECT_DOUBLE_EQ(read[s].time, 0.5 * s);
    EXPECT_EQ(read[s].field.components, (std::vector<std::string>{"DX", "DY", "LAGS_C"}));
    for (int n = 0; n < mesh.n_nodes(); ++n) {
      EXPECT_DOUBLE_EQ(read[s].field.value(n, 0), 0.1 * n + s);
      EXPECT_DOUBLE_EQ(read[s].field.value(n, 1), -0.2 * n);
      EXPECT_DOUBLE_EQ(read[s].field.value(n, 2), n < 2 ? -1e5 * (s + 1) : 0.0);
    }
  }
  EXPECT_THROW(read_med_nodal_field(path, "RESU____NOPE"), DeckError);
  EXPECT_EQ(med_field_name("LONGRESULT", "DEPL"), "LONGRESULT_DEPL");
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const DeckError& e) {
    return e.what();
  }
  return "(no DeckError)";
}

TEST(MedIo, ReaderErrorsAreDeckErrorsNamingTheProblem) {
  const std::string dir = testing::scratch_dir("errors");
  EXPECT_NE(error_of([&] { read_med(dir + "/missing.med"); }).find("no such file"), std::string::npos);
  { std::ofstream(dir + "/text.med") << "this is not HDF5\n"; }
  EXPECT_NE(error_of([&] { read_med(dir + "/text.med"); }).find("not a MED file"), std::string::npos);
  Mesh mesh;
  testing::add_reference_cell(mesh, CellType::Hexa8);
  mesh.detect_dimension();
  const std::string good = dir + "/good.med";
  write_med(good, mesh);
  const std::string msg = error_of([&] { read_med(good, "OTHER"); });
  EXPECT_NE(msg.find("no mesh named 'OTHER'"), std::string::npos);
  EXPECT_NE(msg.find("'MAIL'"), std::string::npos);
  // truncated copies of a real file: always a DeckError, never a crash
  const auto size = fs::file_size(good);
  for (double fraction : {0.1, 0.5, 0.9, 0.99}) {
    const std::string cut = dir + "/cut.med";
    fs::copy_file(good, cut, fs::copy_options::overwrite_existing);
    fs::resize_file(cut, static_cast<uintmax_t>(size * fraction));
    EXPECT_THROW(read_med(cut), DeckError) << fraction;
  }
}

TEST(MedIo, MirroredCellInFileIsReorientedAndATangledOneIsReportedByName) {
  Mesh mesh;
  const auto x = testing::reference_nodes(CellType::Tetra4);
  std::vector<int> nodes;
  for (const auto& p : x) nodes.push_back(mesh.add_node(p[0], p[1], p[2]));
  mesh.add_cell(CellType::Tetra4, {nodes[0], nodes[2], nodes[1], nodes[3]}, "VTKTET");  // VTK order
  mesh.detect_dimension();
  const std::string dir = testing::scratch_dir("inverted");
  write_med(dir + "/inv.med", mesh);
  Mesh back = read_med(dir + "/inv.med");  // the reader keeps the file's order
  EXPECT_NEAR(cell_measure(back, 0), -1.0 / 6.0, 1e-14);
  EXPECT_EQ(orient_cells(back, dir + "/inv.med"), std::vector<int>{0});
  EXPECT_NEAR(cell_measure(back, 0), 1.0 / 6.0, 1e-14);
  EXPECT_EQ(back.cell(0)[0], nodes[0]);
  // a tetra with its apex in the plane of its base: collapsed, named with the file
  mesh.coords[3 * nodes[3] + 2] = 0.0;
  write_med(dir + "/flat.med", mesh);
  Mesh flat = read_med(dir + "/flat.med");
  const std::string msg = error_of([&] { orient_cells(flat, dir + "/flat.med"); });
  EXPECT_NE(msg.find("VTKTET (TETRA4)"), std::string::npos) << msg;
  EXPECT_NE(msg.find("flat.med"), std::string::npos) << msg;
  EXPECT_NE(msg.find("tangled or degenerate"), std::string::npos) << msg;
}

TEST(MedIo, FailedWriteLeavesTheOldFileInPlace) {
  const std::string dir = testing::scratch_dir("atomic");
  Mesh mesh;
  testing::add_reference_cell(mesh, CellType::Quad4);
  mesh.detect_dimension();
  const std::string path = dir + "/keep.med";
  write_med(path, mesh);
  const auto before = fs::file_size(path);
  Mesh bad = mesh;
  bad.node_names[0] = "A_NODE_NAME_LONGER_THAN_16";
  EXPECT_THROW(write_med(path, bad), DeckError);
  EXPECT_EQ(fs::file_size(path), before);
  EXPECT_EQ(read_med(path).node_names[0], "N1");
  for (const auto& entry : fs::directory_iterator(dir))  // no temporary left behind
    EXPECT_EQ(entry.path().filename(), "keep.med");
  EXPECT_THROW(write_med(dir + "/no/such/folder/x.med", mesh), DeckError);
}

}  // namespace
}  // namespace lunaster::engine
