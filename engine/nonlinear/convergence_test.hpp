#pragma once
/// Newton's convergence test on the residual (code_aster's RESI_GLOB_RELA and RESI_GLOB_MAXI):
/// the free residual's largest entry, absolute and relative to the largest load or reaction.
#include <vector>

#include "engine/nonlinear/constraints.hpp"
#include "engine/nonlinear/newton_options.hpp"
#include "engine/nonlinear/rank_layout.hpp"

namespace lunaster::engine {

/// The residual of one Newton iteration, measured.
struct ResidualNorms {
  double relative = 0.0;  ///< |r_F| / max(|f_ext|, |reactions|, round-off floor)
  double absolute = 0.0;  ///< |r_F| (N)
};

class ConvergenceTest {
 public:
  /// `options` and `layout` are borrowed for the run; `stiffness_scale`: the largest |K_ij|,
  /// which sets the floor of the relative residual's reference with the largest displacement:
  /// `displacement` flags, per equation, the displacement unknowns (the multipliers, in Pa,
  /// are no displacements: with LAGS_C of 1e6 Pa the floor was a million times too high).
  ConvergenceTest(const NewtonOptions& options, const RankLayout& layout, double stiffness_scale,
                  std::vector<char> displacement)
      : options_(options), layout_(layout), stiffness_scale_(stiffness_scale), displacement_(std::move(displacement)) {}
  /// The residual's free rows into r_free (n_free), and its norms. Collective in parts.
  ResidualNorms measure(const Constraints& cons, const Vector& residual, const Vector& f_ext, const Vector& u,
                        int owned_free, Vector& r_free) const;
  /// Whether Newton stops at iteration `iter` of a loop with these norms: within both
  /// tolerances, the contact conditions met (`contact_ok`), and, at the start of a later contact
  /// pass (`previous_absolute` >= 0: the absolute residual the previous pass converged with), a
  /// residual the new pairing left where it was.
  bool converged(const ResidualNorms& norms, int iter, double previous_absolute, bool contact_ok) const;

 private:
  const NewtonOptions& options_;
  const RankLayout& layout_;
  double stiffness_scale_;
  std::vector<char> displacement_;
};

}  // namespace lunaster::engine
