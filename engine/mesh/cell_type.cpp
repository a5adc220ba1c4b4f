#include "engine/mesh/cell_type.hpp"

#include <array>
#include <initializer_list>
#include <utility>
#include <vector>

#include "engine/core/error.hpp"
#include "engine/mesh/cell_topology.hpp"

namespace lunaster::engine {

namespace {

constexpr int kNumTypes = 14;

const CellInfo kInfo[kNumTypes] = {
    {CellType::Point1, "POI1", 0, 1, 1, 1},     {CellType::Seg2, "SEG2", 1, 2, 2, 1},
    {CellType::Seg3, "SEG3", 1, 3, 2, 2},       {CellType::Tria3, "TRIA3", 2, 3, 3, 1},
    {CellType::Tria6, "TRIA6", 2, 6, 3, 2},     {CellType::Quad4, "QUAD4", 2, 4, 4, 1},
    {CellType::Quad8, "QUAD8", 2, 8, 4, 2},     {CellType::Tetra4, "TETRA4", 3, 4, 4, 1},
    {CellType::Tetra10, "TETRA10", 3, 10, 4, 2}, {CellType::Pyram5, "PYRAM5", 3, 5, 5, 1},
    {CellType::Penta6, "PENTA6", 3, 6, 6, 1},   {CellType::Penta15, "PENTA15", 3, 15, 6, 2},
    {CellType::Hexa8, "HEXA8", 3, 8, 8, 1},     {CellType::Hexa20, "HEXA20", 3, 20, 8, 2},
};

int index_of(CellType type) { return static_cast<int>(type); }

CellFaces make_faces(CellType face_type, std::initializer_list<std::initializer_list<int>> faces) {
  CellFaces f;
  for (const auto& face : faces) {
    f.face_type[f.n_faces] = face_type;
    f.nodes[f.n_faces].fill(-1);
    int k = 0;
    for (int n : face) f.nodes[f.n_faces][k++] = n;
    ++f.n_faces;
  }
  return f;
}

/// Faces of the MED reference cells (see cell_topology.hpp for their
/// coordinates), each ordered so that (x2-x1) x (x3-x1) points out of the cell;
/// edges of 2D cells follow the counter-clockwise traversal of the cell.
CellFaces build_faces(CellType type) {
  using T = CellType;
  switch (type) {
    case T::Point1: return CellFaces{};
    case T::Seg2: return make_faces(T::Point1, {{0}, {1}});
    case T::Seg3: return make_faces(T::Point1, {{0}, {1}});
    case T::Tria3: return make_faces(T::Seg2, {{0, 1}, {1, 2}, {2, 0}});
    case T::Tria6: return make_faces(T::Seg3, {{0, 1, 3}, {1, 2, 4}, {2, 0, 5}});
    case T::Quad4: return make_faces(T::Seg2, {{0, 1}, {1, 2}, {2, 3}, {3, 0}});
    case T::Quad8: return make_faces(T::Seg3, {{0, 1, 4}, {1, 2, 5}, {2, 3, 6}, {3, 0, 7}});
    case T::Tetra4: return make_faces(T::Tria3, {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}});
    case T::Tetra10:
      return make_faces(T::Tria6, {{0, 1, 2, 4, 5, 6}, {0, 2, 3, 6, 9, 7}, {0, 3, 1, 7, 8, 4}, {1, 3, 2, 8, 9, 5}});
    case T::Hexa8:
      return make_faces(T::Quad4, {{0, 1, 2, 3}, {4, 7, 6, 5}, {0, 4, 5, 1}, {3, 2, 6, 7}, {0, 3, 7, 4}, {1, 5, 6, 2}});
    case T::Hexa20:
      return make_faces(T::Quad8, {{0, 1, 2, 3, 8, 9, 10, 11},
                                   {4, 7, 6, 5, 15, 14, 13, 12},
                                   {0, 4, 5, 1, 16, 12, 17, 8},
                                   {3, 2, 6, 7, 10, 18, 14, 19},
                                   {0, 3, 7, 4, 11, 19, 15, 16},
                                   {1, 5, 6, 2, 17, 13, 18, 9}});
    case T::Pyram5: {
      CellFaces f = make_faces(T::Tria3, {{0, 1, 2, 3}, {0, 3, 4}, {3, 2, 4}, {2, 1, 4}, {1, 0, 4}});
      f.face_type[0] = T::Quad4;
      return f;
    }
    case T::Penta6: {
      CellFaces f = make_faces(T::Quad4, {{0, 1, 2}, {3, 5, 4}, {0, 3, 4, 1}, {0, 2, 5, 3}, {1, 4, 5, 2}});
      f.face_type[0] = f.face_type[1] = T::Tria3;
      return f;
    }
    case T::Penta15: {
      CellFaces f = make_faces(T::Quad8, {{0, 1, 2, 6, 7, 8},
                                          {3, 5, 4, 11, 10, 9},
                                          {0, 3, 4, 1, 12, 9, 13, 6},
                                          {0, 2, 5, 3, 8, 14, 11, 12},
                                          {1, 4, 5, 2, 13, 10, 14, 7}});
      f.face_type[0] = f.face_type[1] = T::Tria6;
      return f;
    }
  }
  throw InternalError("cell_faces: unknown cell type");
}

}  // namespace

const CellInfo& cell_info(CellType type) {
  const int i = index_of(type);
  LUNASTER_ASSERT(i >= 0 && i < kNumTypes, "invalid cell type");
  return kInfo[i];
}

bool cell_type_from_name(std::string_view name, CellType& out) {
  for (const auto& info : kInfo) {
    if (info.name == name) {
      out = info.type;
      return true;
    }
  }
  if (name == "POINT1") { out = CellType::Point1; return true; }
  if (name == "PYRA5") { out = CellType::Pyram5; return true; }
  return false;
}

const CellFaces& cell_faces(CellType type) {
  static const auto table = [] {
    std::array<CellFaces, kNumTypes> t{};
    for (int i = 0; i < kNumTypes; ++i) t[i] = build_faces(static_cast<CellType>(i));
    return t;
  }();
  return table[index_of(type)];
}

const std::vector<std::pair<int, int>>& cell_mid_edges(CellType type) {
  static const std::vector<std::pair<int, int>> none;
  static const std::vector<std::pair<int, int>> seg3{{0, 1}};
  static const std::vector<std::pair<int, int>> tria6{{0, 1}, {1, 2}, {2, 0}};
  static const std::vector<std::pair<int, int>> quad8{{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  static const std::vector<std::pair<int, int>> tetra10{{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
  static const std::vector<std::pair<int, int>> penta15{{0, 1}, {1, 2}, {2, 0}, {3, 4}, {4, 5},
                                                        {5, 3}, {0, 3}, {1, 4}, {2, 5}};
  static const std::vector<std::pair<int, int>> hexa20{{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                                       {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  switch (type) {
    case CellType::Seg3: return seg3;
    case CellType::Tria6: return tria6;
    case CellType::Quad8: return quad8;
    case CellType::Tetra10: return tetra10;
    case CellType::Penta15: return penta15;
    case CellType::Hexa20: return hexa20;
    default: return none;
  }
}

const std::vector<int>& cell_reverse_permutation(CellType type) {
  static const std::vector<int> seg2{1, 0}, seg3{1, 0, 2}, tria3{0, 2, 1}, tria6{0, 2, 1, 5, 4, 3};
  static const std::vector<int> quad4{0, 3, 2, 1}, quad8{0, 3, 2, 1, 7, 6, 5, 4}, point{0};
  switch (type) {
    case CellType::Point1: return point;
    case CellType::Seg2: return seg2;
    case CellType::Seg3: return seg3;
    case CellType::Tria3: return tria3;
    case CellType::Tria6: return tria6;
    case CellType::Quad4: return quad4;
    case CellType::Quad8: return quad8;
    default: break;
  }
  throw InternalError("cell_reverse_permutation: not a 0D/1D/2D cell: " + std::string(cell_info(type).name));
}

namespace {

/// Vertex permutation + the mid-side nodes of the permuted edges (looked up in
/// `cell_mid_edges`, so that each mid-side node stays on its edge).
std::vector<int> with_mid_edges(CellType type, std::vector<int> perm) {
  const auto& edges = cell_mid_edges(type);
  const int nv = static_cast<int>(perm.size());
  for (const auto& [a, b] : edges) {
    const int pa = perm[a], pb = perm[b];
    int found = -1;
    for (size_t k = 0; k < edges.size(); ++k)
      if ((edges[k].first == pa && edges[k].second == pb) || (edges[k].first == pb && edges[k].second == pa))
        found = nv + static_cast<int>(k);
    LUNASTER_ASSERT(found >= 0, "mirror permutation does not map edges to edges");
    perm.push_back(found);
  }
  return perm;
}

}  // namespace

const std::vector<int>& cell_mirror_permutation(CellType type) {
  using T = CellType;
  static const auto table = [] {
    std::array<std::vector<int>, kNumTypes> t{};
    const std::pair<CellType, std::vector<int>> vertices[] = {
        {T::Tria3, {0, 2, 1}},          {T::Tria6, {0, 2, 1}},          {T::Quad4, {0, 3, 2, 1}},
        {T::Quad8, {0, 3, 2, 1}},       {T::Tetra4, {0, 2, 1, 3}},      {T::Tetra10, {0, 2, 1, 3}},
        {T::Pyram5, {0, 3, 2, 1, 4}},   {T::Penta6, {0, 2, 1, 3, 5, 4}}, {T::Penta15, {0, 2, 1, 3, 5, 4}},
        {T::Hexa8, {0, 3, 2, 1, 4, 7, 6, 5}}, {T::Hexa20, {0, 3, 2, 1, 4, 7, 6, 5}}};
    for (const auto& [type, perm] : vertices) t[index_of(type)] = with_mid_edges(type, perm);
    return t;
  }();
  const std::vector<int>& perm = table[index_of(type)];
  if (perm.empty())
    throw InternalError("cell_mirror_permutation: not a 2D/3D cell: " + std::string(cell_info(type).name));
  return perm;
}

CellType linear_type(CellType type) {
  switch (type) {
    case CellType::Seg3: return CellType::Seg2;
    case CellType::Tria6: return CellType::Tria3;
    case CellType::Quad8: return CellType::Quad4;
    case CellType::Tetra10: return CellType::Tetra4;
    case CellType::Penta15: return CellType::Penta6;
    case CellType::Hexa20: return CellType::Hexa8;
    default: return type;
  }
}

const std::vector<CellType>& cell_types_in_med_order() {
  using T = CellType;
  static const std::vector<CellType> order{T::Point1, T::Seg2,   T::Seg3,   T::Tria3,   T::Quad4,
                                           T::Tria6,  T::Quad8,  T::Tetra4, T::Pyram5,  T::Penta6,
                                           T::Hexa8,  T::Tetra10, T::Penta15, T::Hexa20};
  return order;
}

int med_type_rank(CellType type) {
  const auto& order = cell_types_in_med_order();
  for (size_t i = 0; i < order.size(); ++i)
    if (order[i] == type) return static_cast<int>(i);
  return -1;
}

}  // namespace lunaster::engine
