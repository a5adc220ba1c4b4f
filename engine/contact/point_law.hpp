#pragma once
/// A contact law at one point, for any number of conditions per point: the normal one and,
/// for friction, one per tangent direction (dim - 1). Where the point lives (its frame, its
/// gap function, its weight) is the discretisation's part (discretisation.hpp,
/// mortar_segments.hpp); the law sees only local quantities:
///
///   q = (g_n, g_t1[, g_t2])   the relative displacement in the point's frame (m): the normal
///                             gap (> 0 open) and the tangential relative displacement;
///   dq                        the tangential part's increment since the step's start;
///   z = (z_1, .., z_m)        the point's multipliers (Pa), the DOF-map components the law
///                             names (`multipliers`: LAGS_C, LAGS_F1, LAGS_F2 or none);
///   its state at the step's start (status, history variables).
///
/// It returns its local residual and tangent blocks and its status. The shared part maps them
/// to the unknowns with B = dq/du (the discretisation's gap gradients) and the multipliers'
/// interpolation phi:
///
///   r_u += B^T r_q                  K_uu += B^T k_qq B       K_uz += B^T k_qz phi^T
///   r_z += phi r_z                  K_zu += phi k_zq B       K_zz += phi k_zz phi^T
///
/// with k_.. the derivatives of (r_q, r_z) by (q, z). A law says whether the system it gives
/// is symmetric (`symmetric`): k_qq symmetric and either its multipliers do not enter the
/// displacement equations (k_qz = 0: the shared part condenses them and recovers them after
/// the solve, as penalty's LAGS_C) or [k_qq k_qz; k_zq k_zz] is symmetric. Such a system keeps
/// its symmetric (and, with multipliers condensed or eliminated, SPD) paths; a law that is not
/// symmetric (friction in slip: the tangential force follows the normal pressure, not the
/// other way round) routes the system to an unsymmetric factorisation.
///
/// States. A point's state is its status and the law's history variables (e.g. the slip at
/// which it last stuck). The shared part keeps two per point (PointStates): the state at the
/// step's start, which `evaluate` reads and never changes, and the state at the present
/// iterate, which `evaluate` writes. A converged step commits the second onto the first; a
/// subdivided step restores both from a snapshot.
#include <vector>

namespace lunaster::engine::contact {

/// Status of a contact point, numbered as CONT_NOEU's CONT: 0 open, 1 stick, 2 slip. A law
/// without friction reports a closed point as Stick (code_aster's CONT = 1 too).
enum class PointStatus : int { Open = 0, Stick = 1, Slip = 2 };

constexpr int kMaxPointGaps = 3;        ///< q: g_n and dim - 1 tangential components
constexpr int kMaxPointMultipliers = 3; ///< z: LAGS_C, LAGS_F1, LAGS_F2
constexpr int kMaxPointHistory = 4;     ///< history variables of a law at a point

/// A point's state: its status and the law's history variables (`PointLaw::n_history`).
struct PointState {
  PointStatus status = PointStatus::Open;
  double history[kMaxPointHistory] = {};

  friend bool operator==(const PointState&, const PointState&) = default;
};

/// What a law reads at a point.
struct PointKinematics {
  int n_tangents = 0;                          ///< dim - 1 (1 in 2D, 2 in 3D), or 0 (normal only)
  double q[kMaxPointGaps] = {};                ///< g_n, then g_t1[, g_t2] (m)
  double dq_step[kMaxPointGaps] = {};          ///< q minus its value at the step's start (m)
  double z[kMaxPointMultipliers] = {};         ///< the multipliers, in the order of `multipliers` (Pa)
  double weight = 0.0;                         ///< the point's weight in the current configuration (m, m^2)
  double coefficient = 0.0;                    ///< the zone's coefficient of the law (rho, E_N ...)
  double mu = 0.0;                             ///< the zone's friction coefficient (frictional laws)
  double coefficient_t = 0.0;                  ///< the zone's tangential coefficient (COEF_FROT, E_T ...)
};

/// What a law returns at a point (n_q = 1 + n_tangents, n_z = the law's multiplier count).
struct PointResponse {
  int n_q = 0, n_z = 0;
  double r_q[kMaxPointGaps] = {};                          ///< force conjugate to q (N, N per radian on AXIS)
  double r_z[kMaxPointMultipliers] = {};                   ///< the multipliers' equations
  double k_qq[kMaxPointGaps][kMaxPointGaps] = {};          ///< d r_q / d q
  double k_qz[kMaxPointGaps][kMaxPointMultipliers] = {};   ///< d r_q / d z
  double k_zq[kMaxPointMultipliers][kMaxPointGaps] = {};   ///< d r_z / d q
  double k_zz[kMaxPointMultipliers][kMaxPointMultipliers] = {};  ///< d r_z / d z
  PointStatus status = PointStatus::Open;
};

class PointLaw {
 public:
  virtual ~PointLaw() = default;
  virtual const char* name() const = 0;
  /// The multipliers a point carries, as DOF-map components (dof_map.hpp: LAGS_C, LAGS_F1,
  /// LAGS_F2), for a model of dimension `dim`; empty: none.
  virtual std::vector<int> multipliers(int dim) const = 0;
  /// Tangential components the law reads (0: the normal gap only; else dim - 1).
  virtual int n_tangents(int /*dim*/) const { return 0; }
  /// History variables per point (<= kMaxPointHistory).
  virtual int n_history(int /*dim*/) const { return 0; }
  /// True when the system the law gives is symmetric (see the header); false routes it to an
  /// unsymmetric factorisation.
  virtual bool symmetric() const { return true; }
  /// The response at `in`, from the point's state at the step's start. On entry `state` holds
  /// the point's present state (a law whose statuses an outer loop sets reads its status there);
  /// on return, the state at `in` (status, history).
  virtual PointResponse evaluate(const PointKinematics& in, const PointState& start, PointState& state) const = 0;
};

/// The states of a set of points: at the step's start (committed) and at the present iterate.
class PointStates {
 public:
  /// A snapshot: every status and every history variable of every point.
  struct Snapshot {
    std::vector<PointState> start, present;
  };

  void resize(size_t n) { start_.resize(n), present_.resize(n); }
  size_t size() const { return present_.size(); }
  const PointState& start(size_t i) const { return start_[i]; }
  PointState& present(size_t i) { return present_[i]; }
  const PointState& present(size_t i) const { return present_[i]; }
  /// A converged step: its end becomes the next step's start.
  void commit() { start_ = present_; }
  /// The present iterate back to the step's start (a Newton restarted within the step).
  void reset_to_start() { present_ = start_; }
  Snapshot snapshot() const { return {start_, present_}; }
  void restore(const Snapshot& s) { start_ = s.start, present_ = s.present; }
  /// How many points have `status` at the present iterate.
  int count(PointStatus status) const {
    int n = 0;
    for (const auto& s : present_) n += s.status == status;
    return n;
  }

 private:
  std::vector<PointState> start_, present_;
};

}  // namespace lunaster::engine::contact
