#include "engine/contact/linear_gap.hpp"

#include "engine/core/error.hpp"

namespace lunaster::engine::contact {

namespace {

void add_node(LinearGap& gap, const std::vector<double>& coords, const DofMap& dofs, int dim, int node,
              double weight, const double* normal) {
  for (int k = 0; k < 3; ++k) gap.g0 += weight * coords[3 * static_cast<size_t>(node) + k] * normal[k];
  for (int k = 0; k < dim; ++k) {
    const int eq = node < dofs.n_nodes() ? dofs.dof(node, k) : -1;
    const double c = weight * normal[k];
    if (eq < 0 || c == 0.0) continue;
    LUNASTER_ASSERT(gap.n < LinearGap::kMaxTerms, "contact gap: too many terms");
    gap.eq[gap.n] = eq;
    gap.coef[gap.n] = c;
    ++gap.n;
  }
}

}  // namespace

LinearGap make_linear_gap(const std::vector<double>& coords, const DofMap& dofs, int dim, const int* slave,
                          const double* ws, int n_slave, const int* master, const double* wm, int n_master,
                          const double* normal) {
  LinearGap gap;
  for (int a = 0; a < n_slave; ++a) add_node(gap, coords, dofs, dim, slave[a], ws[a], normal);
  for (int b = 0; b < n_master; ++b) add_node(gap, coords, dofs, dim, master[b], -wm[b], normal);
  return gap;
}

void add_outer(const LinearGap& a, const LinearGap& b, double factor, std::vector<Triplet>& tangent) {
  for (int i = 0; i < a.n; ++i)
    for (int j = 0; j < b.n; ++j) tangent.emplace_back(a.eq[i], b.eq[j], factor * a.coef[i] * b.coef[j]);
}

void add_gradient(const LinearGap& g, double factor, Vector& residual) {
  for (int i = 0; i < g.n; ++i) residual[g.eq[i]] += factor * g.coef[i];
}

}  // namespace lunaster::engine::contact
