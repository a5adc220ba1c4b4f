#include "engine/mesh/orientation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "engine/core/error.hpp"
#include "engine/mesh/cell_topology.hpp"

namespace lunaster::engine {

namespace {

using Vec3 = std::array<double, 3>;

Vec3 point(const Mesh& mesh, int node) {
  const double* p = mesh.node(node);
  return {p[0], p[1], p[2]};
}
Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }

/// Number of vertices among the first nodes of a face listed by cell_faces.
int face_n_vertices(CellType face_type) { return cell_info(face_type).n_vertices; }

double max_edge_length(const Mesh& mesh, int c) {
  const int* nodes = mesh.cell(c);
  const int nv = cell_info(mesh.cell_types[c]).n_vertices;
  double h = 0.0;
  for (int i = 0; i < nv; ++i)
    for (int j = i + 1; j < nv; ++j) h = std::max(h, norm(sub(point(mesh, nodes[i]), point(mesh, nodes[j]))));
  return h;
}

/// Smallest and largest corner Jacobians of a cell.
struct JacobianRange {
  double min = 1e300, max = -1e300;
  void add(double j) { min = std::min(min, j), max = std::max(max, j); }
};

/// Corner Jacobians of a 2D cell (z-component of (n-v) x (p-v)).
JacobianRange corner_jacobians_2d(const Mesh& mesh, int c) {
  const int* nodes = mesh.cell(c);
  const int nv = cell_info(mesh.cell_types[c]).n_vertices;
  JacobianRange range;
  for (int i = 0; i < nv; ++i) {
    const Vec3 v = point(mesh, nodes[i]);
    const Vec3 e1 = sub(point(mesh, nodes[(i + 1) % nv]), v);
    const Vec3 e2 = sub(point(mesh, nodes[(i + nv - 1) % nv]), v);
    range.add(cross(e1, e2)[2]);
  }
  return range;
}

/// For each outward face corner (v, next n, previous p) of a 3D cell type: the other edge
/// neighbours of v (those off the face). Depends on the type only, so it is built once per
/// type: the check runs on every cell of every mesh read (a million HEXA8 cells took 0.8 s
/// when each cell built its own neighbour lists).
struct FaceCorner {
  int v, n, p;
  std::array<int, 8> others;
  int n_others = 0;
};
struct CornerTable {
  std::vector<FaceCorner> corners;
};

CornerTable corner_table(CellType type) {
  const CellFaces& faces = cell_faces(type);
  const int nv = cell_info(type).n_vertices;
  std::vector<std::vector<int>> neighbours(nv);
  for (int f = 0; f < faces.n_faces; ++f) {
    const int m = face_n_vertices(faces.face_type[f]);
    for (int k = 0; k < m; ++k) {
      const int v = faces.nodes[f][k], n = faces.nodes[f][(k + 1) % m];
      neighbours[v].push_back(n);
      neighbours[n].push_back(v);
    }
  }
  CornerTable table;
  for (int f = 0; f < faces.n_faces; ++f) {
    const int m = face_n_vertices(faces.face_type[f]);
    const auto* begin = faces.nodes[f].data();
    for (int k = 0; k < m; ++k) {
      FaceCorner corner{faces.nodes[f][k], faces.nodes[f][(k + 1) % m], faces.nodes[f][(k + m - 1) % m], {}, 0};
      // An edge shared by two faces lists its far vertex twice: the same determinant twice,
      // which leaves the minimum and maximum as they are.
      for (int other : neighbours[corner.v]) {
        if (std::find(begin, begin + m, other) != begin + m) continue;
        LUNASTER_ASSERT(corner.n_others < static_cast<int>(corner.others.size()), "too many corner neighbours");
        corner.others[corner.n_others++] = other;
      }
      table.corners.push_back(corner);
    }
  }
  return table;
}

const CornerTable& corner_table_of(CellType type) {
  static const std::array<CornerTable, kCellTypeCount> tables = [] {
    std::array<CornerTable, kCellTypeCount> all;
    for (int t = 0; t < kCellTypeCount; ++t)
      if (cell_info(static_cast<CellType>(t)).dim == 3) all[t] = corner_table(static_cast<CellType>(t));
    return all;
  }();
  return tables[static_cast<int>(type)];
}

/// Corner Jacobians of a 3D cell: at vertex v of an outward face with
/// neighbours n (next) and p (previous), every other edge neighbour c of v must
/// lie inside: det = ((n-v) x (p-v)) . (v-c) > 0.
JacobianRange corner_jacobians_3d(const Mesh& mesh, int c) {
  const int* nodes = mesh.cell(c);
  JacobianRange range;
  for (const FaceCorner& corner : corner_table_of(mesh.cell_types[c]).corners) {
    const Vec3 x = point(mesh, nodes[corner.v]);
    const Vec3 normal = cross(sub(point(mesh, nodes[corner.n]), x), sub(point(mesh, nodes[corner.p]), x));
    for (int k = 0; k < corner.n_others; ++k) range.add(dot(normal, sub(x, point(mesh, nodes[corner.others[k]]))));
  }
  return range;
}

/// Orientation of a volume cell (dimension mesh.dim >= 2) from its corner
/// Jacobians, with the degeneracy threshold 1e-10 h^d.
enum class CellState { NotChecked, Valid, Mirrored, Tangled };

CellState cell_state(const Mesh& mesh, int c) {
  const int cdim = cell_info(mesh.cell_types[c]).dim;
  if (cdim != mesh.dim || cdim < 2) return CellState::NotChecked;
  const double tol = 1e-10 * std::pow(max_edge_length(mesh, c), cdim);
  const JacobianRange j = cdim == 2 ? corner_jacobians_2d(mesh, c) : corner_jacobians_3d(mesh, c);
  if (j.min > tol) return CellState::Valid;
  if (j.max < -tol) return CellState::Mirrored;
  return CellState::Tangled;  // also a NaN coordinate: no comparison above holds
}

void reorder_nodes(Mesh& mesh, int c, const std::vector<int>& perm) {
  int* target = &mesh.cell_nodes[mesh.cell_offsets[c]];
  const std::vector<int> old(target, target + mesh.cell_n_nodes(c));
  for (size_t k = 0; k < perm.size(); ++k) target[k] = old[perm[k]];
}

/// "M6 (QUAD4), M7 (QUAD4), ..." for the first five cells.
std::string cell_list(const Mesh& mesh, const std::vector<int>& cells) {
  std::string list;
  for (size_t i = 0; i < cells.size() && i < 5; ++i) {
    if (i) list += ", ";
    list += mesh.cell_names[cells[i]] + " (" + std::string(cell_info(mesh.cell_types[cells[i]]).name) + ")";
  }
  if (cells.size() > 5) list += ", ...";
  return list;
}

bool same_cyclic_orientation(const std::vector<int>& a, const std::vector<int>& b) {
  const int m = static_cast<int>(a.size());
  if (m == 2) return a == b;  // a segment has no cyclic rotation
  const auto it = std::find(b.begin(), b.end(), a[0]);
  const int k = static_cast<int>(it - b.begin());
  return b[(k + 1) % m] == a[1];
}

/// Global vertex ids of the face of `volume` whose vertex set is `vertices`.
std::vector<int> matching_face(const Mesh& mesh, int volume, const std::vector<int>& vertices) {
  const CellFaces& faces = cell_faces(mesh.cell_types[volume]);
  std::vector<int> sorted = vertices;
  std::sort(sorted.begin(), sorted.end());
  for (int f = 0; f < faces.n_faces; ++f) {
    const int m = face_n_vertices(faces.face_type[f]);
    if (m != static_cast<int>(vertices.size())) continue;
    std::vector<int> face(m);
    for (int k = 0; k < m; ++k) face[k] = mesh.cell(volume)[faces.nodes[f][k]];
    std::vector<int> face_sorted = face;
    std::sort(face_sorted.begin(), face_sorted.end());
    if (face_sorted == sorted) return face;
  }
  return {};
}

}  // namespace

bool is_boundary_type(CellType type, int mesh_dim) {
  switch (type) {
    case CellType::Seg2:
    case CellType::Seg3: return mesh_dim == 2;
    case CellType::Tria3:
    case CellType::Tria6:
    case CellType::Quad4:
    case CellType::Quad8: return mesh_dim == 3;
    default: return false;
  }
}

std::vector<int> find_inverted_cells(const Mesh& mesh) {
  std::vector<int> bad;
  for (int c = 0; c < mesh.n_cells(); ++c) {
    const CellState state = cell_state(mesh, c);
    if (state == CellState::Mirrored || state == CellState::Tangled) bad.push_back(c);
  }
  return bad;
}

std::vector<std::string> inverted_cell_names(const Mesh& mesh) {
  std::vector<std::string> names;
  for (int c : find_inverted_cells(mesh)) names.push_back(mesh.cell_names[c]);
  return names;
}

void check_cell_orientation(const Mesh& mesh, const std::string& source) {
  const std::vector<int> bad = find_inverted_cells(mesh);
  if (bad.empty()) return;
  throw DeckError("mesh file '" + source + "': " + std::to_string(bad.size()) +
                      " inverted or degenerate cell(s) (non-positive Jacobian): " + cell_list(mesh, bad),
                  {"check the node order of these cells (MED order is expected), and that no two of their "
                   "corners are the same node or at the same point"});
}

std::vector<int> find_tangled_cells(const Mesh& mesh) {
  std::vector<int> bad;
  for (int c = 0; c < mesh.n_cells(); ++c)
    if (cell_state(mesh, c) == CellState::Tangled) bad.push_back(c);
  return bad;
}

std::vector<int> orient_cells(Mesh& mesh, const std::string& source) {
  std::vector<int> tangled, mirrored;
  for (int c = 0; c < mesh.n_cells(); ++c) {
    const CellState state = cell_state(mesh, c);
    if (state == CellState::Tangled) tangled.push_back(c);
    if (state == CellState::Mirrored) mirrored.push_back(c);
  }
  if (!tangled.empty())
    throw DeckError("mesh file '" + source + "': " + std::to_string(tangled.size()) +
                        " tangled or degenerate cell(s) (Jacobian zero or of both signs): " +
                        cell_list(mesh, tangled),
                    {"check the node order of these cells (a cell must not cross itself; clockwise or mirrored "
                     "cells are accepted and reoriented), and that no two of their corners are the same node or "
                     "at the same point"});
  for (int c : mirrored) {
    reorder_nodes(mesh, c, cell_mirror_permutation(mesh.cell_types[c]));
    LUNASTER_ASSERT(cell_state(mesh, c) == CellState::Valid,
                    "cell " + mesh.cell_names[c] + " is still inverted after its reorientation");
  }
  return mirrored;
}

double cell_measure(const Mesh& mesh, int c) {
  const CellType type = mesh.cell_types[c];
  const CellInfo& info = cell_info(type);
  const int* nodes = mesh.cell(c);
  if (info.dim == 0) return 0.0;
  if (info.dim == 1) return norm(sub(point(mesh, nodes[1]), point(mesh, nodes[0])));
  if (info.dim == 2) {
    Vec3 area{0, 0, 0};
    const Vec3 o = point(mesh, nodes[0]);
    for (int i = 1; i + 1 < info.n_vertices; ++i) {
      const Vec3 t = cross(sub(point(mesh, nodes[i]), o), sub(point(mesh, nodes[i + 1]), o));
      for (int k = 0; k < 3; ++k) area[k] += 0.5 * t[k];
    }
    if (mesh.dim == 2) return area[2];
    return norm(area);
  }
  Vec3 centre{0, 0, 0};
  for (int i = 0; i < info.n_vertices; ++i)
    for (int k = 0; k < 3; ++k) centre[k] += point(mesh, nodes[i])[k] / info.n_vertices;
  const CellFaces& faces = cell_faces(type);
  double volume = 0.0;
  for (int f = 0; f < faces.n_faces; ++f) {
    const int m = face_n_vertices(faces.face_type[f]);
    const Vec3 a = point(mesh, nodes[faces.nodes[f][0]]);
    for (int k = 1; k + 1 < m; ++k) {
      const Vec3 b = point(mesh, nodes[faces.nodes[f][k]]), d = point(mesh, nodes[faces.nodes[f][k + 1]]);
      volume += dot(cross(sub(b, a), sub(d, a)), sub(a, centre)) / 6.0;
    }
  }
  return volume;
}

std::array<double, 3> boundary_normal(const Mesh& mesh, int c) {
  const int* nodes = mesh.cell(c);
  const int cdim = cell_info(mesh.cell_types[c]).dim;
  if (cdim == 1) {
    const Vec3 t = sub(point(mesh, nodes[1]), point(mesh, nodes[0]));
    return {t[1], -t[0], 0.0};
  }
  LUNASTER_ASSERT(cdim == 2, "boundary_normal needs a 1D or 2D cell");
  const Vec3 x1 = point(mesh, nodes[0]);
  return cross(sub(point(mesh, nodes[1]), x1), sub(point(mesh, nodes[2]), x1));
}

std::vector<BoundaryFacing> boundary_facing(const Mesh& mesh, const std::vector<int>& boundary_cells) {
  // The volume cells around each vertex of the given cells only.
  std::vector<char> wanted(mesh.n_nodes(), 0);
  for (int b : boundary_cells) {
    LUNASTER_ASSERT(is_boundary_type(mesh.cell_types[b], mesh.dim),
                    "boundary_facing: cell " + mesh.cell_names[b] + " is not a boundary cell");
    wanted[mesh.cell(b)[0]] = 1;
  }
  std::vector<int> volumes;
  for (int c = 0; c < mesh.n_cells(); ++c) {
    if (cell_info(mesh.cell_types[c]).dim != mesh.dim) continue;
    const int nv = cell_info(mesh.cell_types[c]).n_vertices;
    for (int k = 0; k < nv; ++k)
      if (wanted[mesh.cell(c)[k]]) {
        volumes.push_back(c);
        break;
      }
  }
  const Mesh::NodeCells around = mesh.node_cells(volumes);
  std::vector<BoundaryFacing> facing(boundary_cells.size());
  for (size_t i = 0; i < boundary_cells.size(); ++i) {
    const int b = boundary_cells[i];
    const int nv = cell_info(mesh.cell_types[b]).n_vertices;
    const std::vector<int> vertices(mesh.cell(b), mesh.cell(b) + nv);
    BoundaryFacing& f = facing[i];
    for (int p = around.start[vertices[0]]; p < around.start[vertices[0] + 1]; ++p) {
      const int v = volumes[around.positions[p]];
      if (!mesh.cell_holds(v, vertices.data(), nv)) continue;
      if (f.owner < 0) f.owner = v;
      else if (f.other < 0) f.other = v;
    }
    if (f.owner < 0) continue;  // Loose
    if (f.other >= 0) {
      f.side = BoundarySide::Inner;
      continue;
    }
    const std::vector<int> face = matching_face(mesh, f.owner, vertices);
    // Every vertex of a face of the owner that is no face of it: an edge of a 3D cell, say.
    if (face.empty()) {
      f.side = BoundarySide::Loose;
      continue;
    }
    f.side = same_cyclic_orientation(vertices, face) ? BoundarySide::Outward : BoundarySide::Inward;
  }
  return facing;
}

int orient_boundary_outward(Mesh& mesh, const std::vector<int>& boundary_cells) {
  for (int b : boundary_cells)
    if (!is_boundary_type(mesh.cell_types[b], mesh.dim))
      throw DeckError("cell " + mesh.cell_names[b] + " (" + std::string(cell_info(mesh.cell_types[b]).name) +
                      ") is not a boundary cell of a " + std::to_string(mesh.dim) + "D mesh");
  const std::vector<BoundaryFacing> facing = boundary_facing(mesh, boundary_cells);
  int flipped = 0;
  for (size_t i = 0; i < boundary_cells.size(); ++i) {
    const int b = boundary_cells[i];
    const BoundaryFacing& f = facing[i];
    if (f.owner < 0)
      throw DeckError("cell " + mesh.cell_names[b] + " (" + std::string(cell_info(mesh.cell_types[b]).name) +
                      ") bounds no " + std::to_string(mesh.dim) + "D cell: cannot orient it");
    if (f.side == BoundarySide::Inner)
      throw DeckError("cell " + mesh.cell_names[b] + " is shared by cells " + mesh.cell_names[f.owner] + " and " +
                      mesh.cell_names[f.other] + ": it is not on the skin");
    if (f.side == BoundarySide::Loose)
      throw DeckError("cell " + mesh.cell_names[b] + " is not a face of cell " + mesh.cell_names[f.owner]);
    if (f.side == BoundarySide::Outward) continue;
    reorder_nodes(mesh, b, cell_reverse_permutation(mesh.cell_types[b]));
    ++flipped;
  }
  return flipped;
}

}  // namespace lunaster::engine
