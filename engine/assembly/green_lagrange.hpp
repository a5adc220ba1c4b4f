#pragma once
/// Total Lagrangian kinematics of a volume cell (internal to the assembly): large displacements
/// and rotations on the initial configuration, the behaviour seeing the Green-Lagrange strain
/// E = (F^T F - I) / 2, F = I + grad_X u, and returning the second Piola-Kirchhoff stress S.
/// The members of SmallStrain, with B = dE/du_e depending on u_e (point() takes u_e and gives E),
/// the tangent's geometric part int G^T S G dV0 (add_geometric) and the Cauchy stress
/// sigma = F S F^T / det F of a point (cauchy) for the result fields. A rigid rotation
/// (F orthogonal) gives E = 0, hence S = 0 and no internal force, whatever its angle.
#include <cmath>

#include <Eigen/Core>
#include <Eigen/LU>

#include "engine/assembly/small_strain.hpp"

namespace lunaster::engine::kernels {

/// Smallest volume ratio det F accepted at a point: below it the cell is inverted or about to be
/// and the step's end is no admissible state (the step is to be subdivided).
constexpr double kMinVolumeRatio = 1e-6;

/// Element strain rows as SmallStrain's: plane (xx, yy, xy), axisymmetric (rr, zz, tt, rz), 3D
/// (xx, yy, zz, xy, xz, yz), engineering shears (2 E_xy). Plane strain: F_zz = 1, E_zz = 0;
/// axisymmetric: F_tt = 1 + u_r / R (R the initial radius).
template <int NN, int DIM, bool AXIS>
class GreenLagrange {
  using Base = SmallStrain<NN, DIM, AXIS>;

 public:
  /// B depends on u_e, the tangent adds a geometric part, the stress is S (Cauchy on output).
  static constexpr bool kLinear = false;
  static constexpr int kNodes = NN, kDim = DIM, kDofs = NN * DIM, kRows = Base::kRows;
  using Coordinates = typename Base::Coordinates;
  using BMatrix = typename Base::BMatrix;
  using Rows = typename Base::Rows;
  using RowsMatrix = typename Base::RowsMatrix;
  using Dofs = Eigen::Matrix<double, kDofs, 1>;
  using Stiffness = Eigen::Matrix<double, kDofs, kDofs>;

  GreenLagrange(const Mesh& mesh, int cell)
      : mesh_(mesh), cell_(cell), re_(reference_element(mesh.cell_types[cell])),
        x_(cell_coordinates<NN, DIM>(mesh, cell)) {}

  int n_points() const { return re_.n_qp; }

  /// At point q for element displacements `ue` (node by node): the strain rows E in `e`, their
  /// derivative B = dE/du_e in `b`; returns the initial configuration's weight |det J| w_q (AXIS:
  /// times R, per radian). Keeps F for add_geometric, cauchy and volume_ratio at this point.
  /// Checks the Jacobian as SmallStrain does.
  double point(int q, const Dofs& ue, BMatrix& b, Rows& e) {
    const double weight = reference_gradients(q);
    f_.setIdentity();
    for (int a = 0; a < NN; ++a)
      for (int i = 0; i < DIM; ++i)
        for (int j = 0; j < DIM; ++j) f_(i, j) += ue(DIM * a + i) * g_(a, j);
    if constexpr (AXIS)
      for (int a = 0; a < NN; ++a) f_(2, 2) += ue(2 * a) * hoop_(a);
    const Eigen::Matrix3d c = f_.transpose() * f_;
    if constexpr (DIM == 3) {
      e << 0.5 * (c(0, 0) - 1.0), 0.5 * (c(1, 1) - 1.0), 0.5 * (c(2, 2) - 1.0), c(0, 1), c(0, 2), c(1, 2);
    } else if constexpr (AXIS) {
      e << 0.5 * (c(0, 0) - 1.0), 0.5 * (c(1, 1) - 1.0), 0.5 * (c(2, 2) - 1.0), c(0, 1);
    } else {
      e << 0.5 * (c(0, 0) - 1.0), 0.5 * (c(1, 1) - 1.0), c(0, 1);
    }
    strain_rows(b);
    return weight;
  }

  /// det F at the last point().
  double volume_ratio() const { return f_.determinant(); }

  /// Adds w G^T S G to `ke` at the last point(): (a k, b l) gets delta_kl w grad N_a . S grad N_b
  /// (AXIS: and w S_tt N_a N_b / R^2 for k = l = r). `s`: the behaviour's stress tensor.
  void add_geometric(const TensorVector& s, double w, Stiffness& ke) const {
    const Eigen::Matrix3d sm = full_tensor(s);
    const Eigen::Matrix<double, NN, DIM> gs = g_ * sm.template topLeftCorner<DIM, DIM>();
    const Eigen::Matrix<double, NN, NN> k = w * (gs * g_.transpose());
    for (int a = 0; a < NN; ++a)
      for (int bb = 0; bb < NN; ++bb)
        for (int l = 0; l < DIM; ++l) ke(DIM * a + l, DIM * bb + l) += k(a, bb);
    if constexpr (AXIS) {  // the hoop stretch moves with u_r only
      const double wt = w * sm(2, 2);
      for (int a = 0; a < NN; ++a)
        for (int bb = 0; bb < NN; ++bb) ke(2 * a, 2 * bb) += wt * hoop_(a) * hoop_(bb);
    }
  }

  /// Cauchy stress F S F^T / det F of the PK2 tensor `s` at the last point(), same layout.
  TensorVector cauchy(const TensorVector& s) const {
    const Eigen::Matrix3d sigma = f_ * full_tensor(s) * f_.transpose() / f_.determinant();
    TensorVector out(s.size());
    if constexpr (DIM == 3) {
      out << sigma(0, 0), sigma(1, 1), sigma(2, 2), sigma(0, 1), sigma(0, 2), sigma(1, 2);
    } else {
      out << sigma(0, 0), sigma(1, 1), sigma(2, 2), sigma(0, 1);
    }
    return out;
  }

  static void to_tensor(const Rows& e, TensorVector& t) { Base::to_tensor(e, t); }
  static Rows from_tensor(const TensorVector& s) { return Base::from_tensor(s); }
  static RowsMatrix from_tangent(const TangentMatrix& d) { return Base::from_tangent(d); }

 private:
  /// Gradients of the shape functions on the initial configuration at point q (and N_a / R);
  /// returns the weight.
  double reference_gradients(int q) {
    const double det = physical_gradients<NN, DIM>(re_, q, x_, g_);
    check_jacobian(det, sign_, mesh_, cell_);
    double weight = std::abs(det) * re_.weight[q];
    if constexpr (AXIS) {
      const double* n = &re_.n[static_cast<size_t>(q) * NN];
      double r = 0.0;
      for (int a = 0; a < NN; ++a) r += n[a] * x_(a, 0);
      if (!(r > 0.0))
        throw DeckError("cell " + cell_label(mesh_, cell_) + " (axisymmetric): integration point at radius r = " +
                        std::to_string(r) + " (expected r > 0; x is the radius in an axisymmetric model)");
      for (int a = 0; a < NN; ++a) hoop_(a) = n[a] / r;
      weight *= r;
    }
    return weight;
  }

  /// B = dE/du_e: the rows of sym(F^T grad delta u) (engineering shears), F at this point.
  void strain_rows(BMatrix& b) const {
    b.setZero();
    for (int a = 0; a < NN; ++a)
      for (int k = 0; k < DIM; ++k) {
        const int col = DIM * a + k;
        b(0, col) = f_(k, 0) * g_(a, 0);
        b(1, col) = f_(k, 1) * g_(a, 1);
        if constexpr (DIM == 3) {
          b(2, col) = f_(k, 2) * g_(a, 2);
          b(3, col) = f_(k, 0) * g_(a, 1) + f_(k, 1) * g_(a, 0);
          b(4, col) = f_(k, 0) * g_(a, 2) + f_(k, 2) * g_(a, 0);
          b(5, col) = f_(k, 1) * g_(a, 2) + f_(k, 2) * g_(a, 1);
        } else if constexpr (AXIS) {
          if (k == 0) b(2, col) = f_(2, 2) * hoop_(a);
          b(3, col) = f_(k, 0) * g_(a, 1) + f_(k, 1) * g_(a, 0);
        } else {
          b(2, col) = f_(k, 0) * g_(a, 1) + f_(k, 1) * g_(a, 0);
        }
      }
  }

  /// The symmetric 3 x 3 tensor of a behaviour's stress (2D: xz = yz = 0).
  static Eigen::Matrix3d full_tensor(const TensorVector& s) {
    Eigen::Matrix3d m;
    if constexpr (DIM == 3) {
      m << s(0), s(3), s(4), s(3), s(1), s(5), s(4), s(5), s(2);
    } else {
      m << s(0), s(3), 0.0, s(3), s(1), 0.0, 0.0, 0.0, s(2);
    }
    return m;
  }

  const Mesh& mesh_;
  const int cell_;
  const ReferenceElement& re_;
  const Coordinates x_;
  Eigen::Matrix<double, NN, DIM> g_;    ///< grad_X N_a at the last point
  Eigen::Matrix<double, NN, 1> hoop_;   ///< N_a / R at the last point (AXIS)
  Eigen::Matrix3d f_;                   ///< F at the last point
  double sign_ = 0.0;
};

/// Calls f(kinematics) with the total Lagrangian kinematics of a volume cell of `model` (its
/// type's node count and dimension, axisymmetric or not). DeckError for a plane stress cell (its
/// thickness stretch, the behaviour's, is not known to the kinematics).
template <class F>
decltype(auto) with_green_lagrange(const FeModel& model, int cell, F&& f) {
  if (model.modelisation[cell] == Modelisation::PlaneStress)
    throw DeckError("cell " + cell_label(*model.mesh, cell) +
                    ": large rotations (total Lagrangian) are not available in plane stress");
  return dispatch_volume(model.mesh->cell_types[cell], [&](auto nn, auto dim) {
    constexpr int NN = decltype(nn)::value, DIM = decltype(dim)::value;
    if constexpr (DIM == 2) {
      if (model.modelisation[cell] == Modelisation::Axisymmetric) {
        GreenLagrange<NN, 2, true> kin(*model.mesh, cell);
        return f(kin);
      }
    }
    GreenLagrange<NN, DIM, false> kin(*model.mesh, cell);
    return f(kin);
  });
}

}  // namespace lunaster::engine::kernels
