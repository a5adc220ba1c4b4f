#include "engine/nonlinear/interface_policy.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "engine/nonlinear/stopwatch.hpp"

namespace lunaster::engine {

void InterfacePolicy::decide(const Constraints& cons, const std::vector<Triplet>& contact, bool eliminations,
                             const ContactHook& hook, const DofMap& dofs, SparseMatrix& k_ff, bool allowed) {
  // The interface solver factorises a symmetric Schur complement (LAPACK dsytrf): an
  // unsymmetric contact tangent (a frictional law in slip) is solved whole, by an LU backend.
  if (use_ != -1 && hook.matrix_kind() == MatrixKind::General) {
    if (use_ == 1) log_.info("  an unsymmetric contact tangent: the whole system is factorised from now on");
    drop();
    return;
  }
  if (use_ == 0) choose(cons, contact, hook, dofs, k_ff, allowed);
  if (use_ == 1 && eliminations) drop();
  if (use_ == 1)
    for (const Triplet& tr : contact) {
      const int i = cons.free_index[tr.row()], j = cons.free_index[tr.col()];
      if (i >= 0 && j >= 0 && (!on_interface_[i] || !on_interface_[j]) && std::abs(tr.value()) > floor_) {
        log_.info("  a contact term outside the surfaces' equations: each contact pass factorises the whole system");
        drop();
        break;
      }
    }
}

void InterfacePolicy::choose(const Constraints& cons, const std::vector<Triplet>& contact, const ContactHook& hook,
                             const DofMap& dofs, SparseMatrix& k_ff, bool allowed) {
  use_ = -1;
  // METHODE='AUTO' only: a deck that names its solver gets it. The dense Schur complement
  // costs m^2 doubles and m^3/3 operations per contact pass: a small interface only, against
  // a large interior (the 2D SSNP121 geometries).
  constexpr int kMaxInterface = 2500, kInteriorPerInterface = 20;
  if (!allowed) return;
  const std::vector<int> surface = hook.surface_equations();
  std::vector<int> eqs;
  for (int eq : surface)
    if (cons.free_index[eq] >= 0) eqs.push_back(cons.free_index[eq]);
  floor_ = 0.0;
  dense_share_ = 0.0;
  if (eqs.size() > static_cast<std::size_t>(kMaxInterface) ||
      static_cast<long>(eqs.size()) * kInteriorPerInterface > cons.n_free) {
    // Too many for the whole surfaces (a 3D surface of a few hundred nodes: 4,263 equations
    // on the CONTINUE 3D benchmark). The contact terms may reach fewer displacement
    // components: one on an interface square to an axis (SSNP121's), whose other components
    // then stay with the interior (1,715 equations on that benchmark): those that the
    // pairing's normals reach, active or not (so also before any point is active), as the
    // hook says. Terms below kNegligibleTerm of the largest count for nothing: a normal's
    // round-off that the gaps do not already leave out (make_linear_gap drops components up
    // to kNormalRoundOff). The dense factorisation must then cost at most kDenseShare of the
    // reference's (ensure_reference), and a term outside the interface, in this
    // solve or a later one (a pairing that reaches another component), makes decide()
    // give the interface solver up.
    constexpr double kDenseShare = 0.5;
    double largest = 0.0;
    for (const Triplet& tr : contact) largest = std::max(largest, std::abs(tr.value()));
    floor_ = kNegligibleTerm * largest;
    const std::array<bool, 3> reached = hook.displacement_components();
    if (!reached[0] && !reached[1] && !reached[2]) return;  // nothing paired
    eqs.clear();
    for (int eq : surface) {
      const int c = dofs.component_of(eq);
      if (cons.free_index[eq] >= 0 && (!is_displacement(c) || reached[c])) eqs.push_back(cons.free_index[eq]);
    }
    if (eqs.size() > static_cast<std::size_t>(kMaxInterface)) return;
    dense_share_ = kDenseShare;
  }
  std::sort(eqs.begin(), eqs.end());
  if (eqs.empty()) return;
  // The reference is K_ff itself, which must store a diagonal on every interface equation. The
  // multipliers' columns are empty and come last (their equations are numbered after every
  // displacement): each gets a zero diagonal appended, in the storage K_ff already holds
  // (split_matrix left it the constrained columns' room).
  SparseMatrix& k = k_ff;
  const int nf = static_cast<int>(k.cols());
  int first_empty = nf;
  while (first_empty > 0 && k.outerIndexPtr()[first_empty] == k.outerIndexPtr()[first_empty - 1]) --first_empty;
  for (int j : eqs) {
    if (j >= first_empty) continue;
    const int* rows = k.innerIndexPtr() + k.outerIndexPtr()[j];
    const int* end = k.innerIndexPtr() + k.outerIndexPtr()[j + 1];
    if (!std::binary_search(rows, end, j)) return;  // an interface equation without a diagonal entry
  }
  if (first_empty < nf) {
    const int nnz = static_cast<int>(k.nonZeros());
    k.resizeNonZeros(nnz + (nf - first_empty));
    for (int j = first_empty; j < nf; ++j) {
      k.innerIndexPtr()[nnz + (j - first_empty)] = j;
      k.valuePtr()[nnz + (j - first_empty)] = 0.0;
      k.outerIndexPtr()[j + 1] = nnz + (j - first_empty) + 1;
    }
  }
  on_interface_.assign(cons.n_free, 0);
  for (int j : eqs) on_interface_[j] = 1;
  solver_ = make_interface_solver(std::move(eqs));
  FactorSettings settings;  // the interface solver reads the singularity test alone
  settings.singularity = options_.factor.singularity;
  solver_->configure(settings);
  use_ = 1;
}

void InterfacePolicy::ensure_reference(SparseMatrix& k_ff, long generation, std::string& analysis_said) {
  if (use_ != 1 || reference_ == generation) return;
  double seconds = 0.0;
  {
    Stopwatch watch(seconds);
    const int m = static_cast<int>(solver_->interface().size());
    try {
      const bool taken = solver_->factorize_reference(k_ff, dense_share_);
      if (const std::string analysis = solver_->analysis_note(); !analysis.empty() && analysis != analysis_said)
        log_.debug("  " + analysis), analysis_said = analysis;
      if (taken) {
        reference_ = generation;
        state_ = LinearSolve::FactorState{};
        stats_.interface_equations = m;
        ++stats_.factorisations;
        log_.info("  elastic system factorised with the " + std::to_string(m) +
                  " equations of the contact surfaces last: each contact pass factorises their Schur "
                  "complement only");
      } else {
        use_ = -1;
        solver_.reset();
        stats_.interface_equations = 0;
        log_.info("  the " + std::to_string(m) +
                  " equations of the contact surfaces are too many for a dense Schur complement against this "
                  "elastic factorisation: each contact pass factorises the whole system");
      }
    } catch (const SolveError& err) {
      if (err.out_of_memory()) throw;
      use_ = -1;
      solver_.reset();
      stats_.interface_equations = 0;
      log_.info("  the elastic system alone is not positive definite (a body held by contact or linear relations "
                "only): each contact pass factorises the whole system");
    }
  }
  stats_.factorize_seconds += seconds;
  stats_.assemble_seconds -= seconds;  // the caller times the system's update as assembly
}

}  // namespace lunaster::engine
