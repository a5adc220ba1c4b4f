#include "tools/ssnp121_mesh.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <map>
#include <sstream>
#include <tuple>

#include "engine/core/error.hpp"
#include "engine/mesh/cell_topology.hpp"
#include "engine/mesh/orientation.hpp"

namespace lunaster::tools {

namespace {

using engine::CellType;
using engine::Mesh;
using Vec3 = std::array<double, 3>;

struct PendingCell {
  CellType type;
  std::vector<int> nodes;
  std::string group;
};

/// Plane `axis = value` whose boundary cells form group `name`.
struct FaceGroup {
  std::string name;
  int axis;
  double value;
};

/// Collects nodes (merged by exact coordinates inside a pool) and cells, then
/// builds the mesh with cells sorted by MED type order and named M1.., N1..
class Builder {
 public:
  int new_pool() {
    pools_.emplace_back();
    return static_cast<int>(pools_.size()) - 1;
  }
  int node(int pool, const Vec3& p) {
    const auto key = key_of(p);
    const auto it = pools_[pool].find(key);
    if (it != pools_[pool].end()) return it->second;
    nodes_.push_back(p);
    const int index = static_cast<int>(nodes_.size()) - 1;
    pools_[pool].emplace(key, index);
    return index;
  }
  int find(int pool, const Vec3& p) const {
    const auto it = pools_[pool].find(key_of(p));
    return it == pools_[pool].end() ? -1 : it->second;
  }
  const Vec3& position(int node) const { return nodes_[node]; }
  void add_cell(CellType type, std::vector<int> nodes, const std::string& group) {
    cells_.push_back({type, std::move(nodes), group});
  }
  void add_node_group(const std::string& name, int pool, const Vec3& p) {
    const int n = find(pool, p);
    if (n >= 0) node_groups_[name].push_back(n);
  }
  Mesh finish() const;

 private:
  static std::array<long long, 3> key_of(const Vec3& p) {
    return {std::llround(p[0] * 1e9), std::llround(p[1] * 1e9), std::llround(p[2] * 1e9)};
  }
  std::vector<std::map<std::array<long long, 3>, int>> pools_;
  std::vector<Vec3> nodes_;
  std::vector<PendingCell> cells_;
  std::map<std::string, std::vector<int>> node_groups_;
};

Mesh Builder::finish() const {
  Mesh mesh;
  for (const Vec3& p : nodes_) mesh.add_node(p[0], p[1], p[2]);
  std::vector<int> order(cells_.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::stable_sort(order.begin(), order.end(), [this](int a, int b) {
    return engine::med_type_rank(cells_[a].type) < engine::med_type_rank(cells_[b].type);
  });
  std::map<std::string, std::vector<int>> cell_groups;
  for (int i : order) {
    const int c = mesh.add_cell(cells_[i].type, cells_[i].nodes);
    cell_groups[cells_[i].group].push_back(c);
  }
  for (const auto& [name, cells] : cell_groups) mesh.add_to_cell_group(name, cells);
  for (const auto& [name, nodes] : node_groups_) mesh.add_to_node_group(name, nodes);
  mesh.detect_dimension();
  engine::check_cell_orientation(mesh, "generated mesh");
  return mesh;
}

/// Geometry of one structured block.
struct BlockGeom {
  Vec3 lo{0, 0, 0}, hi{1, 1, 1};
  int dim = 2;
  double distort = 0.0;
  std::string group;
  std::vector<FaceGroup> faces;
  int pool = 0;
};

/// Deterministic pseudo-random number in [-1, 1] (splitmix64 of the indices).
double jitter(int i, int j, int k, int axis) {
  uint64_t z = (static_cast<uint64_t>(i) * 73856093u) ^ (static_cast<uint64_t>(j) * 19349663u) ^
               (static_cast<uint64_t>(k) * 83492791u) ^ (static_cast<uint64_t>(axis + 1) * 2654435761u);
  z += 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  z ^= z >> 31;
  return 2.0 * static_cast<double>(z >> 11) / static_cast<double>(1ull << 53) - 1.0;
}

class BlockMesher {
 public:
  BlockMesher(Builder& builder, const BlockCells& cells, const BlockGeom& geom)
      : b_(builder), cells_(cells), g_(geom) {}
  void run();

 private:
  Vec3 vertex(int i, int j, int k) const;
  void emit(CellType type, const std::vector<Vec3>& vertices);
  void lattice_cell(int i, int j, int k);

  Builder& b_;
  BlockCells cells_;
  BlockGeom g_;
};

Vec3 BlockMesher::vertex(int i, int j, int k) const {
  const int idx[3] = {i, j, k};
  Vec3 p{0, 0, 0};
  bool interior = true;
  for (int a = 0; a < g_.dim; ++a) {
    const int n = cells_.n[a];
    p[a] = idx[a] == n ? g_.hi[a] : g_.lo[a] + (g_.hi[a] - g_.lo[a]) * idx[a] / n;
    interior = interior && idx[a] > 0 && idx[a] < n;
  }
  if (g_.dim == 2) p[2] = g_.lo[2];
  if (interior && g_.distort > 0.0)
    for (int a = 0; a < g_.dim; ++a) p[a] += g_.distort * (g_.hi[a] - g_.lo[a]) / cells_.n[a] * jitter(i, j, k, a);
  return p;
}

/// Creates a cell from its vertex positions in MED order (mid-side nodes at
/// edge midpoints) and the boundary cells of its faces lying on a group plane.
void BlockMesher::emit(CellType type, const std::vector<Vec3>& vertices) {
  std::vector<int> nodes;
  for (const Vec3& v : vertices) nodes.push_back(b_.node(g_.pool, v));
  for (const auto& [a, c] : engine::cell_mid_edges(type)) {
    const Vec3 &p = vertices[a], &q = vertices[c];
    nodes.push_back(b_.node(g_.pool, {0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1]), 0.5 * (p[2] + q[2])}));
  }
  b_.add_cell(type, nodes, g_.group);
  const engine::CellFaces& faces = engine::cell_faces(type);
  for (int f = 0; f < faces.n_faces; ++f) {
    const int m = engine::cell_info(faces.face_type[f]).n_nodes;
    std::vector<int> face(m);
    for (int k = 0; k < m; ++k) face[k] = nodes[faces.nodes[f][k]];
    for (const FaceGroup& fg : g_.faces) {
      const bool on_plane = std::all_of(face.begin(), face.end(),
                                        [&](int n) { return b_.position(n)[fg.axis] == fg.value; });
      if (on_plane) b_.add_cell(faces.face_type[f], face, fg.name);
    }
  }
}

void BlockMesher::lattice_cell(int i, int j, int k) {
  auto c = [&](int a, int b, int d) { return vertex(i + a, j + b, k + d); };
  switch (engine::linear_type(cells_.type)) {
    case CellType::Quad4: emit(cells_.type, {c(0, 0, 0), c(1, 0, 0), c(1, 1, 0), c(0, 1, 0)}); break;
    case CellType::Tria3:
      emit(cells_.type, {c(0, 0, 0), c(1, 0, 0), c(1, 1, 0)});
      emit(cells_.type, {c(0, 0, 0), c(1, 1, 0), c(0, 1, 0)});
      break;
    case CellType::Hexa8:
      emit(cells_.type, {c(0, 0, 0), c(0, 1, 0), c(1, 1, 0), c(1, 0, 0), c(0, 0, 1), c(0, 1, 1), c(1, 1, 1), c(1, 0, 1)});
      break;
    case CellType::Penta6:  // counter-clockwise xy triangles, reversed: MED's first face points down (out)
      emit(cells_.type, {c(0, 0, 0), c(1, 1, 0), c(1, 0, 0), c(0, 0, 1), c(1, 1, 1), c(1, 0, 1)});
      emit(cells_.type, {c(0, 0, 0), c(0, 1, 0), c(1, 1, 0), c(0, 0, 1), c(0, 1, 1), c(1, 1, 1)});
      break;
    case CellType::Tetra4: {  // Kuhn subdivision: 6 tetrahedra along the main diagonal, conforming
      const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
      for (const auto& p : perms) {
        std::array<int, 3> w1{0, 0, 0};
        w1[p[0]] = 1;
        std::array<int, 3> w2 = w1;
        w2[p[1]] = 1;
        // det[w1, w2, (1,1,1)] > 0 is the VTK/Gmsh orientation; MED wants the opposite.
        const double det = w1[0] * (w2[1] - w2[2]) - w1[1] * (w2[0] - w2[2]) + w1[2] * (w2[0] - w2[1]);
        if (det > 0) std::swap(w1, w2);
        emit(cells_.type, {c(0, 0, 0), c(w1[0], w1[1], w1[2]), c(w2[0], w2[1], w2[2]), c(1, 1, 1)});
      }
      break;
    }
    default: throw DeckError("meshgen: unsupported block cell type " + std::string(engine::cell_info(cells_.type).name));
  }
}

void BlockMesher::run() {
  const int nz = g_.dim == 3 ? cells_.n[2] : 1;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < cells_.n[1]; ++j)
      for (int i = 0; i < cells_.n[0]; ++i) lattice_cell(i, j, k);
}

void check_dim(const BlockCells& cells, int dim, const std::string& what) {
  if (engine::cell_info(cells.type).dim != dim)
    throw DeckError("meshgen: " + what + ": " + std::string(engine::cell_info(cells.type).name) + " is not a " +
                    std::to_string(dim) + "D cell type");
}

/// One annular body r0 <= r <= r1, 0 <= theta <= pi/2, of a ring/sleeve mesh.
struct AnnulusGeom {
  double r0 = 0.0, r1 = 1.0;
  std::string group;
  std::string inner, outer, x0, y0;  ///< boundary groups on r = r0, r = r1, x = 0, y = 0
  int pool = 0;
};

/// Meshes an annulus on the lattice of polar parameters: node (s, t) in half-cell units
/// (s through the thickness, t along the arc) sits at r = r0 + (r1 - r0) s / (2 NR),
/// theta = pi/2 t / (2 NT). The map (r, theta) -> (x, y) has Jacobian r > 0, so cells
/// listed (s, t), (s+1, t), (s+1, t+1), (s, t+1) are counter-clockwise.
void mesh_annulus(Builder& b, const BlockCells& cells, const AnnulusGeom& g) {
  const int nt = cells.n[0], nr = cells.n[1];
  const auto position = [&](int s, int t) -> Vec3 {
    const double r = s == 2 * nr ? g.r1 : g.r0 + (g.r1 - g.r0) * s / (2.0 * nr);
    if (t == 0) return {r, 0.0, 0.0};          // exactly on y = 0
    if (t == 2 * nt) return {0.0, r, 0.0};     // exactly on x = 0
    const double theta = 0.5 * M_PI * t / (2.0 * nt);
    return {r * std::cos(theta), r * std::sin(theta), 0.0};
  };
  const engine::CellFaces& faces = engine::cell_faces(cells.type);
  for (int j = 0; j < nt; ++j)
    for (int i = 0; i < nr; ++i) {
      std::vector<std::array<int, 2>> st{{2 * i, 2 * j}, {2 * i + 2, 2 * j}, {2 * i + 2, 2 * j + 2}, {2 * i, 2 * j + 2}};
      for (const auto& [p, q] : engine::cell_mid_edges(cells.type))
        st.push_back({(st[p][0] + st[q][0]) / 2, (st[p][1] + st[q][1]) / 2});
      std::vector<int> nodes;
      for (const auto& [s, t] : st) nodes.push_back(b.node(g.pool, position(s, t)));
      b.add_cell(cells.type, nodes, g.group);
      for (int f = 0; f < faces.n_faces; ++f) {
        const int m = engine::cell_info(faces.face_type[f]).n_nodes;
        const auto all = [&](int axis, int value) {
          for (int k = 0; k < m; ++k)
            if (st[faces.nodes[f][k]][axis] != value) return false;
          return true;
        };
        std::string name;
        if (all(0, 0)) name = g.inner;
        else if (all(0, 2 * nr)) name = g.outer;
        else if (all(1, 0)) name = g.y0;
        else if (all(1, 2 * nt)) name = g.x0;
        if (name.empty()) continue;
        std::vector<int> face(m);
        for (int k = 0; k < m; ++k) face[k] = nodes[faces.nodes[f][k]];
        b.add_cell(faces.face_type[f], face, name);
      }
    }
}

}  // namespace

BlockCells parse_block_cells(const std::string& spec, int dim) {
  const auto colon = spec.find(':');
  if (colon == std::string::npos) throw DeckError("meshgen: expected TYPE:N or TYPE:NXxNY[xNZ], got '" + spec + "'");
  std::string name = spec.substr(0, colon);
  std::transform(name.begin(), name.end(), name.begin(), [](unsigned char ch) { return std::toupper(ch); });
  BlockCells cells;
  if (!engine::cell_type_from_name(name, cells.type)) throw DeckError("meshgen: unknown cell type '" + name + "'");
  std::vector<int> counts;
  std::string rest = spec.substr(colon + 1);
  size_t pos = 0;
  while (pos <= rest.size()) {
    const size_t x = rest.find('x', pos);
    const std::string part = rest.substr(pos, x == std::string::npos ? std::string::npos : x - pos);
    if (part.empty() || part.find_first_not_of("0123456789") != std::string::npos || part.size() > 6)
      throw DeckError("meshgen: bad cell count in '" + spec + "'");
    counts.push_back(std::stoi(part));
    if (x == std::string::npos) break;
    pos = x + 1;
  }
  if (counts.size() == 1) counts.assign(dim, counts[0]);
  if (static_cast<int>(counts.size()) != dim) throw DeckError("meshgen: '" + spec + "' needs " + std::to_string(dim) + " counts");
  for (int a = 0; a < dim; ++a) {
    if (counts[a] < 1) throw DeckError("meshgen: cell counts must be >= 1 in '" + spec + "'");
    cells.n[a] = counts[a];
  }
  check_dim(cells, dim, spec);
  return cells;
}

Mesh make_ssnp121_2d(const Ssnp121Options2d& o) {
  check_dim(o.upper, 2, "upper block");
  check_dim(o.lower, 2, "lower block");
  if (o.glued && (o.upper.type != o.lower.type || o.upper.n[0] != o.lower.n[0]))
    throw DeckError("meshgen: --glued needs the same cell type and count in both blocks");
  Builder b;
  const int up = b.new_pool();
  const int low = o.glued ? up : b.new_pool();
  if (!(o.x0 < o.x1)) throw DeckError("meshgen: --x-range needs X0 < X1");
  const double x0 = o.x0, x1 = o.x1, xm = 0.5 * (o.x0 + o.x1);
  BlockGeom upper{{x0, 0, 0}, {x1, 1, 0}, 2, 0.0, "PLAQUE1",
                  {{"AB", 1, 0.0}, {"BC", 0, x1}, {"CD", 1, 1.0}, {"DA", 0, x0}}, up};
  BlockGeom lower{{x0, -1, 0}, {x1, 0, 0}, 2, 0.0, "PLAQUE2",
                  {{"EF", 1, 0.0}, {"FG", 0, x1}, {"GH", 1, -1.0}, {"HE", 0, x0}}, low};
  BlockMesher(b, o.upper, upper).run();
  BlockMesher(b, o.lower, lower).run();
  if (o.top.n[0] > 0) {
    check_dim(o.top, 2, "top block");
    const int top_pool = b.new_pool();
    BlockGeom top{{x0, 1, 0}, {x1, 2, 0}, 2, 0.0, "PLAQUE3",
                  {{"IJ", 1, 1.0}, {"JK", 0, x1}, {"KL", 1, 2.0}, {"LI", 0, x0}}, top_pool};
    BlockMesher(b, o.top, top).run();
    for (const auto& [name, x, y] : std::vector<std::tuple<std::string, double, double>>{
             {"I", x0, 1}, {"J", x1, 1}, {"K", x1, 2}, {"L", x0, 2}, {"P", xm, 1}})
      b.add_node_group(name, top_pool, {x, y, 0});
  }
  for (const auto& [name, x, y] : std::vector<std::tuple<std::string, double, double>>{
           {"A", x0, 0}, {"B", x1, 0}, {"C", x1, 1}, {"D", x0, 1}, {"O", xm, 0}})
    b.add_node_group(name, up, {x, y, 0});
  for (const auto& [name, x, y] : std::vector<std::tuple<std::string, double, double>>{
           {"E", x0, 0}, {"F", x1, 0}, {"G", x1, -1}, {"H", x0, -1}})
    b.add_node_group(name, low, {x, y, 0});
  return b.finish();
}

void name_nodes_as_gibi_script(Mesh& mesh) {
  // Which block each node is in (nodes on the interface are not shared: one per block).
  std::vector<int> block(mesh.n_nodes(), -1);
  const char* plates[2] = {"PLAQUE1", "PLAQUE2"};
  for (int b = 0; b < 2; ++b) {
    const auto group = mesh.cell_groups.find(plates[b]);
    if (group == mesh.cell_groups.end()) throw DeckError(std::string("meshgen: no cell group ") + plates[b]);
    for (int c : group->second)
      for (int a = 0; a < mesh.cell_n_nodes(c); ++a) {
        const int n = mesh.cell(c)[a];
        if (block[n] >= 0 && block[n] != b) throw DeckError("meshgen: the blocks share nodes (--glued): no GIBI names");
        block[n] = b;
      }
  }
  double lo = 1e300, hi = -1e300;
  for (int n = 0; n < mesh.n_nodes(); ++n) lo = std::min(lo, mesh.coords[3 * n]), hi = std::max(hi, mesh.coords[3 * n]);
  const double tol = 1e-9 * (hi - lo);
  // The corners and the lines of the script, block by block: {x, y} of the first and second point.
  struct Line { double x0, y0, x1, y1; };
  const std::array<std::array<double, 2>, 4> corners[2] = {{{{lo, 0}, {hi, 0}, {hi, 1}, {lo, 1}}},
                                                           {{{lo, 0}, {hi, 0}, {hi, -1}, {lo, -1}}}};
  std::vector<long> rank(mesh.n_nodes(), -1);  // sort key: where the script creates the node
  auto at = [&](int n, double x, double y) {
    return std::abs(mesh.coords[3 * n] - x) <= tol && std::abs(mesh.coords[3 * n + 1] - y) <= tol;
  };
  for (int b = 0; b < 2; ++b)
    for (int k = 0; k < 4; ++k)
      for (int n = 0; n < mesh.n_nodes(); ++n)
        if (block[n] == b && at(n, corners[b][k][0], corners[b][k][1])) rank[n] = 4 * b + k;
  for (int b = 0; b < 2; ++b)
    for (int k = 0; k < 4; ++k) {
      const auto& p = corners[b][k];
      const auto& q = corners[b][(k + 1) % 4];
      const double len = std::hypot(q[0] - p[0], q[1] - p[1]);
      for (int n = 0; n < mesh.n_nodes(); ++n) {
        if (block[n] != b || rank[n] >= 0) continue;
        const double dx = mesh.coords[3 * n] - p[0], dy = mesh.coords[3 * n + 1] - p[1];
        const double along = (dx * (q[0] - p[0]) + dy * (q[1] - p[1])) / len;
        const double off = std::abs(dx * (q[1] - p[1]) - dy * (q[0] - p[0])) / len;
        if (off <= tol && along > tol && along < len - tol)
          rank[n] = 8 + (4L * b + k) * 10000000L + std::lround(along / len * 1e6);
      }
    }
  const long inner = 8 + 8L * 10000000L;
  for (int n = 0; n < mesh.n_nodes(); ++n)
    if (rank[n] < 0) {
      // Row by row from the interface (|y| up), then by x.
      const double y = std::abs(mesh.coords[3 * n + 1]), x = mesh.coords[3 * n] - lo;
      rank[n] = inner + block[n] * 1000000000000L + std::lround(y * 1e4) * 1000000L + std::lround(x * 1e4);
    }
  std::vector<int> order(mesh.n_nodes());
  for (int n = 0; n < mesh.n_nodes(); ++n) order[n] = n;
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return rank[a] < rank[b]; });
  for (size_t k = 0; k < order.size(); ++k) mesh.node_names[order[k]] = "N" + std::to_string(k + 1);
}

Mesh make_ring_sleeve(const RingOptions& o) {
  const auto check_quad = [](const BlockCells& cells, const std::string& what) {
    if (cells.type != CellType::Quad4 && cells.type != CellType::Quad8)
      throw DeckError("meshgen: " + what + ": expected quad4 or quad8, got " +
                      std::string(engine::cell_info(cells.type).name));
  };
  check_quad(o.ring, "--ring");
  check_quad(o.sleeve, "--sleeve");
  if (!(0.0 < o.a && o.a < o.b && o.b < o.c))
  {
    std::ostringstream given;
    given << o.a << ", " << o.b << ", " << o.c;
    throw DeckError("meshgen: ring radii must satisfy 0 < a < b < c, got " + given.str());
  }
  Builder b;
  const int ring = b.new_pool();
  const int sleeve = b.new_pool();
  mesh_annulus(b, o.ring, {o.a, o.b, "RING", "INNER", "RING_OUT", "X0_RING", "Y0_RING", ring});
  mesh_annulus(b, o.sleeve, {o.b, o.c, "SLEEVE", "SLEEVE_IN", "OUTER", "X0_SLEEVE", "Y0_SLEEVE", sleeve});
  for (const auto& [name, pool, x, y] : std::vector<std::tuple<std::string, int, double, double>>{
           {"A_X", ring, o.a, 0}, {"A_Y", ring, 0, o.a}, {"P_X", ring, o.b, 0}, {"P_Y", ring, 0, o.b},
           {"Q_X", sleeve, o.b, 0}, {"Q_Y", sleeve, 0, o.b}, {"C_X", sleeve, o.c, 0}, {"C_Y", sleeve, 0, o.c}})
    b.add_node_group(name, pool, {x, y, 0});
  return b.finish();
}

Mesh make_ssnp121_3d(const Ssnp121Options3d& o) {
  check_dim(o.v1, 3, "V1");
  check_dim(o.v2, 3, "V2");
  if (o.glued && (o.v1.type != o.v2.type || o.v1.n[0] != o.v2.n[0] || o.v1.n[1] != o.v2.n[1]))
    throw DeckError("meshgen: --glued needs the same cell type and x/y counts in V1 and V2");
  Builder b;
  const int p1 = b.new_pool();
  const int p2 = o.glued ? p1 : b.new_pool();
  BlockGeom v1{{0, 0, 0}, {1, 1, 1}, 3, 0.0, "V1", {{"ENCAST", 2, 0.0}, {"SURESC", 2, 1.0}}, p1};
  BlockGeom v2{{0, 0, 1}, {1, 1, 2}, 3, 0.0, "V2", {{"SURMAI", 2, 1.0}, {"SURCHA", 2, 2.0}}, p2};
  if (o.x_faces) {
    v1.faces.push_back({"X0_V1", 0, 0.0}), v1.faces.push_back({"X1_V1", 0, 1.0});
    v2.faces.push_back({"X0_V2", 0, 0.0}), v2.faces.push_back({"X1_V2", 0, 1.0});
  }
  BlockMesher(b, o.v1, v1).run();
  BlockMesher(b, o.v2, v2).run();
  if (o.v3.n[0] > 0) {
    check_dim(o.v3, 3, "V3");
    const int p3 = b.new_pool();
    BlockGeom v3{{0, 0, 2}, {1, 1, 3}, 3, 0.0, "V3", {{"SURBA3", 2, 2.0}, {"SURCH3", 2, 3.0}}, p3};
    BlockMesher(b, o.v3, v3).run();
    b.add_node_group("A31", p3, {0, 0, 2});
    b.add_node_group("A32", p3, {1, 0, 2});
    b.add_node_group("A33", p3, {1, 1, 2});
    b.add_node_group("A34", p3, {0, 1, 2});
  }
  b.add_node_group("A21", p1, {0, 0, 1});
  b.add_node_group("A22", p1, {1, 0, 1});
  b.add_node_group("A23", p1, {1, 1, 1});
  b.add_node_group("A24", p1, {0, 1, 1});
  return b.finish();
}

Mesh make_block(const BlockOptions& o) {
  const int dim = engine::cell_info(o.cells.type).dim;
  if (dim < 2) throw DeckError("meshgen: a block needs a 2D or 3D cell type");
  Builder b;
  const int pool = b.new_pool();
  const bool rect = o.lo != std::array<double, 2>{0.0, 0.0} || o.hi != std::array<double, 2>{1.0, 1.0};
  if (rect && dim != 2) throw DeckError("meshgen: a block rectangle (--rect) needs a 2D cell type");
  if (!(o.lo[0] < o.hi[0] && o.lo[1] < o.hi[1])) throw DeckError("meshgen: --rect needs X0 < X1 and Y0 < Y1");
  BlockGeom g{{o.lo[0], o.lo[1], 0}, {o.hi[0], o.hi[1], dim == 3 ? 1.0 : 0.0}, dim, o.distort, "BLOCK", {}, pool};
  g.faces = {{"LEFT", 0, g.lo[0]}, {"RIGHT", 0, g.hi[0]}};
  if (dim == 2) {
    g.faces.push_back({"BOTTOM", 1, g.lo[1]});
    g.faces.push_back({"TOP", 1, g.hi[1]});
  } else {
    g.faces.push_back({"FRONT", 1, 0.0});
    g.faces.push_back({"BACK", 1, 1.0});
    g.faces.push_back({"BOTTOM", 2, 0.0});
    g.faces.push_back({"TOP", 2, 1.0});
  }
  BlockMesher(b, o.cells, g).run();
  const int n_corners = dim == 2 ? 4 : 8;
  for (int c = 0; c < n_corners; ++c) {
    const int x = c & 1, y = (c >> 1) & 1, z = (c >> 2) & 1;
    std::string name = "C" + std::to_string(x) + std::to_string(y) + (dim == 3 ? std::to_string(z) : "");
    b.add_node_group(name, pool, {x ? g.hi[0] : g.lo[0], y ? g.hi[1] : g.lo[1], double(z)});
  }
  return b.finish();
}

void mirror_cell_groups(Mesh& mesh, const std::vector<std::string>& groups) {
  const auto reorder = [&](int c, const std::vector<int>& perm) {
    int* target = &mesh.cell_nodes[mesh.cell_offsets[c]];
    const std::vector<int> old(target, target + mesh.cell_n_nodes(c));
    for (size_t k = 0; k < perm.size(); ++k) target[k] = old[perm[k]];
  };
  std::vector<char> mirrored(mesh.n_cells(), 0);
  for (const std::string& g : groups) {
    const auto it = mesh.cell_groups.find(g);
    if (it == mesh.cell_groups.end()) throw DeckError("meshgen: no cell group '" + g + "' to mirror");
    int n = 0;
    for (int c : it->second)
      if (engine::cell_info(mesh.cell_types[c]).dim == mesh.dim && !mirrored[c]) mirrored[c] = 1, ++n;
    if (n == 0) throw DeckError("meshgen: group '" + g + "' holds no " + std::to_string(mesh.dim) + "D cell");
  }
  std::vector<std::vector<int>> volumes_of_node(mesh.n_nodes());
  for (int c = 0; c < mesh.n_cells(); ++c)
    if (mirrored[c]) {
      for (int k = 0; k < mesh.cell_n_nodes(c); ++k) volumes_of_node[mesh.cell(c)[k]].push_back(c);
      reorder(c, engine::cell_mirror_permutation(mesh.cell_types[c]));
    }
  for (int c = 0; c < mesh.n_cells(); ++c) {
    if (engine::cell_info(mesh.cell_types[c]).dim != mesh.dim - 1) continue;
    const int* nodes = mesh.cell(c);
    const int nn = mesh.cell_n_nodes(c);
    const bool on_mirrored = std::any_of(volumes_of_node[nodes[0]].begin(), volumes_of_node[nodes[0]].end(), [&](int v) {
      const int* vn = mesh.cell(v);
      return std::all_of(nodes, nodes + nn, [&](int n) { return std::find(vn, vn + mesh.cell_n_nodes(v), n) != vn + mesh.cell_n_nodes(v); });
    });
    if (on_mirrored) reorder(c, engine::cell_reverse_permutation(mesh.cell_types[c]));
  }
}

}  // namespace lunaster::tools

