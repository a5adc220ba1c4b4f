#include "engine/nonlinear/constraints.hpp"

#include <algorithm>
#include <map>
#include <string>

#include "engine/assembly/halo.hpp"
#include "engine/core/error.hpp"
#include "engine/core/memory.hpp"

namespace lunaster::engine {

namespace {

/// Calls held(eq, condition) for each Dirichlet condition of `loads`, in order; throws DeckError
/// for a condition on an unknown the model does not carry.
template <class Held>
void for_each_condition(const DofMap& dofs, const MechanicalLoads& loads, const Mesh& mesh, Held&& held) {
  for (const auto& d : loads.dirichlet) {
    const int eq = dofs.dof(d.node, d.component);
    if (eq < 0)
      throw DeckError("imposed " + std::string(component_name(d.component)) + " on node " + mesh.node_names[d.node] +
                      ", which carries no such unknown in the model");
    held(eq, d);
  }
}

/// r + K b over the whole numbering, and r' = (r + K b)_R + A^T (r + K b)_E into r_free.
void eliminated_residual(const Constraints& cons, const std::vector<Elimination>& relations,
                         const std::vector<Constraints::Column>& column, const std::vector<int>& index_of,
                         const Vector& residual, Vector& r_free) {
  const int n = static_cast<int>(cons.free_index.size());
  Vector rb = residual;
  for (size_t i = 0; i < relations.size(); ++i)
    if (relations[i].value != 0.0)
      for (const auto& [row, v] : column[i]) rb[row] += v * relations[i].value;
  for (int eq = 0; eq < n; ++eq) {
    const int k = cons.free_index[eq];
    if (k >= 0) r_free[k] = index_of[eq] >= 0 ? 0.0 : rb[eq];
  }
  for (size_t i = 0; i < relations.size(); ++i)
    for (const auto& [k, a] : relations[i].terms)
      if (cons.free_index[k] >= 0) r_free[cons.free_index[k]] += a * rb[relations[i].eq];
}

/// The fill K' - K_RR as sparse products, which sum the contributions of neighbouring relations
/// (one triplet per product term would be tens of millions in 3D): with KE the columns of K at E
/// (rows over the whole numbering) and A the relations' coefficients, P = KE A holds K_RE A in
/// its R rows and K_EE A in its E rows; then K' - K_RR = P_R + P_R^T + A^T P_E.
void append_fill(const Constraints& cons, const std::vector<Elimination>& relations,
                 const std::vector<Constraints::Column>& column, const std::vector<int>& index_of,
                 std::vector<Triplet>& triplets) {
  const int n = static_cast<int>(cons.free_index.size());
  const int m = static_cast<int>(relations.size());
  std::vector<Triplet> t;
  for (int i = 0; i < m; ++i)
    for (const auto& [row, v] : column[i])
      if (cons.free_index[row] >= 0) t.emplace_back(row, i, v);
  SparseMatrix ke(n, m);
  ke.setFromTriplets(t.begin(), t.end());
  t.clear();
  for (int i = 0; i < m; ++i)
    for (const auto& [k, a] : relations[i].terms)
      if (cons.free_index[k] >= 0) t.emplace_back(i, k, a);
  SparseMatrix a(m, n);
  a.setFromTriplets(t.begin(), t.end());
  std::vector<Triplet>().swap(t);
  const SparseMatrix p = ke * a;  // n x n, column-major
  // P_E as an m x n matrix (its rows at the eliminated equations), then A^T P_E.
  std::vector<Triplet> pe;
  for (int k = 0; k < p.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(p, k); it; ++it)
      if (index_of[it.row()] >= 0) pe.emplace_back(index_of[it.row()], k, it.value());
  SparseMatrix pe_m(m, n);
  pe_m.setFromTriplets(pe.begin(), pe.end());
  const SparseMatrix s = SparseMatrix(a.transpose()) * pe_m;
  // The fill goes into triplets in one allocation (millions of terms in 3D: growing the
  // vector by doubling copied it onto fresh pages several times over).
  const std::size_t fill =
      2 * (static_cast<std::size_t>(p.nonZeros()) - pe.size()) + static_cast<std::size_t>(s.nonZeros());
  reserve_on_huge_pages(triplets, triplets.size() + fill);
  for (int k = 0; k < p.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(p, k); it; ++it) {
      const int row = static_cast<int>(it.row());
      if (index_of[row] >= 0) continue;
      triplets.emplace_back(row, k, it.value());
      triplets.emplace_back(k, row, it.value());
    }
  for (int k = 0; k < s.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(s, k); it; ++it)
      triplets.emplace_back(static_cast<int>(it.row()), k, it.value());
}

}  // namespace

std::vector<int> Constraints::held_equations(const DofMap& dofs, const MechanicalLoads& loads, const Mesh& mesh) {
  std::vector<int> eqs;
  for_each_condition(dofs, loads, mesh, [&eqs](int eq, const DirichletValue&) { eqs.push_back(eq); });
  std::sort(eqs.begin(), eqs.end());
  eqs.erase(std::unique(eqs.begin(), eqs.end()), eqs.end());
  return eqs;
}

Constraints Constraints::at_instant(const DofMap& dofs, const MechanicalLoads& loads, double t, const Mesh& mesh) {
  std::map<int, double> imposed;
  for_each_condition(dofs, loads, mesh, [&](int eq, const DirichletValue& d) {
    imposed[eq] = d.value * loads.multipliers.at(d.load)(t);
  });
  Constraints c;
  c.free_index.assign(dofs.n_dofs(), 0);
  for (const auto& [eq, value] : imposed) {
    c.free_index[eq] = -1;
    c.constrained.push_back(eq);
    c.values.push_back(value);
  }
  for (int eq = 0; eq < dofs.n_dofs(); ++eq)
    if (c.free_index[eq] == 0) c.free_index[eq] = c.n_free++;
  return c;
}

Constraints Constraints::holding(int n, const std::vector<int>& constrained) {
  Constraints c;
  c.free_index.assign(n, 0);
  for (int eq : constrained) c.free_index[eq] = -1, c.constrained.push_back(eq);
  c.values.assign(constrained.size(), 0.0);
  for (int eq = 0; eq < n; ++eq)
    if (c.free_index[eq] == 0) c.free_index[eq] = c.n_free++;
  return c;
}

void Constraints::take_from_owners(const Halo& equation_halo) {
  const int n = static_cast<int>(free_index.size());
  // Per unknown: constrained or not, and its value, from its owner.
  std::vector<double> said(2 * static_cast<size_t>(n), 0.0);
  for (size_t i = 0; i < constrained.size(); ++i) {
    said[2 * constrained[i]] = 1.0;
    said[2 * constrained[i] + 1] = values[i];
  }
  equation_halo.copy_to_ghosts(said, 2);
  constrained.clear(), values.clear();
  n_free = 0;
  for (int eq = 0; eq < n; ++eq)
    if (said[2 * eq] != 0.0) {
      free_index[eq] = -1;
      constrained.push_back(eq);
      values.push_back(said[2 * eq + 1]);
    } else {
      free_index[eq] = n_free++;
    }
}

void Constraints::impose(Vector& u) const {
  for (size_t i = 0; i < constrained.size(); ++i) u[constrained[i]] = values[i];
}

std::vector<int> Constraints::eliminate(const std::vector<Elimination>& relations, const ColumnSource& columns,
                                        const Vector& residual, std::vector<Triplet>& triplets,
                                        Vector& r_free) const {
  const int n = static_cast<int>(free_index.size());
  std::vector<int> index_of(n, -1);
  std::vector<int> eqs;
  eqs.reserve(relations.size());
  for (size_t i = 0; i < relations.size(); ++i) {
    const int eq = relations[i].eq;
    LUNASTER_ASSERT(eq >= 0 && eq < n && free_index[eq] >= 0 && index_of[eq] < 0,
                    "an eliminated unknown must be free and eliminated once");
    index_of[eq] = static_cast<int>(i);
    eqs.push_back(eq);
  }
  // Columns of K at the eliminated equations: the stiffness's, then the contact triplets'.
  std::vector<Column> column(relations.size());
  for (size_t i = 0; i < relations.size(); ++i) columns(relations[i].eq, column[i]);
  for (const auto& tr : triplets)
    if (index_of[tr.col()] >= 0) column[index_of[tr.col()]].emplace_back(tr.row(), tr.value());
  eliminated_residual(*this, relations, column, index_of, residual, r_free);
  append_fill(*this, relations, column, index_of, triplets);
  return eqs;
}

void Constraints::recover(const std::vector<Elimination>& relations, const Vector& du_free, Vector& u) const {
  for (const Elimination& e : relations) {
    // du_e = b_e + sum a_k du_k (its own entry of du is the zero of its unit row).
    double d = e.value;
    for (const auto& [k, a] : e.terms)
      if (free_index[k] >= 0) d += a * du_free[free_index[k]];
    u[e.eq] += d;
  }
}

}  // namespace lunaster::engine
