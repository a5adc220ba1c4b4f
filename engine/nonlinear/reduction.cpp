#include "engine/nonlinear/reduction.hpp"

#include "engine/core/error.hpp"
#include "engine/solver/linear_solver.hpp"  // symmetric_times

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

void split_matrix(SparseMatrix& k, std::vector<int> constrained, SplitMatrix& out) {
  LUNASTER_ASSERT(k.rows() == k.cols() && k.isCompressed(), "split_matrix: K must be square and compressed");
  const int n = static_cast<int>(k.cols());
  out.ff = SparseMatrix();
  out.c = SparseMatrix();
  out.equation.clear();
  std::sort(constrained.begin(), constrained.end());
  constrained.erase(std::unique(constrained.begin(), constrained.end()), constrained.end());
  out.constrained = std::move(constrained);
  out.free_index.assign(n, 0);
  for (int eq : out.constrained) out.free_index[eq] = -1;
  for (int eq = 0; eq < n; ++eq)
    if (out.free_index[eq] == 0) {
      out.free_index[eq] = static_cast<int>(out.equation.size());
      out.equation.push_back(eq);
    }
  const int* outer_k = k.outerIndexPtr();
  int* inner = k.innerIndexPtr();
  double* values = k.valuePtr();
  // K(:, C), the constrained columns one after the other.
  const int nc = static_cast<int>(out.constrained.size());
  out.c = SparseMatrix(n, nc);
  int* outer_c = out.c.outerIndexPtr();
  outer_c[0] = 0;
  for (int c = 0; c < nc; ++c) {
    const int eq = out.constrained[c];
    outer_c[c + 1] = outer_c[c] + (outer_k[eq + 1] - outer_k[eq]);
  }
  out.c.resizeNonZeros(outer_c[nc]);
  for (int c = 0; c < nc; ++c) {
    const int p0 = outer_k[out.constrained[c]], p1 = outer_k[out.constrained[c] + 1];
    std::copy(inner + p0, inner + p1, out.c.innerIndexPtr() + outer_c[c]);
    std::copy(values + p0, values + p1, out.c.valuePtr() + outer_c[c]);
  }
  // K(F, F) in K's own storage: the free rows of the free columns moved to the front, in
  // order (an entry never moves to a later position), and that storage handed to an
  // nf x nf matrix (conservativeResize and makeCompressed would copy it).
  const int nf = static_cast<int>(out.equation.size());
  std::vector<int> outer_ff(static_cast<size_t>(nf) + 1, 0);
  int w = 0;
  for (int j = 0; j < nf; ++j) {
    const int col = out.equation[j];
    for (int p = outer_k[col]; p < outer_k[col + 1]; ++p) {
      const int row = out.free_index[inner[p]];
      if (row < 0) continue;
      inner[w] = row;
      values[w++] = values[p];
    }
    outer_ff[j + 1] = w;
  }
  out.ff = SparseMatrix(nf, nf);
  std::copy(outer_ff.begin(), outer_ff.end(), out.ff.outerIndexPtr());
  out.ff.data().swap(k.data());
  out.ff.resizeNonZeros(w);  // shrinks the size, keeps the allocation
  k = SparseMatrix();
}

Vector SplitMatrix::ff_times(const Vector& x) const {
  return symmetric ? symmetric_times(ff, x) : Vector(ff * x);
}

Vector SplitMatrix::times(const Vector& u) const {
  // K u = K(:, F) u_F + K(:, C) u_C; rows C of K(:, F) u_F are K(C, F) u_F = K(F, C)^T u_F.
  const int nf = static_cast<int>(equation.size());
  Vector u_free(nf);
  for (int j = 0; j < nf; ++j) u_free[j] = u[equation[j]];
  const Vector k_u_free = ff_times(u_free);
  Vector ku = Vector::Zero(static_cast<Eigen::Index>(free_index.size()));
  for (int j = 0; j < nf; ++j) ku[equation[j]] = k_u_free[j];
  const int* outer = c.outerIndexPtr();
  const int* inner = c.innerIndexPtr();
  const double* values = c.valuePtr();
  for (int k = 0; k < static_cast<int>(constrained.size()); ++k) {
    const int eq = constrained[k];
    const double u_c = u[eq];
    double row = 0.0;
    for (int p = outer[k]; p < outer[k + 1]; ++p) {
      ku[inner[p]] += values[p] * u_c;
      if (free_index[inner[p]] >= 0) row += values[p] * u[inner[p]];
    }
    ku[eq] += row;
  }
  return ku;
}

void SplitMatrix::add_constrained_rows(const Vector& x, Vector& y) const {
  // Row c of K(C, F) is column c of K(F, C) (K is symmetric): its free entries.
  const int* outer = c.outerIndexPtr();
  const int* inner = c.innerIndexPtr();
  const double* values = c.valuePtr();
  for (int k = 0; k < static_cast<int>(constrained.size()); ++k) {
    double row = 0.0;
    for (int p = outer[k]; p < outer[k + 1]; ++p)
      if (free_index[inner[p]] >= 0) row += values[p] * x[free_index[inner[p]]];
    y[constrained[k]] += row;
  }
}

}  // namespace lunaster::engine
