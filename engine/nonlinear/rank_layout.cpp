#include "engine/nonlinear/rank_layout.hpp"

#include <cmath>
#include <limits>

#include "engine/parallel/mpi_runtime.hpp"

namespace lunaster::engine {

double RankLayout::largest_entry(const Vector& v, int n_owned) const {
  if (!in_parts()) return v.size() ? v.cwiseAbs().maxCoeff() : 0.0;
  const double here = n_owned > 0 ? v.head(n_owned).cwiseAbs().maxCoeff() : 0.0;
  // A NaN stays a NaN over the ranks (max would drop it): the ranks stop alike.
  const double bad = parallel::max_over_ranks(std::isfinite(here) ? 0.0 : 1.0);
  return bad > 0.0 ? std::numeric_limits<double>::quiet_NaN() : parallel::max_over_ranks(here);
}

double RankLayout::largest_over_ranks(double here) const {
  return in_parts() ? parallel::max_over_ranks(here) : here;
}

bool RankLayout::all_ranks(bool here) const {
  return in_parts() ? parallel::max_over_ranks(here ? 0.0 : 1.0) == 0.0 : here;
}

void RankLayout::complete(Vector& v) const {
  if (kind_ == Kind::Shared) parallel::sum_over_ranks(v.data(), v.size());
  if (kind_ != Kind::InParts) return;
  equation_halo_->add_to_owners(v.data(), 1);
  equation_halo_->copy_to_ghosts(v.data(), 1);
}

}  // namespace lunaster::engine
