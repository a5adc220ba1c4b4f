#pragma once
/// One cell's response (internal to the assembly and the stress recovery): the behaviour
/// integrated at each point of the cell's kinematics, giving the element's internal force
/// f_e = sum_q w_q B^T sigma, its tangent K_e = sum_q w_q B^T D_t B and the points' stresses.
/// The one element loop of the linear stiffness, the internal forces, the stresses and the
/// nonlinear tangent. Under the total Lagrangian kinematics B = B(u_e), sigma is the second
/// Piola-Kirchhoff stress S, K_e adds the geometric part sum_q w_q G^T S G and the points'
/// stresses are Cauchy's.
#include <Eigen/Core>

#include "engine/assembly/green_lagrange.hpp"
#include "engine/assembly/small_strain.hpp"
#include "engine/material/behaviour.hpp"
#include "engine/material/cell_behaviours.hpp"
#include "engine/material/material_states.hpp"

namespace lunaster::engine::kernels {

/// Calls f(kinematics) with the small-strain kinematics of a volume cell of `model` (its type's
/// node count and dimension, axisymmetric or not).
template <class F>
decltype(auto) with_small_strain(const FeModel& model, int cell, F&& f) {
  return dispatch_volume(model.mesh->cell_types[cell], [&](auto nn, auto dim) {
    constexpr int NN = decltype(nn)::value, DIM = decltype(dim)::value;
    if constexpr (DIM == 2) {
      if (model.modelisation[cell] == Modelisation::Axisymmetric) {
        SmallStrain<NN, 2, true> kin(*model.mesh, cell);
        return f(kin);
      }
    }
    SmallStrain<NN, DIM, false> kin(*model.mesh, cell);
    return f(kin);
  });
}

/// Calls f(kinematics) with the kinematics `kinematics` of a volume cell of `model`.
template <class F>
decltype(auto) with_kinematics(const FeModel& model, Kinematics kinematics, int cell, F&& f) {
  if (kinematics == Kinematics::TotalLagrangian) return with_green_lagrange(model, cell, f);
  return with_small_strain(model, cell, f);
}

/// What to compute for one cell. Without `ue` the strain is zero (the tangent at rest);
/// without `states` the step starts from a zero state and nothing is stored.
template <class Kin>
struct CellRequest {
  using Dofs = Eigen::Matrix<double, Kin::kDofs, 1>;
  const Dofs* ue = nullptr;                          ///< element displacements, node by node
  MaterialStates* states = nullptr;                  ///< start read, end (trial) written
  Eigen::Matrix<double, Kin::kDofs, Kin::kDofs>* ke = nullptr;  ///< tangent, set when given
  Dofs* fe = nullptr;                                ///< internal force, set when given
  Eigen::MatrixXd* point_stresses = nullptr;         ///< n_points x tensor size, set when given
};

/// Integrates `behaviour` over the points of one cell. A linear behaviour's tangent is taken at
/// the first point only (Behaviour::is_linear: the same at every point). Returns Failed at the
/// first point whose integration failed or, under large rotations, whose volume ratio det F is
/// below kMinVolumeRatio (the outputs are then incomplete).
template <class Kin>
IntegrationStatus cell_response(const Behaviour& behaviour, Modelisation hypothesis, int cell, Kin& kin,
                                const CellRequest<Kin>& req) {
  constexpr int ND = Kin::kDofs, NR = Kin::kRows, DIM = Kin::kDim;
  using Slot = MaterialStates::Slot;
  const int nt = tensor_size(DIM);
  PointInput in;
  in.hypothesis = hypothesis;
  PointOutput out;
  typename Kin::BMatrix b;
  Eigen::Matrix<double, NR, ND> db;
  typename Kin::RowsMatrix d;
  bool have_d = false;
  const bool linear = behaviour.is_linear();
  if (req.ke) req.ke->setZero();
  if (req.fe) req.fe->setZero();
  if (req.point_stresses) req.point_stresses->resize(kin.n_points(), nt);
  MaterialStates* st = req.states;
  for (int q = 0; q < kin.n_points(); ++q) {
    double w;
    typename Kin::Rows e;
    if constexpr (Kin::kLinear) {
      w = kin.point(q, b);
      e = req.ue ? typename Kin::Rows(b * *req.ue) : Kin::Rows::Zero();
    } else {
      w = req.ue ? kin.point(q, *req.ue, b, e) : kin.point(q, CellRequest<Kin>::Dofs::Zero(), b, e);
      if (!(kin.volume_ratio() >= kMinVolumeRatio)) return IntegrationStatus::Failed;
    }
    Kin::to_tensor(e, in.strain_end);
    if (st) {
      in.strain_start = Eigen::Map<const Eigen::VectorXd>(st->strain(Slot::Start, cell, q), nt);
      in.stress_start = Eigen::Map<const Eigen::VectorXd>(st->stress(Slot::Start, cell, q), nt);
      in.variables_start = st->variables(Slot::Start, cell, q);
      out.variables_end = st->variables(Slot::End, cell, q);
    } else {
      in.strain_start = TensorVector::Zero(nt);
      in.stress_start = TensorVector::Zero(nt);
    }
    out.want_tangent = req.ke && !(linear && have_d);
    if (behaviour.integrate(in, out) != IntegrationStatus::Ok) return IntegrationStatus::Failed;
    if (st) {
      Eigen::Map<Eigen::VectorXd>(st->strain(Slot::End, cell, q), nt) = in.strain_end;
      Eigen::Map<Eigen::VectorXd>(st->stress(Slot::End, cell, q), nt) = out.stress;
    }
    if (req.point_stresses) {
      if constexpr (Kin::kLinear) {
        req.point_stresses->row(q) = out.stress.transpose();
      } else {
        req.point_stresses->row(q) = kin.cauchy(out.stress).transpose();
      }
    }
    if (req.fe) req.fe->noalias() += w * (b.transpose() * Kin::from_tensor(out.stress));
    if (req.ke) {
      if (out.want_tangent) d = Kin::from_tangent(out.tangent), have_d = true;
      db.noalias() = w * (d * b);
      req.ke->noalias() += b.transpose() * db;
      if constexpr (!Kin::kLinear) kin.add_geometric(out.stress, w, *req.ke);
    }
  }
  return IntegrationStatus::Ok;
}

}  // namespace lunaster::engine::kernels
