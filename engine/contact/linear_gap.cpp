#include "engine/contact/linear_gap.hpp"

#include <algorithm>
#include <cmath>

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
  // A normal's round-off taken as 0 adds no term, so the contact tangent of a face square to
  // an axis reaches the normal component alone (8/9 fewer terms in 3D).
  double n[3];
  for (int k = 0; k < 3; ++k) n[k] = std::abs(normal[k]) <= kNormalRoundOff ? 0.0 : normal[k];
  LinearGap gap;
  for (int a = 0; a < n_slave; ++a) add_node(gap, coords, dofs, dim, slave[a], ws[a], n);
  for (int b = 0; b < n_master; ++b) add_node(gap, coords, dofs, dim, master[b], -wm[b], n);
  return gap;
}

void tangent_frame(const double* n, int dim, double t[2][3]) {
  if (dim == 2) {
    t[0][0] = -n[1], t[0][1] = n[0], t[0][2] = 0.0;
    return;
  }
  // The axis least aligned with n; a tie within 1e-6 keeps the lower axis, so that round-off in
  // a normal along an axis (a flat face tilted by 1e-13) does not swap t1 and t2 between two
  // pairings, and with them the tangential multipliers' meaning.
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(n[k]) < std::abs(n[axis]) - 1e-6) axis = k;
  double e[3] = {0.0, 0.0, 0.0};
  e[axis] = 1.0;
  double norm2 = 0.0;
  for (int k = 0; k < 3; ++k) t[0][k] = e[k] - n[axis] * n[k], norm2 += t[0][k] * t[0][k];
  const double inv = 1.0 / std::sqrt(norm2);
  for (int k = 0; k < 3; ++k) t[0][k] *= inv;
  t[1][0] = n[1] * t[0][2] - n[2] * t[0][1];
  t[1][1] = n[2] * t[0][0] - n[0] * t[0][2];
  t[1][2] = n[0] * t[0][1] - n[1] * t[0][0];
}

void add_outer(const LinearGap& a, const LinearGap& b, double factor, std::vector<Triplet>& tangent) {
  for (int i = 0; i < a.n; ++i)
    for (int j = 0; j < b.n; ++j) tangent.emplace_back(a.eq[i], b.eq[j], factor * a.coef[i] * b.coef[j]);
}

void add_gradient(const LinearGap& g, double factor, Vector& residual) {
  for (int i = 0; i < g.n; ++i) residual[g.eq[i]] += factor * g.coef[i];
}

int LocalTangent::index(int eq) {
  if (eq >= static_cast<int>(pos_.size())) pos_.resize(std::max<size_t>(eq + 1, 2 * pos_.size()), -1);
  if (pos_[eq] >= 0) return pos_[eq];
  const int n = static_cast<int>(eqs_.size());
  if (n == stride_) {  // grow, keeping the entries already summed
    const int stride = std::max(64, 2 * stride_);
    std::vector<double> dense(static_cast<size_t>(stride) * stride, 0.0);
    std::vector<char> touched(static_cast<size_t>(stride) * stride, 0);
    for (int i = 0; i < n; ++i) {
      const size_t from = static_cast<size_t>(i) * stride_, to = static_cast<size_t>(i) * stride;
      std::copy(dense_.begin() + from, dense_.begin() + from + n, dense.begin() + to);
      std::copy(touched_.begin() + from, touched_.begin() + from + n, touched.begin() + to);
    }
    dense_.swap(dense);
    touched_.swap(touched);
    stride_ = stride;
  }
  eqs_.push_back(eq);
  pos_[eq] = n;
  return n;
}

void LocalTangent::add_outer(const LinearGap& a, const LinearGap& b, double factor) {
  // The points of a cell paired with one master cell share their equations: the pattern of
  // a a^T (an inactive point's zeros) is marked once for them.
  if (factor == 0.0 && &a == &b) {
    if (marked_.size() == static_cast<size_t>(a.n) && std::equal(a.eq.begin(), a.eq.begin() + a.n, marked_.begin())) return;
    marked_.assign(a.eq.begin(), a.eq.begin() + a.n);
  }
  int ia[LinearGap::kMaxTerms], ib[LinearGap::kMaxTerms];
  for (int i = 0; i < a.n; ++i) ia[i] = index(a.eq[i]);
  for (int j = 0; j < b.n; ++j) ib[j] = index(b.eq[j]);
  for (int i = 0; i < a.n; ++i) {
    double* row = dense_.data() + static_cast<size_t>(ia[i]) * stride_;
    char* mark = touched_.data() + static_cast<size_t>(ia[i]) * stride_;
    const double fa = factor * a.coef[i];
    if (fa == 0.0) {  // the pattern only (an inactive point's zeros)
      for (int j = 0; j < b.n; ++j) mark[ib[j]] = 1;
      continue;
    }
    for (int j = 0; j < b.n; ++j) row[ib[j]] += fa * b.coef[j], mark[ib[j]] = 1;
  }
}

void LocalTangent::flush(std::vector<Triplet>& tangent) {
  const int n = static_cast<int>(eqs_.size());
  for (int i = 0; i < n; ++i) {
    double* row = dense_.data() + static_cast<size_t>(i) * stride_;
    char* mark = touched_.data() + static_cast<size_t>(i) * stride_;
    for (int j = 0; j < n; ++j)
      if (mark[j]) tangent.emplace_back(eqs_[i], eqs_[j], row[j]), row[j] = 0.0, mark[j] = 0;
  }
  for (int eq : eqs_) pos_[eq] = -1;
  eqs_.clear();
  marked_.clear();
}

}  // namespace lunaster::engine::contact
