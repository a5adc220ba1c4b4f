// Mortar segmentation of short curved SEG3 cells far from the origin (a fine mesh of a circle
// of radius 0.75 m, the ring/sleeve case): the projections' Newton iterations must stop at
// the round-off level of their step, which exceeds 1e-14 once the cells are short; otherwise
// they report failure after converging and whole slave cells lose their master.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "engine/contact/mortar_integration.hpp"
#include "engine/contact/surface_element.hpp"

namespace {

using lunaster::engine::CellType;
namespace mortar = lunaster::engine::contact::mortar;

/// SEG3 on the circle of radius r between angles t0 and t1 (mid node at the mid angle), listed
/// from t0 to t1: the normal (t_y, -t_x) points away from the centre when t1 > t0.
std::vector<double> arc(double r, double t0, double t1) {
  const double tm = 0.5 * (t0 + t1);
  return {r * std::cos(t0), r * std::sin(t0), 0.0, r * std::cos(t1), r * std::sin(t1), 0.0,
          r * std::cos(tm), r * std::sin(tm), 0.0};
}

/// Length of the SEG3 by 6-point Gauss (exact to degree 11: plenty for a parabola's speed).
double length(const std::vector<double>& x) {
  const double g[3] = {0.2386191860831909, 0.6612093864662645, 0.9324695142031521};
  const double w[3] = {0.4679139345726910, 0.3607615730481386, 0.1713244923791704};
  double s = 0.0;
  for (int i = 0; i < 3; ++i)
    for (double xi : {-g[i], g[i]}) {
      // SEG3 (MED): N0 = xi (xi - 1) / 2, N1 = xi (xi + 1) / 2, N2 = 1 - xi^2
      const double d0 = xi - 0.5, d1 = xi + 0.5, d2 = -2.0 * xi;
      const double tx = d0 * x[0] + d1 * x[3] + d2 * x[6], ty = d0 * x[1] + d1 * x[4] + d2 * x[7];
      s += w[i] * std::hypot(tx, ty);
    }
  return s;
}

/// Slave arc (ring side, r = 0.75, normal outward) cells cover [0, pi/2] in n_s cells, master
/// (sleeve side, listed backwards: normal towards the centre) in n_m cells. Returns the largest
/// relative shortfall of a slave cell's covered length against its own length.
double worst_cover(int n_s, int n_m) {
  const double b = 0.75, quarter = 0.5 * M_PI;
  std::vector<std::vector<double>> masters;
  for (int i = 0; i < n_m; ++i) masters.push_back(arc(b, quarter * (i + 1) / n_m, quarter * i / n_m));
  double worst = 0.0;
  for (int j = 0; j < n_s; ++j) {
    const std::vector<double> s = arc(b, quarter * j / n_s, quarter * (j + 1) / n_s);
    double covered = 0.0;
    const int centre = j * n_m / n_s;  // the masters around the slave cell (the rest are far)
    for (int i = std::max(0, centre - 2); i <= std::min(n_m - 1, centre + 2); ++i) {
      std::vector<mortar::OverlapPoint> pts;
      covered += mortar::overlap_points(CellType::Seg3, s.data(), CellType::Seg3, masters[i].data(), 4, pts);
    }
    worst = std::max(worst, std::abs(covered - length(s)) / length(s));
  }
  return worst;
}

TEST(MortarShortArcs, FineCurvedSeg3MeshesOfACircleCoverEverySlaveCell) {
  // Matching and non-matching quarter circles, from 48 cells (h = 25 mm) to 768 (h = 1.5 mm):
  // before the round-off-aware stop, 128 matching cells already lost some slave cells whole.
  for (const auto& [n_s, n_m] : std::vector<std::pair<int, int>>{{48, 48}, {128, 128}, {384, 384}, {768, 768}})
    EXPECT_LT(worst_cover(n_s, n_m), 1e-12) << n_s << " / " << n_m;
  // Non-matching: the master's curved cells do not lie on the slave's, so each overlap is the
  // interval between the projected master ends; the pieces still add up to the slave cell.
  for (const auto& [n_s, n_m] : std::vector<std::pair<int, int>>{{120, 100}, {240, 200}, {480, 400}})
    EXPECT_LT(worst_cover(n_s, n_m), 1e-12) << n_s << " / " << n_m;
}

}  // namespace
