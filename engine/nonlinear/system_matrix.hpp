#pragma once
/// The matrix of the Newton system and its cache: K split by the Dirichlet conditions (K_ff,
/// the constrained columns), and each iteration's system, K_ff with the contact terms written
/// into K_ff's own storage and put back afterwards (restore), or, with the interface solver,
/// the contact terms alone beside a K_ff kept factorised. Its pattern counter and values key
/// tell the linear solve when a factorisation can be kept.
#include <cstdint>
#include <utility>
#include <vector>

#include "engine/assembly/dof_map.hpp"
#include "engine/nonlinear/constraints.hpp"
#include "engine/nonlinear/rank_layout.hpp"
#include "engine/nonlinear/reduction.hpp"
#include "engine/nonlinear/tangent_source.hpp"
#include "engine/solver/linear_solver.hpp"

namespace lunaster::engine {

class SystemMatrix {
 public:
  /// Drops the previous run's matrices and cache.
  void clear();
  /// K from `tangent` (borrowed for the run) at u, split by the Dirichlet set `constrained`
  /// (the same at every instant); `distributed`: this rank holds only its own nodes' columns.
  /// With `f_int`, the internal forces at u from the same integration. Returns false when a
  /// behaviour's integration failed (TangentSource::assemble).
  bool assemble(TangentSource& tangent, const Vector& u, const std::vector<int>& constrained, bool distributed,
                Vector* f_int = nullptr);
  /// A tangent that is not constant: K assembled again at u (the same split), so that the
  /// next update builds its system from it (new values key, new contact positions). Nothing
  /// for a constant one, nor when K is already the tangent at u (refresh_with_forces at the
  /// same u). Returns false when a behaviour's integration failed at u.
  bool refresh(const Vector& u);
  /// A tangent that is not constant: the refresh at u and the internal forces at u (this rank's
  /// share) into `f_int`, from one integration of the behaviours (each point returns its stress
  /// and its tangent together); the next refresh at the same u keeps this K. False when a
  /// behaviour's integration failed at u.
  bool refresh_with_forces(const Vector& u, Vector& f_int);
  /// Whether the tangent is constant (K and its factorisations kept for the run).
  bool constant() const { return tangent_ == nullptr || tangent_->constant(); }
  /// Whether K is positive definite (false: a softening behaviour's tangent, TangentSource).
  bool positive_definite() const { return tangent_ == nullptr || tangent_->positive_definite(); }
  /// The kind of the system K + terms whose own kind is `terms`: symmetric indefinite rather
  /// than SPD when K is not positive definite (a softening tangent: never Cholesky).
  MatrixKind kind(MatrixKind terms) const {
    return terms == MatrixKind::SymmetricPositiveDefinite && !positive_definite() ? MatrixKind::SymmetricIndefinite
                                                                                  : terms;
  }

  /// K split: K_ff (numbered as Constraints::free_index), the constrained columns. Between
  /// updates (or after restore) ff is K_ff itself.
  SplitMatrix& elastic() { return elastic_; }
  const SplitMatrix& elastic() const { return elastic_; }

  /// K u over the whole numbering, made whole over the ranks as `layout` lays the run out;
  /// `holder`: the backend K_ff was handed to (its product gives K_ff's part), or null.
  /// Collective unless the run is whole.
  Vector times(const Vector& u, const RankLayout& layout, const LinearSolver* holder) const;
  /// The columns of K at the eliminated equations, for Constraints::eliminate (valid while cons
  /// is): from K_ff when this rank holds it whole, else the whole columns of the eliminated
  /// equations' nodes, assembled here (shared model) or gathered from their owners (in parts,
  /// `part`), kept while the set of nodes holds. Collective unless the run is whole.
  Constraints::ColumnSource columns(const Constraints& cons, const std::vector<Elimination>& relations,
                                    const RankLayout& layout, const FeModel& model, const DofMap& dofs,
                                    const MeshPart* part);

  /// Starts an iteration's system: K_ff restored, the Dirichlet set taken (a new one: a new
  /// generation of K_ff), per free equation whether this rank holds its column (`owned_nodes`
  /// with a shared model, else null).
  void begin(const Constraints& cons, const DofMap& dofs, const std::vector<char>* owned_nodes);
  /// The system is K_ff alone (no contact hook).
  void fill_alone();
  /// The interface solver's system: the contact terms within `on_interface` (per free
  /// equation) and the condensed equations' unit diagonals, beside K_ff (increment()).
  void fill_interface(const Constraints& cons, const std::vector<Triplet>& contact, const std::vector<int>& condensed,
                      long contact_version, const std::vector<int>& interface, const std::vector<char>& on_interface);
  /// The whole system in K_ff's storage: the contact terms added, the condensed equations' and
  /// the eliminated equations' rows and columns made unit diagonals.
  void fill_whole(const Constraints& cons, const std::vector<Triplet>& contact, const std::vector<int>& condensed,
                  const std::vector<int>& eliminated, long contact_version);
  /// A shared model: the pattern counter and values key made the whole system's, alike on
  /// every rank (`pattern_before`: the counter before this iteration's fill). Collective.
  void agree_over_ranks(long pattern_before);
  /// K_ff back in elastic().ff (the values the fill overwrote); nothing to do when it holds K_ff.
  void restore();

  /// The system of the last fill: K_ff with its terms, or the terms alone (increment()).
  const SparseMatrix& matrix() const { return *cache_.matrix; }
  bool has_matrix() const { return cache_.matrix != nullptr; }
  /// The system is K_ff + matrix() (the interface solver's terms alone).
  bool increment() const { return cache_.increment; }
  long pattern() const { return cache_.pattern; }
  std::uint64_t values_key() const { return cache_.values_key; }
  /// Incremented when the Dirichlet set or K_ff's values change.
  long generation() const { return cache_.elastic_generation; }

 private:
  /// The restricted system, kept between iterations and instants.
  struct Cache {
    bool valid = false;
    std::vector<int> constrained;  ///< Dirichlet equations the pattern was built for
    long elastic_generation = 0;   ///< incremented when the Dirichlet set (or K_ff) changes
    long contact_version = -1;     ///< contact pattern version the pattern was built for
    long pattern = 0;              ///< incremented at each new pattern
    bool new_constraints = false;  ///< the Dirichlet set of this iteration is new
    /// The interface solver's contact terms C (the system is K_ff + C, increment is true).
    SparseMatrix a;
    /// The system: elastic_.ff (without a contact hook K_ff itself; with one, K_ff with this
    /// iteration's contact terms written in place, see saved), or &a with the interface solver.
    const SparseMatrix* matrix = nullptr;
    bool increment = false;
    /// The values this iteration's condensed and eliminated equations overwrote (position,
    /// value; put back in reverse order), then K_ff's values at the contact positions (each
    /// position once, kept with the pattern: K_ff does not change within a run).
    std::vector<std::pair<int, double>> saved;
    std::vector<int> contact_unique;
    /// Positions of elastic_.ff that are not K_ff's own, there for the contact terms (ascending).
    std::vector<int> contact_only;
    std::vector<double> contact_elastic;
    bool contact_written = false;  ///< the contact terms are in elastic_.ff now
    std::vector<int> contact_pos;  ///< position in the matrix of each contact triplet, -1 if constrained
    std::vector<int> diagonal;     ///< position of each diagonal entry in the matrix, -1 in another rank's column
    std::vector<char> owned;       ///< shared model: per free equation, whether this rank holds its column
    std::uint64_t values_key = 0;  ///< key of the system's current values
  };
  /// K_ff's pattern grown to hold every contact position of this pairing (and the diagonal).
  void rebuild_pattern(const Constraints& cons, const std::vector<Triplet>& contact, long contact_version);
  /// The positions of this pairing's contact triplets and of the diagonal in the new pattern,
  /// and K_ff's values at them.
  void locate_contact(const Constraints& cons, const std::vector<Triplet>& contact, long contact_version);
  /// This iteration's values written into K_ff's storage, the overwritten ones saved.
  void write_values(const Constraints& cons, const std::vector<Triplet>& contact, const std::vector<int>& condensed,
                    const std::vector<int>& eliminated);
  /// A shared model: this rank's columns only (the others are empty here).
  bool mine(int j) const { return cache_.owned.empty() || cache_.owned[j]; }
  /// K (not constant) assembled again at u, with the internal forces into f_int when given.
  bool reassemble(const Vector& u, Vector* f_int);
  TangentSource* tangent_ = nullptr;
  bool distributed_ = false;
  /// The displacement K is the tangent at (refresh_with_forces), empty when unknown: kept
  /// until the next refresh, to skip a second integration at the same u.
  Vector tangent_at_;
  SplitMatrix elastic_;
  Cache cache_;
  /// With eliminations on a shared model or in parts: the whole columns of K at the eliminated
  /// equations' nodes (ghost_nodes_), kept while that set of nodes holds.
  SparseMatrix ghost_;
  std::vector<int> ghost_nodes_;
};

}  // namespace lunaster::engine
