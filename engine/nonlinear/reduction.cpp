#include "engine/nonlinear/reduction.hpp"

namespace lunaster::engine {

SparseMatrix restrict_matrix(const SparseMatrix& a, const std::vector<int>& index, int n_kept) {
  SparseMatrix r(n_kept, n_kept);
  std::vector<int> outer(static_cast<size_t>(n_kept) + 1, 0);
  for (int j = 0; j < a.outerSize(); ++j) {
    const int rj = index[j];
    if (rj < 0) continue;
    for (SparseMatrix::InnerIterator it(a, j); it; ++it)
      if (index[it.row()] >= 0) ++outer[rj + 1];
  }
  for (int j = 0; j < n_kept; ++j) outer[j + 1] += outer[j];
  r.resizeNonZeros(outer[n_kept]);
  int* inner = r.innerIndexPtr();
  double* values = r.valuePtr();
  for (int j = 0; j < a.outerSize(); ++j) {
    const int rj = index[j];
    if (rj < 0) continue;
    int k = outer[rj];
    for (SparseMatrix::InnerIterator it(a, j); it; ++it) {
      const int ri = index[it.row()];
      if (ri < 0) continue;
      inner[k] = ri;
      values[k++] = it.value();
    }
  }
  std::copy(outer.begin(), outer.end(), r.outerIndexPtr());
  return r;
}

}  // namespace lunaster::engine
