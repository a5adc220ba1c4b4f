#include "tools/hertz_mesh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <sstream>
#include <vector>

#include "engine/core/error.hpp"
#include "engine/mesh/cell_topology.hpp"
#include "engine/mesh/orientation.hpp"

namespace lunaster::tools {

namespace {

using engine::CellType;
using engine::Mesh;
using Vec3 = std::array<double, 3>;
/// A lattice node in half units: {2k or 2k+1 (shell, or between shells), 2i, 2j, 2l}.
/// Mid-side nodes are the half sums of the descriptors of their edge's ends.
using Desc = std::array<int, 4>;

/// Reference side of the ball's core with --grading 1, and the largest one allowed.
constexpr double kUniformCore = 1.0 / 3.0;
constexpr double kMaxBallCore = 0.34;

std::string fmt(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

/// One body: its lattice (core cells m per axis, shell scales per axis, blend) and map.
struct Body {
  bool ball = false;
  int dim = 2;
  std::array<int, 3> m{1, 1, 1};
  std::array<std::vector<double>, 3> scale;  ///< side of the core (k = 0) and of each shell, per axis
  std::vector<double> blend;                 ///< ball: 0 (square) .. 1 (sphere) per shell
  double r = 1.0, w = 1.0, h = 1.0;
  std::string group;
  std::array<std::string, 3> zero_face;  ///< boundary group on lattice coordinate a = 0
  std::array<std::string, 3> far_face;   ///< boundary group on the outer shell, face a
  int layers() const { return static_cast<int>(scale[0].size()) - 1; }
};

double at_half(const std::vector<double>& v, int k2) {
  return k2 % 2 == 0 ? v[k2 / 2] : 0.5 * (v[k2 / 2] + v[k2 / 2 + 1]);
}

Vec3 position(const Body& b, const Desc& d) {
  double p[3] = {0, 0, 0};
  double f[3] = {0, 0, 0};
  for (int a = 0; a < b.dim; ++a) {
    f[a] = static_cast<double>(d[1 + a]) / (2.0 * b.m[a]);
    p[a] = at_half(b.scale[a], d[0]) * f[a];
  }
  if (!b.ball) {
    const double depth = p[b.dim - 1] == 0.0 ? 0.0 : -b.h * p[b.dim - 1];
    return b.dim == 2 ? Vec3{b.w * p[0], depth, 0.0} : Vec3{b.w * p[0], b.w * p[1], depth};
  }
  const double t = at_half(b.blend, d[0]);
  if (t > 0.0) {  // equiangular projection of the square (cube) shell onto the sphere of the same size
    double dir[3] = {0, 0, 0}, norm = 0.0;
    for (int a = 0; a < b.dim; ++a) {
      dir[a] = f[a] == 1.0 ? 1.0 : f[a] == 0.0 ? 0.0 : std::tan(0.25 * M_PI * f[a]);
      norm += dir[a] * dir[a];
    }
    const double s = at_half(b.scale[0], d[0]) / std::sqrt(norm);
    for (int a = 0; a < b.dim; ++a) p[a] = (1.0 - t) * p[a] + t * s * dir[a];
  }
  // reference ball of radius 2 -> physical ball: X = (0, 2R) + 4R (u, -(w+2)) / |(u, w+2)|^2
  double u[3] = {2 * p[0], 2 * p[1], 2 * p[2]};
  u[b.dim - 1] += 2.0;
  const double den = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
  Vec3 x{0, 0, 0};
  for (int a = 0; a + 1 < b.dim; ++a) x[a] = 4 * b.r * u[a] / den;
  x[b.dim - 1] = 2 * b.r - 4 * b.r * u[b.dim - 1] / den;
  if (d[0] == 2 * b.layers()) x[b.dim - 1] = b.r;  // outer shell: exactly on the flat top
  return x;
}

class Writer {
 public:
  explicit Writer(Mesh& mesh) : mesh_(mesh) {}
  void body(const Body& b, CellType type);
  void node_group(const std::string& name, const Body& b, const Desc& d) {
    const auto it = index_.find(key(b, d));
    if (it != index_.end()) node_groups_[name].push_back(it->second);
  }
  void finish();

 private:
  std::pair<const Body*, Desc> key(const Body& b, const Desc& d) const { return {&b, d}; }
  int node(const Body& b, const Desc& d) {
    const auto [it, fresh] = index_.emplace(key(b, d), static_cast<int>(positions_.size()));
    if (fresh) positions_.push_back(position(b, d));
    return it->second;
  }
  void emit(const Body& b, CellType type, std::vector<Desc> vertices);

  struct Pending {
    CellType type;
    std::vector<int> nodes;
    std::string group;
  };
  Mesh& mesh_;
  std::map<std::pair<const Body*, Desc>, int> index_;
  std::vector<Vec3> positions_;
  std::vector<Pending> cells_;
  std::map<std::string, std::vector<int>> node_groups_;
};

/// Adds a cell from its vertex descriptors (MED order for a positive reference cell),
/// mirrored for the block (its map reverses orientation), and its boundary cells.
void Writer::emit(const Body& b, CellType type, std::vector<Desc> v) {
  if (!b.ball) {
    const std::vector<int> perm = v.size() == 3 ? std::vector<int>{0, 2, 1}
                                  : v.size() == 4 ? std::vector<int>{0, 3, 2, 1}
                                                  : std::vector<int>{4, 5, 6, 7, 0, 1, 2, 3};
    const std::vector<Desc> old = v;
    for (size_t k = 0; k < perm.size(); ++k) v[k] = old[perm[k]];
  }
  for (const auto& [p, q] : engine::cell_mid_edges(type))
    v.push_back({(v[p][0] + v[q][0]) / 2, (v[p][1] + v[q][1]) / 2, (v[p][2] + v[q][2]) / 2, (v[p][3] + v[q][3]) / 2});
  std::vector<int> nodes;
  for (const Desc& d : v) nodes.push_back(node(b, d));
  cells_.push_back({type, nodes, b.group});
  const engine::CellFaces& faces = engine::cell_faces(type);
  const int last_shell = 2 * b.layers();
  for (int f = 0; f < faces.n_faces; ++f) {
    const int n = engine::cell_info(faces.face_type[f]).n_nodes;
    const auto all = [&](auto pred) {
      for (int k = 0; k < n; ++k)
        if (!pred(v[faces.nodes[f][k]])) return false;
      return true;
    };
    for (int a = 0; a < b.dim; ++a) {
      std::string name;
      if (all([&](const Desc& d) { return d[1 + a] == 0; })) name = b.zero_face[a];
      else if (all([&](const Desc& d) { return d[0] == last_shell && d[1 + a] == 2 * b.m[a]; })) name = b.far_face[a];
      if (name.empty()) continue;
      std::vector<int> face(n);
      for (int k = 0; k < n; ++k) face[k] = nodes[faces.nodes[f][k]];
      cells_.push_back({faces.face_type[f], face, name});
    }
  }
}

void Writer::body(const Body& b, CellType type) {
  const bool tria = engine::linear_type(type) == CellType::Tria3;
  const auto add = [&](const std::vector<Desc>& c) {
    if (!tria) return emit(b, type, c);
    emit(b, type, {c[0], c[1], c[2]});
    emit(b, type, {c[0], c[2], c[3]});
  };
  // corner offsets e of a square / cube cell in MED vertex order
  const std::vector<std::array<int, 3>> corners =
      b.dim == 2 ? std::vector<std::array<int, 3>>{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}
                 : std::vector<std::array<int, 3>>{{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0},
                                                   {0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1}};
  const int nz = b.dim == 3 ? b.m[2] : 1;
  for (int l = 0; l < nz; ++l)  // core
    for (int j = 0; j < b.m[1]; ++j)
      for (int i = 0; i < b.m[0]; ++i) {
        std::vector<Desc> c;
        for (const auto& e : corners) c.push_back({0, 2 * (i + e[0]), 2 * (j + e[1]), 2 * (l + e[2])});
        add(c);
      }
  for (int k = 0; k < b.layers(); ++k)  // shells: one cell thick, patch p on the face x_p = side
    for (int p = 0; p < b.dim; ++p) {
      std::array<int, 3> n{b.m[0], b.m[1], b.dim == 3 ? b.m[2] : 1};
      n[p] = 1;
      for (int l = 0; l < n[2]; ++l)
        for (int j = 0; j < n[1]; ++j)
          for (int i = 0; i < n[0]; ++i) {
            const int idx[3] = {i, j, l};
            std::vector<Desc> c;
            for (const auto& e : corners) {
              Desc d{2 * (k + e[p]), 0, 0, 0};
              for (int a = 0; a < b.dim; ++a) d[1 + a] = a == p ? 2 * b.m[a] : 2 * (idx[a] + e[a]);
              c.push_back(d);
            }
            add(c);
          }
    }
}

void Writer::finish() {
  for (const Vec3& p : positions_) mesh_.add_node(p[0], p[1], p[2]);
  std::vector<int> order(cells_.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::stable_sort(order.begin(), order.end(), [this](int a, int b) {
    return engine::med_type_rank(cells_[a].type) < engine::med_type_rank(cells_[b].type);
  });
  std::map<std::string, std::vector<int>> groups;
  for (int i : order) groups[cells_[i].group].push_back(mesh_.add_cell(cells_[i].type, cells_[i].nodes));
  for (const auto& [name, cells] : groups) mesh_.add_to_cell_group(name, cells);
  for (const auto& [name, nodes] : node_groups_) mesh_.add_to_node_group(name, nodes);
  mesh_.detect_dimension();
}

/// Geometric shell sides from the core side s0 < 1 to 1 in `layers` steps.
std::vector<double> geometric(double s0, int layers) {
  std::vector<double> s(layers + 1);
  for (int k = 0; k < layers; ++k) s[k] = s0 * std::pow(1.0 / s0, static_cast<double>(k) / layers);
  s[layers] = 1.0;
  return s;
}

}  // namespace

Mesh make_hertz(const HertzOptions& o, HertzLayout* layout) {
  const int dim = engine::cell_info(o.type).dim;
  const CellType lin = engine::linear_type(o.type);
  if (!(lin == CellType::Quad4 || lin == CellType::Tria3 || lin == CellType::Hexa8))
    throw DeckError("meshgen: --hertz: expected quad4, quad8, tria3, tria6 (2D) or hexa8, hexa20 (3D), got " +
                    std::string(engine::cell_info(o.type).name));
  if (o.n < 1 || o.refine < 1) throw DeckError("meshgen: --hertz: the cell count N and --refine must be >= 1");
  if (!(o.radius > 0 && o.width > 0 && o.height > 0))
    throw DeckError("meshgen: --hertz: radius and block sizes must be > 0, got R = " + fmt(o.radius) + ", W = " +
                    fmt(o.width) + ", H = " + fmt(o.height));
  if (!(o.grading >= 1.0 && o.grading <= 4.0))
    throw DeckError("meshgen: --grading must lie in [1, 4], got " + fmt(o.grading));
  HertzLayout lay;
  lay.h0 = o.radius / (static_cast<double>(o.n) * o.refine);
  const bool graded = o.grading > 1.0;
  const int m = graded ? std::max(1, static_cast<int>(std::lround(1.0 / (o.grading - 1.0)))) : 0;

  Body ball;
  ball.ball = true;
  ball.dim = dim;
  ball.r = o.radius;
  ball.group = "BALL";
  const double ds = lay.h0 / (2.0 * o.radius);  // the map is R times the identity at O, on a radius-2 reference
  int k_ball = 0;
  if (graded) {
    const double s0 = m * ds;
    k_ball = std::max(1, static_cast<int>(std::lround(std::log(1.0 / s0) / std::log(o.grading))));
    ball.m = {m, m, m};
    for (int a = 0; a < 3; ++a) ball.scale[a] = geometric(s0, k_ball);
    lay.g_ball = std::pow(1.0 / s0, 1.0 / k_ball);
  } else {  // quasi-uniform: core of a third of the reference radius, layers h0 thick
    const int n = std::max(1, static_cast<int>(std::lround(kUniformCore / ds)));
    k_ball = 2 * n;
    ball.m = {n, n, n};
    for (int a = 0; a < 3; ++a) {
      ball.scale[a].resize(k_ball + 1);
      for (int k = 0; k <= k_ball; ++k)
        ball.scale[a][k] = k == k_ball ? 1.0 : kUniformCore + (1.0 - kUniformCore) * k / k_ball;
    }
  }
  // The blend to the sphere follows log(s): the corner of shell k, at s_k ((1-t) sqrt(d) + t),
  // then moves outward from shell to shell as long as (sqrt(d) - 1) / log(1 / s0) < 1.
  const double s0 = ball.scale[0][0];
  if (s0 > kMaxBallCore)
    throw DeckError("meshgen: --hertz: the uniform core of m = " + std::to_string(m) + " cells of size h0 = " +
                    fmt(lay.h0) + " covers too much of the ball to round it off; use a larger N or --grading 1");
  ball.blend.resize(k_ball + 1);
  for (int k = 0; k <= k_ball; ++k)
    ball.blend[k] = k == k_ball ? 1.0 : std::log(ball.scale[0][k] / s0) / std::log(1.0 / s0);
  lay.m_ball = ball.m[0];
  lay.layers_ball = k_ball;

  Body block;
  block.dim = dim;
  block.w = o.width;
  block.h = o.height;
  block.group = "BLOCK";
  const double size[3] = {o.width, dim == 3 ? o.width : o.height, o.height};
  if (graded) {
    double smallest = 1.0;
    for (int a = 0; a < dim; ++a) {
      const double s0 = m * lay.h0 / size[a];
      if (s0 >= 1.0)
        throw DeckError("meshgen: --hertz: the uniform core of m = " + std::to_string(m) + " cells of size h0 = " +
                        fmt(lay.h0) + " does not fit in the block (" + fmt(size[a]) + "); use a larger N or --grading 1");
      smallest = std::min(smallest, s0);
    }
    const int k = std::max(1, static_cast<int>(std::lround(std::log(1.0 / smallest) / std::log(o.grading))));
    for (int a = 0; a < dim; ++a) {
      const double s0 = m * lay.h0 / size[a];
      block.m[a] = m;
      block.scale[a] = geometric(s0, k);
      lay.g_block[a] = std::pow(1.0 / s0, 1.0 / k);
    }
    lay.layers_block = k;
  } else {
    for (int a = 0; a < dim; ++a) {
      block.m[a] = std::max(1, static_cast<int>(std::lround(size[a] / lay.h0)));
      block.scale[a] = {1.0};
    }
  }
  if (dim == 2) block.m[2] = 1, ball.m[2] = 1;
  for (int a = 0; a < 3; ++a) lay.m_block[a] = block.m[a];

  if (dim == 2) {
    ball.zero_face = {"AXIS_BALL", "BALL_SURF", ""};
    ball.far_face = {"BALL_TOP", "BALL_TOP", ""};
    block.zero_face = {"AXIS_BLOCK", "BLOCK_TOP", ""};
    block.far_face = {"BLOCK_SIDE", "BLOCK_BOTTOM", ""};
  } else {
    ball.zero_face = {"SYMX_BALL", "SYMY_BALL", "BALL_SURF"};
    ball.far_face = {"BALL_TOP", "BALL_TOP", "BALL_TOP"};
    block.zero_face = {"SYMX_BLOCK", "SYMY_BLOCK", "BLOCK_TOP"};
    block.far_face = {"BLOCK_SIDE", "BLOCK_SIDE", "BLOCK_BOTTOM"};
  }

  Mesh mesh;
  Writer w(mesh);
  w.body(ball, o.type);
  w.body(block, o.type);
  w.node_group("O_BALL", ball, {0, 0, 0, 0});
  w.node_group("O_BLOCK", block, {0, 0, 0, 0});
  Desc c{2 * ball.layers(), 0, 0, 0}, dd{2 * block.layers(), 0, 0, 0};
  c[dim] = 2 * ball.m[dim - 1];
  dd[dim] = 2 * block.m[dim - 1];
  w.node_group("C_BALL", ball, c);
  w.node_group("D_BLOCK", block, dd);
  w.finish();
  engine::check_cell_orientation(mesh, "generated Hertz mesh");
  if (layout) *layout = lay;
  return mesh;
}

namespace {

/// The node order of a cell's mirror image (reversed orientation), as positions in its nodes.
std::vector<int> mirror_order(CellType t) {
  switch (t) {
    case CellType::Seg2: return {1, 0};
    case CellType::Seg3: return {1, 0, 2};
    case CellType::Tria3: return {0, 2, 1};
    case CellType::Tria6: return {0, 2, 1, 5, 4, 3};
    case CellType::Quad4: return {0, 3, 2, 1};
    case CellType::Quad8: return {0, 3, 2, 1, 7, 6, 5, 4};
    default: throw DeckError("meshgen: cannot mirror a " + std::string(engine::cell_info(t).name) + " cell");
  }
}

}  // namespace

Mesh mirrored_about_x0(const Mesh& mesh, double tol) {
  Mesh out = mesh;
  const int n = mesh.n_nodes();
  std::vector<int> image(n);
  for (int i = 0; i < n; ++i) {
    const double* x = mesh.node(i);
    image[i] = std::abs(x[0]) <= tol ? i : out.add_node(-x[0], x[1], x[2], "N" + std::to_string(out.n_nodes() + 1));
  }
  std::vector<int> cell_image(mesh.n_cells(), -1);
  std::vector<char> on_axis(mesh.n_cells(), 0);
  for (int c = 0; c < mesh.n_cells(); ++c) {
    const int* nodes = mesh.cell(c);
    bool axis = true;
    for (int a = 0; a < mesh.cell_n_nodes(c); ++a) axis = axis && image[nodes[a]] == nodes[a];
    on_axis[c] = axis;
    if (axis) continue;
    std::vector<int> mirrored;
    for (int a : mirror_order(mesh.cell_types[c])) mirrored.push_back(image[nodes[a]]);
    cell_image[c] = out.add_cell(mesh.cell_types[c], mirrored, "M" + std::to_string(out.n_cells() + 1));
  }
  for (const auto& [name, cells] : mesh.cell_groups) {
    std::vector<int> images;
    bool all_on_axis = true;
    for (int c : cells) {
      all_on_axis = all_on_axis && on_axis[c];
      if (cell_image[c] >= 0) images.push_back(cell_image[c]);
    }
    if (all_on_axis) {
      out.cell_groups.erase(name);
      continue;
    }
    out.add_to_cell_group(name, images);
  }
  for (const auto& [name, nodes] : mesh.node_groups) {
    std::vector<int> images;
    for (int i : nodes)
      if (image[i] != i) images.push_back(image[i]);
    if (!images.empty()) out.add_to_node_group(name, images);
  }
  // The cells on the axis are inside the mirrored body: dropped with their groups, and so are
  // their nodes' groups made of axis cells alone (AXIS_BALL, AXIS_BLOCK as node groups too).
  std::vector<int> keep;
  for (int c = 0; c < out.n_cells(); ++c)
    if (c >= mesh.n_cells() || !on_axis[c]) keep.push_back(c);
  if (keep.size() == static_cast<size_t>(out.n_cells())) return out;
  Mesh kept;
  kept.dim = out.dim, kept.name = out.name;
  kept.coords = out.coords, kept.node_names = out.node_names, kept.node_groups = out.node_groups;
  std::vector<int> renumber(out.n_cells(), -1);
  for (int c : keep) {
    renumber[c] = kept.add_cell(out.cell_types[c], std::vector<int>(out.cell(c), out.cell(c) + out.cell_n_nodes(c)),
                                "M" + std::to_string(kept.n_cells() + 1));
  }
  for (const auto& [name, cells] : out.cell_groups) {
    std::vector<int> moved;
    for (int c : cells)
      if (renumber[c] >= 0) moved.push_back(renumber[c]);
    if (!moved.empty()) kept.add_to_cell_group(name, moved);
  }
  return kept;
}

}  // namespace lunaster::tools
