#pragma once
/// Fixed-size element kernels shared by assembly and post-processing
/// (internal to lunaster_fe). Templates run over the closed set of volume cell
/// types through `dispatch_volume`, so each instantiation lives in the .cpp
/// that calls it.
#include <string>
#include <type_traits>

#include <Eigen/Dense>

#include "engine/core/error.hpp"
#include "engine/fe/fe_model.hpp"
#include "engine/fe/reference_element.hpp"

namespace lunaster::engine::kernels {

template <int N>
using Int = std::integral_constant<int, N>;

/// Calls f(Int<n_nodes>, Int<dim>) for a 2D/3D volume cell type.
template <class F>
decltype(auto) dispatch_volume(CellType type, F&& f) {
  switch (type) {
    case CellType::Tria3: return f(Int<3>{}, Int<2>{});
    case CellType::Tria6: return f(Int<6>{}, Int<2>{});
    case CellType::Quad4: return f(Int<4>{}, Int<2>{});
    case CellType::Quad8: return f(Int<8>{}, Int<2>{});
    case CellType::Tetra4: return f(Int<4>{}, Int<3>{});
    case CellType::Tetra10: return f(Int<10>{}, Int<3>{});
    case CellType::Penta6: return f(Int<6>{}, Int<3>{});
    case CellType::Penta15: return f(Int<15>{}, Int<3>{});
    case CellType::Hexa8: return f(Int<8>{}, Int<3>{});
    case CellType::Hexa20: return f(Int<20>{}, Int<3>{});
    default: break;
  }
  throw InternalError("element kernel: cell type is not a 2D/3D volume cell");
}

/// Number of Voigt stress components used by the kernels: 3 in 2D (xx, yy, xy), 6 in 3D.
template <int DIM>
constexpr int kVoigt = DIM == 2 ? 3 : 6;

/// Node coordinates of a cell as an NN x DIM matrix.
template <int NN, int DIM>
Eigen::Matrix<double, NN, DIM> cell_coordinates(const Mesh& mesh, int cell) {
  Eigen::Matrix<double, NN, DIM> x;
  const int* nodes = mesh.cell(cell);
  for (int a = 0; a < NN; ++a)
    for (int k = 0; k < DIM; ++k) x(a, k) = mesh.coords[3 * static_cast<size_t>(nodes[a]) + k];
  return x;
}

/// Physical shape-function gradients at quadrature point q; returns det J.
template <int NN, int DIM>
double physical_gradients(const ReferenceElement& re, int q, const Eigen::Matrix<double, NN, DIM>& x,
                          Eigen::Matrix<double, NN, DIM>& grad) {
  const Eigen::Map<const Eigen::Matrix<double, NN, DIM, Eigen::RowMajor>> dref(
      &re.dn[static_cast<size_t>(q) * NN * DIM]);
  const Eigen::Matrix<double, DIM, DIM> jac = x.transpose() * dref;  // J(i,j) = dx_i/dxi_j
  const double det = jac.determinant();
  grad.noalias() = dref * jac.inverse();
  return det;
}

/// Strain-displacement matrix (engineering shears), DOFs ordered node by node.
template <int NN, int DIM>
void strain_matrix(const Eigen::Matrix<double, NN, DIM>& g, Eigen::Matrix<double, kVoigt<DIM>, NN * DIM>& b) {
  b.setZero();
  for (int a = 0; a < NN; ++a) {
    const int c = DIM * a;
    b(0, c) = g(a, 0);
    b(1, c + 1) = g(a, 1);
    if constexpr (DIM == 2) {
      b(2, c) = g(a, 1);
      b(2, c + 1) = g(a, 0);
    } else {
      b(2, c + 2) = g(a, 2);
      b(3, c) = g(a, 1);
      b(3, c + 1) = g(a, 0);
      b(4, c) = g(a, 2);
      b(4, c + 2) = g(a, 0);
      b(5, c + 1) = g(a, 2);
      b(5, c + 2) = g(a, 1);
    }
  }
}

/// Name of a cell for messages (its mesh name, or #index).
inline std::string cell_label(const Mesh& mesh, int cell) {
  return cell < static_cast<int>(mesh.cell_names.size()) ? mesh.cell_names[cell] : "#" + std::to_string(cell + 1);
}

/// Checks the Jacobian signs of a cell: all of one sign and non-zero. Cells of
/// either orientation are accepted (|det J| weights the integrals, as
/// code_aster does); a sign change or a zero means a tangled or degenerate cell.
inline void check_jacobian(double det, double& first_sign, const Mesh& mesh, int cell) {
  const double sign = det > 0 ? 1.0 : (det < 0 ? -1.0 : 0.0);
  if (first_sign == 0.0) first_sign = sign;
  if (sign == 0.0 || sign != first_sign) {
    const std::string name = cell < static_cast<int>(mesh.cell_names.size()) ? mesh.cell_names[cell]
                                                                                : "#" + std::to_string(cell + 1);
    throw DeckError("cell " + name + ": degenerate or tangled cell (Jacobian changes sign or vanishes)");
  }
}

/// Axisymmetric (AXIS) kernels. x is the radius r, y the axis. Strains in the order of the
/// stress components SIXX SIYY SIZZ SIXY: (eps_rr, eps_zz, eps_tt = u_r / r, gamma_rz), with
/// z the axis (mesh y) and t the hoop direction (reported as SIZZ, as code_aster does).
constexpr int kVoigtAxis = 4;

/// Strain-displacement matrix of an AXIS cell at a point of radius r > 0 where the shape
/// functions are `n` and their physical gradients `g`: rows rr, zz, tt (N_a / r), rz.
template <int NN>
void axis_strain_matrix(const Eigen::Matrix<double, NN, 2>& g, const double* n, double r,
                        Eigen::Matrix<double, kVoigtAxis, 2 * NN>& b) {
  b.setZero();
  for (int a = 0; a < NN; ++a) {
    const int c = 2 * a;
    b(0, c) = g(a, 0);
    b(1, c + 1) = g(a, 1);
    b(2, c) = n[a] / r;
    b(3, c) = g(a, 1);
    b(3, c + 1) = g(a, 0);
  }
}

/// One quadrature point of an AXIS cell: fills B and returns the integration weight
/// |det J| w_q r (per radian, code_aster's AXIS measure). Quadrature points are interior,
/// so r > 0 there for any cell with its nodes at r >= 0 and straight edges; a point at
/// r <= 0 (a cell lying on the axis, or curved across it) is a DeckError naming the cell.
template <int NN>
double axis_point(const ReferenceElement& re, int q, const Eigen::Matrix<double, NN, 2>& x, const Mesh& mesh,
                  int cell, double& sign, Eigen::Matrix<double, NN, 2>& g, Eigen::Matrix<double, kVoigtAxis, 2 * NN>& b) {
  const double det = physical_gradients<NN, 2>(re, q, x, g);
  check_jacobian(det, sign, mesh, cell);
  const double* n = &re.n[static_cast<size_t>(q) * NN];
  double r = 0.0;
  for (int a = 0; a < NN; ++a) r += n[a] * x(a, 0);
  if (!(r > 0.0))
    throw DeckError("cell " + cell_label(mesh, cell) + " (axisymmetric): integration point at radius r = " +
                    std::to_string(r) + " (expected r > 0; x is the radius in an axisymmetric model)");
  axis_strain_matrix<NN>(g, n, r, b);
  return std::abs(det) * re.weight[q] * r;
}

}  // namespace lunaster::engine::kernels
