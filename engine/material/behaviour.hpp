#pragma once
/// The constitutive law at an integration point: from the state at a step's start and the
/// strain at its end, the stress, the internal variables at the end and the tangent. A
/// behaviour is data in, data out (as MGIS's integrate(BehaviourData&)): it holds its
/// material constants only, never a point's history; the history lives in MaterialStates.
///
/// Tensors are symmetric, in Voigt order with engineering shears (gamma_xy = 2 eps_xy):
/// 2D (xx, yy, zz, xy), 3D (xx, yy, zz, xy, xz, yz). In an axisymmetric model x is the
/// radius, y the axis and zz the hoop component. The strain measure is the kinematics' (small
/// strain today; a large-rotation kinematics hands its own measure and takes the conjugate
/// stress back, the behaviour does not know which).
#include <string>
#include <vector>

#include <Eigen/Core>

#include "engine/fe/fe_model.hpp"

namespace lunaster::engine {

/// Largest tensor size (3D); 2D tensors use the first 4 entries.
constexpr int kMaxTensorSize = 6;
/// A symmetric tensor in the Voigt order above (4 or 6 entries, no heap storage).
using TensorVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxTensorSize, 1>;
/// d stress / d strain, size n x n with n the tensor size.
using TangentMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxTensorSize, kMaxTensorSize>;

/// Tensor size of a model of dimension `dim`: 4 in 2D, 6 in 3D.
inline int tensor_size(int dim) { return dim == 2 ? 4 : 6; }

/// What a behaviour reads at one point. The zz strain of a plane model is 0 (plane stress: the
/// behaviour finds the zz strain that makes the zz stress vanish and returns the condensed tangent).
struct PointInput {
  Modelisation hypothesis = Modelisation::Solid3D;
  TensorVector strain_start;              ///< strain at the step's start
  TensorVector strain_end;                ///< strain at the step's end (trial)
  TensorVector stress_start;              ///< stress at the step's start, Pa
  const double* variables_start = nullptr;  ///< internal variables at the step's start (n_variables())
};

/// What a behaviour writes at one point. `variables_end` points at n_variables() values owned by
/// the caller (the state store's trial slot).
struct PointOutput {
  TensorVector stress;               ///< stress at the step's end, Pa
  double* variables_end = nullptr;   ///< internal variables at the step's end
  bool want_tangent = true;          ///< fill `tangent`
  TangentMatrix tangent;             ///< d stress_end / d strain_end (consistent tangent), Pa
};

/// Outcome of one point's integration. Failed: no admissible state at the end of this step (a
/// local iteration that did not converge): the step is to be subdivided.
enum class IntegrationStatus { Ok, Failed };

/// A constitutive law. Implementations are immutable once built and may be shared by many cells
/// and called from several threads at once.
class Behaviour {
 public:
  virtual ~Behaviour() = default;
  /// True when the stress is a fixed linear map of the strain, the same at every point of a cell
  /// and at every instant, with no internal variables: the tangent is then the stiffness, which
  /// a driver assembles once (per set of constraints) and keeps factorised.
  virtual bool is_linear() const = 0;
  /// False when the consistent tangent may lose positive definiteness (a softening law): a
  /// system built from it is then factorised as symmetric indefinite (LDL^T or LU), never by
  /// Cholesky.
  virtual bool tangent_positive_definite() const { return true; }
  /// Names of the internal variables, in storage order (e.g. {"EPSPEQ", "INDIPLAS"}).
  virtual const std::vector<std::string>& variable_names() const = 0;
  int n_variables() const { return static_cast<int>(variable_names().size()); }
  /// Integrates the law over one step at one point (sizes: tensor_size of the model).
  virtual IntegrationStatus integrate(const PointInput& in, PointOutput& out) const = 0;
};

}  // namespace lunaster::engine
