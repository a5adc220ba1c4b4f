#pragma once
/// Small-strain kinematics of a volume cell (internal to the assembly): the strain rows of the
/// element (B, strain = B u_e), the integration weight, and the map between those rows and the
/// behaviour's tensor. A large-rotation kinematics replaces this piece (same members, B then
/// depends on u_e and adds a geometric stiffness); the behaviours and the element loop stay.
#include <Eigen/Core>

#include "engine/assembly/element_kernels.hpp"
#include "engine/material/behaviour.hpp"

namespace lunaster::engine::kernels {

/// Element strain rows: plane (xx, yy, xy), axisymmetric (rr, zz, tt, rz), 3D (xx, yy, zz, xy,
/// xz, yz), engineering shears. The plane zz strain is not a row (0 in plane strain, the
/// behaviour's in plane stress).
template <int NN, int DIM, bool AXIS>
class SmallStrain {
 public:
  static_assert(DIM == 3 || DIM == 2, "2D or 3D cells");
  static_assert(!AXIS || DIM == 2, "axisymmetric cells are 2D");
  /// strain = B u_e, B independent of u_e (the element loop's small-strain path).
  static constexpr bool kLinear = true;
  static constexpr int kNodes = NN, kDim = DIM, kDofs = NN * DIM;
  static constexpr int kRows = DIM == 3 ? 6 : (AXIS ? kVoigtAxis : 3);
  using Coordinates = Eigen::Matrix<double, NN, DIM>;
  using BMatrix = Eigen::Matrix<double, kRows, kDofs>;
  using Rows = Eigen::Matrix<double, kRows, 1>;
  using RowsMatrix = Eigen::Matrix<double, kRows, kRows>;

  SmallStrain(const Mesh& mesh, int cell)
      : mesh_(mesh), cell_(cell), re_(reference_element(mesh.cell_types[cell])),
        x_(cell_coordinates<NN, DIM>(mesh, cell)) {}

  int n_points() const { return re_.n_qp; }

  /// B at point q; returns the weight |det J| w_q (AXIS: times r, per radian). Checks the
  /// Jacobian's sign against the cell's other points (DeckError for a tangled cell).
  double point(int q, BMatrix& b) {
    if constexpr (AXIS) {
      return axis_point<NN>(re_, q, x_, mesh_, cell_, sign_, g_, b);
    } else {
      const double det = physical_gradients<NN, DIM>(re_, q, x_, g_);
      check_jacobian(det, sign_, mesh_, cell_);
      strain_matrix<NN, DIM>(g_, b);
      return std::abs(det) * re_.weight[q];
    }
  }

  /// The behaviour's tensor (tensor_size(DIM) entries) of element strain rows.
  static void to_tensor(const Rows& e, TensorVector& t) {
    if constexpr (DIM == 2 && !AXIS) {
      t.resize(4);
      t << e(0), e(1), 0.0, e(2);
    } else {
      t = e;
    }
  }
  /// Element rows of a behaviour's stress.
  static Rows from_tensor(const TensorVector& s) {
    if constexpr (DIM == 2 && !AXIS) {
      return Rows(s(0), s(1), s(3));
    } else {
      return s;
    }
  }
  /// Element rows and columns of a behaviour's tangent (plane: the xx, yy, xy block).
  static RowsMatrix from_tangent(const TangentMatrix& d) {
    if constexpr (DIM == 2 && !AXIS) {
      const int map[3] = {0, 1, 3};
      RowsMatrix out;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) out(i, j) = d(map[i], map[j]);
      return out;
    } else {
      return d;
    }
  }

 private:
  const Mesh& mesh_;
  const int cell_;
  const ReferenceElement& re_;
  const Coordinates x_;
  Eigen::Matrix<double, NN, DIM> g_;
  double sign_ = 0.0;
};

}  // namespace lunaster::engine::kernels
