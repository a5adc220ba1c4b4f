#pragma once
// Test helpers for fe/: structured, distorted meshes of every volume cell type
// built directly in a Mesh (no dependency on the mesh library's builders),
// boundary faces, and Dirichlet-by-elimination solves.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "engine/assembly/assembly.hpp"
#include "engine/assembly/dof_map.hpp"
#include "engine/fe/fe_model.hpp"
#include "engine/fe/reference_element.hpp"
#include "engine/fe/shape.hpp"
#include "engine/solver/linear_solver.hpp"

namespace lunaster::engine::test {

inline void expect_close(double a, double b, double rel, double abs_tol, const std::string& what = {}) {
  EXPECT_LE(std::abs(a - b), abs_tol + rel * std::max(std::abs(a), std::abs(b))) << what << ": " << a << " vs " << b;
}

/// Builds a mesh on [0,1]^dim with n cells per direction of one volume type
/// (triangles/prisms/tetrahedra subdivide squares/cubes), interior vertices
/// moved by up to `distortion`, mid-side nodes at straight-edge midpoints.
class BlockBuilder {
 public:
  BlockBuilder(CellType type, int n, double distortion) : type_(type), n_(n) {
    dim_ = cell_dim(type);
    mesh_.dim = dim_;
    const int nz = dim_ == 3 ? n : 0;
    for (int k = 0; k <= nz; ++k)
      for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
          double x[3] = {double(i) / n, double(j) / n, dim_ == 3 ? double(k) / n : 0.0};
          const bool interior = i > 0 && i < n && j > 0 && j < n && (dim_ == 2 || (k > 0 && k < n));
          if (interior) {  // deterministic pseudo-random offsets
            const int seed = 7 * i + 13 * j + 29 * k;
            for (int d = 0; d < dim_; ++d) x[d] += distortion / n * std::sin(1.7 * seed + 2.3 * d + 0.5);
          }
          add_node(x);
        }
  }

  int vertex(int i, int j, int k = 0) const { return (k * (n_ + 1) + j) * (n_ + 1) + i; }
  int dim() const { return dim_; }
  Mesh& mesh() { return mesh_; }

  int add_node(const double* x) {
    mesh_.coords.insert(mesh_.coords.end(), {x[0], x[1], x[2]});
    mesh_.node_names.push_back("N" + std::to_string(mesh_.node_names.size() + 1));
    return static_cast<int>(mesh_.node_names.size()) - 1;
  }

  /// Mid-side node of a vertex pair, shared between cells.
  int mid(int a, int b) {
    const auto key = std::minmax(a, b);
    auto it = mids_.find(key);
    if (it != mids_.end()) return it->second;
    double x[3];
    for (int d = 0; d < 3; ++d) x[d] = 0.5 * (mesh_.coords[3 * a + d] + mesh_.coords[3 * b + d]);
    return mids_[key] = add_node(x);
  }

  /// Adds a cell given its vertices (MED order); mid-side nodes are derived
  /// from the reference coordinates of the quadratic type.
  int add_cell(CellType type, std::vector<int> v) {
    const int nn = cell_n_nodes(type), nv = cell_n_vertices(type), rd = cell_dim(type);
    for (int a = nv; a < nn; ++a) {
      double xa[3] = {0, 0, 0};
      reference_node(type, a, xa);
      bool found = false;
      for (int i = 0; i < nv && !found; ++i)
        for (int j = i + 1; j < nv && !found; ++j) {
          double xi[3] = {0, 0, 0}, xj[3] = {0, 0, 0};
          reference_node(type, i, xi);
          reference_node(type, j, xj);
          bool same = true;
          for (int d = 0; d < rd; ++d) same = same && std::abs(0.5 * (xi[d] + xj[d]) - xa[d]) < 1e-12;
          // the edge must be a true edge: exactly one (tensor) or any (simplex) coordinate pair
          if (same && is_edge(type, xi, xj)) {
            v.push_back(mid(v[i], v[j]));
            found = true;
          }
        }
      EXPECT_TRUE(found) << "no edge for mid-side node " << a;
    }
    mesh_.cell_types.push_back(type);
    mesh_.cell_nodes.insert(mesh_.cell_nodes.end(), v.begin(), v.end());
    mesh_.cell_offsets.push_back(static_cast<int>(mesh_.cell_nodes.size()));
    mesh_.cell_names.push_back("M" + std::to_string(mesh_.cell_types.size()));
    return static_cast<int>(mesh_.cell_types.size()) - 1;
  }

  /// Fills the block with volume cells of the builder's type; returns their indices.
  std::vector<int> fill() {
    std::vector<int> cells;
    const CellType t = type_;
    const int nz = dim_ == 3 ? n_ : 1;
    for (int k = 0; k < nz; ++k)
      for (int j = 0; j < n_; ++j)
        for (int i = 0; i < n_; ++i) {
          if (dim_ == 2) {
            const int a = vertex(i, j), b = vertex(i + 1, j), c = vertex(i + 1, j + 1), d = vertex(i, j + 1);
            if (t == CellType::Quad4 || t == CellType::Quad8) {
              cells.push_back(add_cell(t, {a, b, c, d}));
            } else {
              cells.push_back(add_cell(t, {a, b, c}));
              cells.push_back(add_cell(t, {a, c, d}));
            }
            continue;
          }
          int c[8];  // cube corners: bottom ccw from (i,j), then top
          const int di[4] = {0, 1, 1, 0}, dj[4] = {0, 0, 1, 1};
          for (int q = 0; q < 8; ++q) c[q] = vertex(i + di[q % 4], j + dj[q % 4], k + q / 4);
          if (t == CellType::Hexa8 || t == CellType::Hexa20) {
            // MED: bottom face numbered clockwise seen from above (outward normal)
            cells.push_back(add_cell(t, {c[0], c[3], c[2], c[1], c[4], c[7], c[6], c[5]}));
          } else if (t == CellType::Penta6 || t == CellType::Penta15) {
            cells.push_back(add_cell(t, {c[0], c[2], c[1], c[4], c[6], c[5]}));
            cells.push_back(add_cell(t, {c[0], c[3], c[2], c[4], c[7], c[6]}));
          } else {
            // Kuhn subdivision into 6 tetrahedra along the diagonal c0-c6
            const int paths[6][2] = {{1, 2}, {1, 5}, {3, 2}, {3, 7}, {4, 5}, {4, 7}};
            for (const auto& p : paths) {
              std::vector<int> v = {c[0], c[p[0]], c[p[1]], c[6]};
              if (triple(v) > 0) std::swap(v[1], v[2]);  // MED: face (0,1,2) normal outward
              cells.push_back(add_cell(t, v));
            }
          }
        }
    return cells;
  }

  /// Boundary cells on the face x_{dim-1} = 1 (top), outward normal +y / +z.
  std::vector<int> top_faces() {
    std::vector<int> faces;
    const CellType vt = type_;
    const bool quadratic = cell_n_nodes(vt) > cell_n_vertices(vt);
    if (dim_ == 2) {
      for (int i = 0; i < n_; ++i)  // from right to left: t = -x, n = (t_y, -t_x) = +y
        faces.push_back(add_cell(quadratic ? CellType::Seg3 : CellType::Seg2, {vertex(i + 1, n_), vertex(i, n_)}));
      return faces;
    }
    const bool tri = vt == CellType::Tetra4 || vt == CellType::Tetra10 || vt == CellType::Penta6 ||
                     vt == CellType::Penta15;
    for (int j = 0; j < n_; ++j)
      for (int i = 0; i < n_; ++i) {
        const int a = vertex(i, j, n_), b = vertex(i + 1, j, n_), c = vertex(i + 1, j + 1, n_), d = vertex(i, j + 1, n_);
        if (tri) {
          const CellType ft = quadratic ? CellType::Tria6 : CellType::Tria3;
          // Kuhn tetrahedra and the prisms both split the top square along a-c
          faces.push_back(add_cell(ft, {a, b, c}));
          faces.push_back(add_cell(ft, {a, c, d}));
        } else {
          faces.push_back(add_cell(quadratic ? CellType::Quad8 : CellType::Quad4, {a, b, c, d}));
        }
      }
    return faces;
  }

 private:
  static bool is_edge(CellType type, const double* xi, const double* xj) {
    // Tensor cells (QUAD/HEXA and the prism axis): an edge changes one coordinate.
    // Simplex-like cells: every vertex pair is an edge, except the prism's
    // "diagonals" (different triangle vertex AND different level).
    switch (type) {
      case CellType::Quad8:
      case CellType::Hexa20: {
        int changed = 0;
        for (int d = 0; d < 3; ++d) changed += xi[d] != xj[d];
        return changed == 1;
      }
      case CellType::Penta15: return xi[2] == xj[2] || (xi[0] == xj[0] && xi[1] == xj[1]);
      default: return true;
    }
  }
  double triple(const std::vector<int>& v) const {
    const double* x0 = mesh_.node(v[0]);
    double e[3][3];
    for (int r = 0; r < 3; ++r)
      for (int d = 0; d < 3; ++d) e[r][d] = mesh_.node(v[r + 1])[d] - x0[d];
    return e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
           e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
  }

  CellType type_;
  int n_, dim_;
  Mesh mesh_;
  std::map<std::pair<int, int>, int> mids_;
};

/// A model over all cells of `mesh` of the given dimension, one material.
inline FeModel make_model(const Mesh& mesh, int dim, Modelisation mod, ElasticMaterial mat) {
  FeModel model;
  model.mesh = &mesh;
  model.dim = dim;
  model.materials = {mat};
  model.modelisation.assign(mesh.n_cells(), Modelisation::None);
  model.material.assign(mesh.n_cells(), -1);
  for (int c = 0; c < mesh.n_cells(); ++c)
    if (cell_dim(mesh.cell_types[c]) == dim) {
      model.modelisation[c] = mod;
      model.material[c] = 0;
    }
  return model;
}

inline SparseMatrix assemble_matrix(const FeModel& model, const DofMap& dofs) {
  std::vector<Triplet> t;
  assemble_stiffness(model, dofs, t);
  SparseMatrix k(dofs.n_dofs(), dofs.n_dofs());
  k.setFromTriplets(t.begin(), t.end());
  return k;
}

/// Solves K u = f with u(eq) = value imposed on `fixed` (elimination), CHOLMOD.
inline Vector solve_with_dirichlet(const SparseMatrix& k, const Vector& f, const std::map<int, double>& fixed) {
  const int n = static_cast<int>(k.rows());
  Vector u = Vector::Zero(n);
  std::vector<int> free_index(n, -1);
  int nf = 0;
  for (int i = 0; i < n; ++i) {
    auto it = fixed.find(i);
    if (it == fixed.end()) free_index[i] = nf++;
    else u(i) = it->second;
  }
  const Vector r = f - k * u;
  std::vector<Triplet> t;
  Vector rf(nf);
  for (int i = 0; i < n; ++i)
    if (free_index[i] >= 0) rf(free_index[i]) = r(i);
  for (int c = 0; c < k.outerSize(); ++c)
    for (SparseMatrix::InnerIterator it(k, c); it; ++it)
      if (free_index[it.row()] >= 0 && free_index[c] >= 0) t.emplace_back(free_index[it.row()], free_index[c], it.value());
  SparseMatrix kff(nf, nf);
  kff.setFromTriplets(t.begin(), t.end());
  auto solver = make_linear_solver(SolverKind::Cholmod);
  solver->factorize(kff, MatrixKind::SymmetricPositiveDefinite);
  const Vector uf = solver->solve(rf);
  for (int i = 0; i < n; ++i)
    if (free_index[i] >= 0) u(i) = uf(free_index[i]);
  return u;
}

inline const std::vector<CellType>& volume_types() {
  static const std::vector<CellType> types = {CellType::Tria3,   CellType::Tria6,  CellType::Quad4,  CellType::Quad8,
                                              CellType::Tetra4,  CellType::Tetra10, CellType::Penta6, CellType::Penta15,
                                              CellType::Hexa8,   CellType::Hexa20};
  return types;
}

inline std::string type_name(CellType t) {
  switch (t) {
    case CellType::Seg2: return "SEG2";
    case CellType::Seg3: return "SEG3";
    case CellType::Tria3: return "TRIA3";
    case CellType::Tria6: return "TRIA6";
    case CellType::Quad4: return "QUAD4";
    case CellType::Quad8: return "QUAD8";
    case CellType::Tetra4: return "TETRA4";
    case CellType::Tetra10: return "TETRA10";
    case CellType::Penta6: return "PENTA6";
    case CellType::Penta15: return "PENTA15";
    case CellType::Hexa8: return "HEXA8";
    case CellType::Hexa20: return "HEXA20";
    default: return "?";
  }
}

}  // namespace lunaster::engine::test
