// Inverted-cell detection, reorientation of clockwise / mirrored cells
// (orient_cells) and ORIE_PEAU outward orientation of boundary cells.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

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

/// The number of `facing` entries on each side: outward, inward, inner, loose.
std::array<int, 4> sides(const std::vector<BoundaryFacing>& facing) {
  std::array<int, 4> n{0, 0, 0, 0};
  for (const BoundaryFacing& f : facing) ++n[static_cast<int>(f.side)];
  return n;
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

TEST(Orientation, AThirdBlockIsMeshedApartWithOutwardFacesOnBothItsInterfaces) {
  // 2D: PLAQUE3 on the upper block, its own nodes on y = 1 (IJ faces down, CD up).
  tools::Ssnp121Options2d o2;
  o2.top = tools::parse_block_cells("tria6:3", 2);
  Mesh m2 = tools::make_ssnp121_2d(o2);
  EXPECT_EQ(m2.cell_groups.at("PLAQUE3").size(), 18u);
  const auto ij = m2.cell_groups.at("IJ"), cd = m2.cell_groups.at("CD"), kl = m2.cell_groups.at("KL");
  EXPECT_EQ(ij.size(), 3u);
  for (int c : ij) EXPECT_GT(dot(boundary_normal(m2, c), {0, -1, 0}), 0.0);
  for (int c : kl) EXPECT_GT(dot(boundary_normal(m2, c), {0, 1, 0}), 0.0);
  EXPECT_EQ(orient_boundary_outward(m2, ij), 0);
  const int i = m2.node_groups.at("I")[0], d = m2.node_groups.at("D")[0], p = m2.node_groups.at("P")[0];
  EXPECT_NE(i, d);  // same place (-1, 1), two bodies
  EXPECT_EQ(m2.node(i)[0], m2.node(d)[0]);
  EXPECT_EQ(m2.node(i)[1], 1.0);
  EXPECT_NEAR(m2.node(p)[0], 0.0, 1e-15);  // a mid-side node here: the mean of -1/3 and 1/3
  for (int c : cd)
    for (int a = 0; a < m2.cell_n_nodes(c); ++a)
      for (int e : ij)
        for (int b = 0; b < m2.cell_n_nodes(e); ++b) EXPECT_NE(m2.cell(c)[a], m2.cell(e)[b]);
  // 3D: V3 on V2, SURBA3 facing down, SURCH3 up; no third block unless asked.
  tools::Ssnp121Options3d o3;
  o3.v2 = tools::parse_block_cells("hexa8:1x1x1", 3);
  o3.v3 = tools::parse_block_cells("penta6:2x2x1", 3);
  Mesh m3 = tools::make_ssnp121_3d(o3);
  EXPECT_EQ(m3.cell_groups.at("V3").size(), 8u);
  for (int c : m3.cell_groups.at("SURBA3")) EXPECT_GT(dot(boundary_normal(m3, c), {0, 0, -1}), 0.0);
  for (int c : m3.cell_groups.at("SURCH3")) EXPECT_GT(dot(boundary_normal(m3, c), {0, 0, 1}), 0.0);
  EXPECT_EQ(m3.node(m3.node_groups.at("A33")[0])[2], 2.0);
  EXPECT_EQ(tools::make_ssnp121_3d(tools::Ssnp121Options3d{}).cell_groups.count("V3"), 0u);
}

TEST(Orientation, OrientBoundaryOutward3dAllFaceTypes) {
  for (const char* v1 : {"hexa8:2x2x1", "hexa20:2x2x1", "penta6:2x2x1", "penta15:2x2x1", "tetra4:2x2x1", "tetra10:1x1x1"}) {
    tools::Ssnp121Options3d opt;
    opt.v1 = tools::parse_block_cells(v1, 3);
    opt.v2 = tools::parse_block_cells("hexa8:1x1x1", 3);
    Mesh mesh = tools::make_ssnp121_3d(opt);
    const auto esc = mesh.cell_groups.at("SURESC"), enc = mesh.cell_groups.at("ENCAST");
    EXPECT_EQ(sides(boundary_facing(mesh, esc))[0], static_cast<int>(esc.size())) << v1;
    reverse_cells(mesh, esc);
    reverse_cells(mesh, {enc[0]});
    // boundary_facing (which ORIE_PEAU reads) finds the reversed faces inward, and only those
    const auto facing = boundary_facing(mesh, enc);
    EXPECT_EQ(facing[0].side, BoundarySide::Inward) << v1;
    EXPECT_EQ(sides(facing), (std::array<int, 4>{static_cast<int>(enc.size()) - 1, 1, 0, 0})) << v1;
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

TEST(Orientation, BoundaryFacingTellsInwardCellsOfEveryEdgeType2d) {
  // QUAD8 below (SEG3 edges), QUAD4 / TRIA3 / TRIA6 above (SEG2 / SEG3 edges): the generator's
  // edges face outward; reversed ones face inward, and ORIE_PEAU (which reads the same facing)
  // turns exactly those.
  for (const char* upper : {"quad4:4", "tria3:3", "tria6:2"}) {
    tools::Ssnp121Options2d opt;
    opt.lower = tools::parse_block_cells("quad8:5", 2);
    opt.upper = tools::parse_block_cells(upper, 2);
    Mesh mesh = tools::make_ssnp121_2d(opt);
    std::vector<int> edges;
    for (const char* g : {"AB", "BC", "CD", "DA", "EF", "FG", "GH", "HE"})
      for (int c : mesh.cell_groups.at(g)) edges.push_back(c);
    EXPECT_EQ(sides(boundary_facing(mesh, edges)), (std::array<int, 4>{static_cast<int>(edges.size()), 0, 0, 0}))
        << upper;
    const auto ab = mesh.cell_groups.at("AB"), ef = mesh.cell_groups.at("EF");
    reverse_cells(mesh, {ab[0], ab[1], ef[1]});
    const auto facing = boundary_facing(mesh, edges);
    EXPECT_EQ(sides(facing), (std::array<int, 4>{static_cast<int>(edges.size()) - 3, 3, 0, 0})) << upper;
    for (size_t i = 0; i < edges.size(); ++i) {
      const bool reversed = edges[i] == ab[0] || edges[i] == ab[1] || edges[i] == ef[1];
      EXPECT_EQ(facing[i].side, reversed ? BoundarySide::Inward : BoundarySide::Outward) << upper;
      EXPECT_EQ(facing[i].other, -1);
      EXPECT_EQ(cell_info(mesh.cell_types[facing[i].owner]).dim, 2);
    }
    EXPECT_EQ(orient_boundary_outward(mesh, edges), 3) << upper;
    EXPECT_EQ(sides(boundary_facing(mesh, edges))[1], 0) << upper;
  }
}

TEST(Orientation, BoundaryFacingOfInnerAndLooseCells) {
  tools::Ssnp121Options2d opt;
  opt.upper = opt.lower = tools::parse_block_cells("quad4:2", 2);
  opt.glued = true;
  Mesh mesh = tools::make_ssnp121_2d(opt);
  // glued interface: AB lies between a cell of each block, either way round
  const auto ab = mesh.cell_groups.at("AB");
  reverse_cells(mesh, {ab[0]});
  for (const BoundaryFacing& f : boundary_facing(mesh, ab)) {
    EXPECT_EQ(f.side, BoundarySide::Inner);
    EXPECT_GE(f.owner, 0);
    EXPECT_GE(f.other, 0);
    EXPECT_NE(f.owner, f.other);
  }
  // a segment across the domain, and a diagonal of a cell: no cell has it as an edge
  const int far = mesh.add_node(5, 5, 0);
  const int lost = mesh.add_cell(CellType::Seg2, {0, far}, "LOST");
  const int q = mesh.cell_groups.at("PLAQUE1")[0];
  const int diagonal = mesh.add_cell(CellType::Seg2, {mesh.cell(q)[0], mesh.cell(q)[2]}, "DIAGONAL");
  const auto facing = boundary_facing(mesh, {lost, diagonal});
  EXPECT_EQ(facing[0].side, BoundarySide::Loose);
  EXPECT_EQ(facing[0].owner, -1);
  EXPECT_EQ(facing[1].side, BoundarySide::Loose);
  EXPECT_EQ(facing[1].owner, q);
  EXPECT_THROW(boundary_facing(mesh, {q}), InternalError);
}

/// The reference cell of `type` under an affine map with no symmetry (so that
/// a wrong permutation cannot hide behind one; faces stay plane, so that
/// `cell_measure` is exact), shifted by `shift` along x.
int add_distorted_cell(Mesh& mesh, CellType type, double shift) {
  const double a[3][3] = {{1.1, 0.2, -0.1}, {0.15, 0.9, 0.25}, {-0.05, 0.1, 1.2}};
  const bool plane = cell_info(type).dim == 2;
  std::vector<int> nodes;
  for (const auto& p : testing::reference_nodes(type)) {
    double x[3] = {shift, 0.0, 0.0};
    for (int i = 0; i < (plane ? 2 : 3); ++i)
      for (int j = 0; j < (plane ? 2 : 3); ++j) x[i] += a[i][j] * p[j];
    nodes.push_back(mesh.add_node(x[0], x[1], x[2]));
  }
  return mesh.add_cell(type, nodes);
}

TEST(Orientation, MirrorPermutationIsAnInvolutionKeepingMidSideNodesOnTheirEdges) {
  for (CellType t : testing::all_cell_types()) {
    const CellInfo& info = cell_info(t);
    if (info.dim < 2) {
      EXPECT_THROW(cell_mirror_permutation(t), InternalError) << info.name;
      continue;
    }
    const auto& perm = cell_mirror_permutation(t);
    ASSERT_EQ(static_cast<int>(perm.size()), info.n_nodes) << info.name;
    EXPECT_EQ(perm[0], 0) << info.name;
    for (int k = 0; k < info.n_nodes; ++k) EXPECT_EQ(perm[perm[k]], k) << info.name;
    if (info.dim == 2) {
      EXPECT_EQ(perm, cell_reverse_permutation(t)) << info.name;
    }
    Mesh mesh;
    const int c = add_distorted_cell(mesh, t, 0.0);
    mesh.detect_dimension();
    const double measure = cell_measure(mesh, c);
    ASSERT_GT(measure, 0.0) << info.name;
    testing::permute_cell(mesh, c, perm);
    EXPECT_NEAR(cell_measure(mesh, c), -measure, 1e-14) << info.name;
    EXPECT_LT(testing::mid_side_offset(mesh, c), 1e-15) << info.name;
    EXPECT_EQ(find_inverted_cells(mesh), std::vector<int>{c}) << info.name;
    EXPECT_TRUE(find_tangled_cells(mesh).empty()) << info.name;
  }
}

TEST(Orientation, MirroredCellsOfEveryTypeAreReorientedToPositiveMeasure) {
  // Cells mirrored by a hand-written reflection (not the one orient_cells uses):
  // orient_cells gives a valid cell with the same vertices, the same measure and
  // its mid-side nodes on their edges, and leaves the valid cells alone.
  for (CellType t : testing::all_cell_types()) {
    const CellInfo& info = cell_info(t);
    if (info.dim < 2) continue;
    Mesh mesh;
    const int good = add_distorted_cell(mesh, t, 0.0);
    const int bad = add_distorted_cell(mesh, t, 3.0);
    const int boundary = mesh.add_cell(info.dim == 2 ? CellType::Seg2 : CellType::Tria3,
                                       info.dim == 2 ? std::vector<int>{mesh.cell(bad)[1], mesh.cell(bad)[0]}
                                                     : std::vector<int>{mesh.cell(bad)[0], mesh.cell(bad)[1], mesh.cell(bad)[2]});
    mesh.detect_dimension();
    const double measure = cell_measure(mesh, bad);
    const std::vector<int> good_nodes(mesh.cell(good), mesh.cell(good) + info.n_nodes);
    const std::vector<int> boundary_nodes(mesh.cell(boundary), mesh.cell(boundary) + mesh.cell_n_nodes(boundary));
    std::vector<int> vertices(mesh.cell(bad), mesh.cell(bad) + info.n_vertices);
    testing::permute_cell(mesh, bad, testing::hand_written_reflection(t));
    ASSERT_LT(testing::mid_side_offset(mesh, bad), 1e-15) << info.name << ": the test's reflection is wrong";
    ASSERT_NEAR(cell_measure(mesh, bad), -measure, 1e-13) << info.name;
    const std::vector<int> mirrored(mesh.cell(bad), mesh.cell(bad) + info.n_nodes);

    EXPECT_EQ(orient_cells(mesh, "m.med"), std::vector<int>{bad}) << info.name;
    EXPECT_NEAR(cell_measure(mesh, bad), measure, 1e-13) << info.name;
    EXPECT_LT(testing::mid_side_offset(mesh, bad), 1e-15) << info.name;
    EXPECT_TRUE(find_inverted_cells(mesh).empty()) << info.name;
    std::vector<int> after(mesh.cell(bad), mesh.cell(bad) + info.n_vertices);
    EXPECT_NE(std::vector<int>(mesh.cell(bad), mesh.cell(bad) + info.n_nodes), mirrored) << info.name;
    std::sort(vertices.begin(), vertices.end());
    std::sort(after.begin(), after.end());
    EXPECT_EQ(after, vertices) << info.name;
    EXPECT_EQ(std::vector<int>(mesh.cell(good), mesh.cell(good) + info.n_nodes), good_nodes) << info.name;
    EXPECT_EQ(std::vector<int>(mesh.cell(boundary), mesh.cell(boundary) + mesh.cell_n_nodes(boundary)), boundary_nodes)
        << info.name << ": boundary cells keep their own order";
    EXPECT_TRUE(orient_cells(mesh, "m.med").empty()) << info.name << ": a second pass changes nothing";
  }
}

std::string orient_error(Mesh& mesh) {
  try {
    orient_cells(mesh, "cells.msh");
  } catch (const DeckError& e) {
    return e.format();
  }
  return "(no DeckError)";
}

TEST(Orientation, TangledAndCollapsedCellsStillStopTheRun) {
  // bow-tie QUAD4 (self-intersecting), QUAD4 with a repeated node, flat TRIA3,
  // HEXA8 with a corner folded through a face, and their valid neighbours
  Mesh mesh;
  const int a = mesh.add_node(0, 0, 0), b = mesh.add_node(1, 0, 0), c = mesh.add_node(1, 1, 0), d = mesh.add_node(0, 1, 0);
  const int e = mesh.add_node(2, 0, 0);
  mesh.add_cell(CellType::Quad4, {a, b, c, d}, "GOOD");
  mesh.add_cell(CellType::Quad4, {a, b, d, c}, "BOWTIE");
  mesh.add_cell(CellType::Quad4, {a, b, c, c}, "REPEATED");
  mesh.add_cell(CellType::Tria3, {a, b, e}, "FLAT");
  mesh.add_cell(CellType::Quad4, {a, d, c, b}, "CLOCKWISE");
  mesh.detect_dimension();
  const Mesh before = mesh;
  const std::string msg = orient_error(mesh);
  EXPECT_NE(msg.find("mesh file 'cells.msh': 3 tangled or degenerate cell(s) (Jacobian zero or of both signs): "
                     "BOWTIE (QUAD4), REPEATED (QUAD4), FLAT (TRIA3)"),
            std::string::npos)
      << msg;
  EXPECT_NE(msg.find("no two of their corners are the same node or at the same point"), std::string::npos) << msg;
  EXPECT_EQ(mesh.cell_nodes, before.cell_nodes) << "nothing is reoriented when the run stops";
  EXPECT_EQ(find_tangled_cells(mesh), (std::vector<int>{1, 2, 3}));

  Mesh hexa;
  testing::add_reference_cell(hexa, CellType::Hexa8);
  hexa.detect_dimension();
  hexa.coords[3 * 6 + 0] = -0.5;  // node 6 (1,1,1) pulled through the x=0 face
  hexa.coords[3 * 6 + 1] = -0.5;
  EXPECT_NE(orient_error(hexa).find("1 tangled or degenerate cell(s)"), std::string::npos);
  // the same fold on a mirrored hexa is still tangled
  Mesh mirrored_fold = hexa;
  testing::permute_cell(mirrored_fold, 0, cell_mirror_permutation(CellType::Hexa8));
  EXPECT_NE(orient_error(mirrored_fold).find("1 tangled or degenerate cell(s)"), std::string::npos);
}

TEST(Orientation, OriePeauAfterReorientingAClockwiseBlockGivesOutwardNormals2d) {
  // The lower block meshed clockwise, as Gmsh does for a curve loop
  // (-1,0) -> (1,0) -> (1,-1) -> (-1,-1): every cell and every edge of the loop
  // reversed. orient_cells fixes the cells only; ORIE_PEAU then orients the
  // edges outward from the reoriented cells.
  tools::Ssnp121Options2d opt;
  opt.lower = tools::parse_block_cells("quad8:3", 2);
  opt.upper = tools::parse_block_cells("tria6:2", 2);
  Mesh mesh = tools::make_ssnp121_2d(opt);
  const auto& lower = mesh.cell_groups.at("PLAQUE2");
  for (int c : lower) testing::permute_cell(mesh, c, cell_reverse_permutation(mesh.cell_types[c]));
  for (const char* g : {"EF", "FG", "GH", "HE"}) reverse_cells(mesh, mesh.cell_groups.at(g));
  const auto ef = mesh.cell_groups.at("EF"), gh = mesh.cell_groups.at("GH");
  for (int c : ef) ASSERT_LT(dot(boundary_normal(mesh, c), {0, 1, 0}), 0.0);
  Mesh not_reoriented = mesh;  // what ORIE_PEAU would do on the clockwise cells
  EXPECT_EQ(orient_boundary_outward(not_reoriented, ef), 0);

  EXPECT_EQ(orient_cells(mesh, "lower_cw.msh"), lower);
  for (int c : lower) EXPECT_GT(cell_measure(mesh, c), 0.0);
  for (int c : ef) EXPECT_LT(dot(boundary_normal(mesh, c), {0, 1, 0}), 0.0) << "boundary cells keep their order";
  EXPECT_EQ(orient_boundary_outward(mesh, ef), static_cast<int>(ef.size()));
  EXPECT_EQ(orient_boundary_outward(mesh, gh), static_cast<int>(gh.size()));
  for (int c : ef) EXPECT_GT(dot(boundary_normal(mesh, c), {0, 1, 0}), 0.0);
  for (int c : gh) EXPECT_GT(dot(boundary_normal(mesh, c), {0, -1, 0}), 0.0);
  for (int c : ef) EXPECT_EQ(testing::mid_side_offset(mesh, c), 0.0);
}

TEST(Orientation, OriePeauAfterReorientingMirroredVolumesGivesOutwardNormals3d) {
  for (const char* v1 : {"hexa20:2x2x1", "penta15:2x2x1", "tetra10:1x1x1", "hexa8:2x2x1", "penta6:1x1x1", "tetra4:1x1x1"}) {
    tools::Ssnp121Options3d opt;
    opt.v1 = tools::parse_block_cells(v1, 3);
    opt.v2 = tools::parse_block_cells("hexa8:1x1x1", 3);
    Mesh mesh = tools::make_ssnp121_3d(opt);
    const auto& volume = mesh.cell_groups.at("V1");
    for (int c : volume) testing::permute_cell(mesh, c, testing::hand_written_reflection(mesh.cell_types[c]));
    EXPECT_EQ(orient_cells(mesh, "v1.med"), volume) << v1;
    const auto esc = mesh.cell_groups.at("SURESC");
    reverse_cells(mesh, esc);
    EXPECT_EQ(orient_boundary_outward(mesh, esc), static_cast<int>(esc.size())) << v1;
    for (int c : esc) EXPECT_GT(dot(boundary_normal(mesh, c), {0, 0, 1}), 0.0) << v1;
    for (int c : volume) EXPECT_EQ(testing::mid_side_offset(mesh, c), 0.0) << v1;
  }
}

}  // namespace
}  // namespace lunaster::engine
