/// Per-type reference tables (shape data at quadrature points, extrapolation).
#include "engine/fe/reference_element.hpp"

#include "engine/mesh/cell_topology.hpp"

#include <array>
#include <mutex>

#include <Eigen/Dense>

#include "engine/core/error.hpp"
#include "engine/fe/quadrature.hpp"
#include "engine/fe/shape.hpp"

namespace lunaster::engine {
namespace {

struct TypeFacts {
  int dim, n_nodes, n_vertices;
};

TypeFacts facts(CellType type) {
  switch (type) {
    case CellType::Point1: return {0, 1, 1};
    case CellType::Seg2: return {1, 2, 2};
    case CellType::Seg3: return {1, 3, 2};
    case CellType::Tria3: return {2, 3, 3};
    case CellType::Tria6: return {2, 6, 3};
    case CellType::Quad4: return {2, 4, 4};
    case CellType::Quad8: return {2, 8, 4};
    case CellType::Tetra4: return {3, 4, 4};
    case CellType::Tetra10: return {3, 10, 4};
    case CellType::Pyram5: return {3, 5, 5};
    case CellType::Penta6: return {3, 6, 6};
    case CellType::Penta15: return {3, 15, 6};
    case CellType::Hexa8: return {3, 8, 8};
    case CellType::Hexa20: return {3, 20, 8};
  }
  return {0, 0, 0};
}


/// Least-squares Gauss -> vertex fit, then linear interpolation to every node.
std::vector<double> build_extrapolation(const ReferenceElement& re, const std::vector<QuadraturePoint>& qp) {
  const CellType lin = linear_type(re.type);
  const int nv = cell_n_vertices(re.type);
  Eigen::MatrixXd m(re.n_qp, nv);
  double nl[kMaxCellNodes];
  for (int q = 0; q < re.n_qp; ++q) {
    shape_functions(lin, qp[q].xi, nl, nullptr);
    for (int v = 0; v < nv; ++v) m(q, v) = nl[v];
  }
  const Eigen::MatrixXd fit = (m.transpose() * m).ldlt().solve(m.transpose());  // nv x n_qp
  Eigen::MatrixXd e(re.n_nodes, re.n_qp);
  for (int a = 0; a < re.n_nodes; ++a) {
    double xi[3] = {0, 0, 0};
    reference_node(re.type, a, xi);
    shape_functions(lin, xi, nl, nullptr);
    e.row(a).setZero();
    for (int v = 0; v < nv; ++v) e.row(a) += nl[v] * fit.row(v);
  }
  std::vector<double> out(static_cast<size_t>(re.n_nodes) * re.n_qp);
  for (int a = 0; a < re.n_nodes; ++a)
    for (int q = 0; q < re.n_qp; ++q) out[static_cast<size_t>(a) * re.n_qp + q] = e(a, q);
  return out;
}

ReferenceElement build(CellType type) {
  LUNASTER_ASSERT(has_shape_functions(type), "reference_element: cell type without shape functions");
  ReferenceElement re;
  re.type = type;
  re.dim = cell_dim(type);
  re.n_nodes = cell_n_nodes(type);
  const auto& qp = full_integration(type);
  re.n_qp = static_cast<int>(qp.size());
  re.weight.resize(re.n_qp);
  re.n.resize(static_cast<size_t>(re.n_qp) * re.n_nodes);
  re.dn.resize(static_cast<size_t>(re.n_qp) * re.n_nodes * re.dim);
  for (int q = 0; q < re.n_qp; ++q) {
    re.weight[q] = qp[q].weight;
    shape_functions(type, qp[q].xi, &re.n[static_cast<size_t>(q) * re.n_nodes],
                    &re.dn[static_cast<size_t>(q) * re.n_nodes * re.dim]);
  }
  re.extrapolation = build_extrapolation(re, qp);
  return re;
}

}  // namespace

int cell_dim(CellType type) { return facts(type).dim; }
int cell_n_nodes(CellType type) { return facts(type).n_nodes; }
int cell_n_vertices(CellType type) { return facts(type).n_vertices; }
bool has_shape_functions(CellType type) { return type != CellType::Point1 && type != CellType::Pyram5; }

const ReferenceElement& reference_element(CellType type) {
  static std::array<ReferenceElement, kCellTypeCount> table;
  static std::array<std::once_flag, kCellTypeCount> once;
  const int t = static_cast<int>(type);
  std::call_once(once[t], [&] { table[t] = build(type); });
  return table[t];
}

}  // namespace lunaster::engine
