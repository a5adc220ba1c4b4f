#include "engine/nonlinear/relations_hook.hpp"

#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <unordered_map>
#include <utility>

#include "engine/assembly/linear_relations.hpp"
#include "engine/core/error.hpp"

namespace lunaster::engine {

namespace {

/// A relation whose every unknown is imposed (Dirichlet conditions), possibly once other
/// relations are substituted: sum c u_eq = sum b v_l must hold for the imposed values.
struct ImposedRelation {
  int relation = -1;                          ///< the relation (0-based) it was built from
  std::vector<std::pair<int, double>> terms;  ///< (equation, c)
  std::vector<std::pair<int, double>> rhs;    ///< (relation l, b): the right-hand sides v_l
};

/// The relations solved for one unknown each instead of a multiplier (code_aster's
/// ELIM_LAGR='OUI'): Gaussian elimination over the relations in their order, each pivot the
/// free unknown of largest coefficient (the first of them on a tie) once the unknowns chosen
/// before are substituted, and every expression closed (no pivot in another's terms):
/// u_p = sum_k a_k u_k + sum_l b_l v_l, v_l the right-hand side of relation l. The system
/// then keeps K's kind (SPD stays SPD, CHOLMOD). The relations' forces C^T lambda come from
/// the pivots' rows of the residual: C_P^T lambda = -r_P.
class RelationEliminator {
 public:
  /// `free`: whether an equation is free (not Dirichlet-constrained).
  void build(const std::vector<LinearRelation>& relations, const DofMap& dofs, const std::function<bool(int)>& free) {
    const int m = static_cast<int>(relations.size());
    pivot_.assign(m, -1);
    imposed_only_.clear();
    std::map<int, int> position;                        // pivot equation -> index in exprs_
    std::unordered_map<int, std::vector<int>> users;    // equation -> expressions that name it
    for (int i = 0; i < m; ++i) {
      std::vector<std::pair<int, double>> row;  // in term order
      auto add = [&row](int eq, double c) {
        for (auto& [e, v] : row)
          if (e == eq) return void(v += c);
        row.emplace_back(eq, c);
      };
      for (const auto& t : relations[i].terms) add(dofs.dof(t.node, t.component), t.coef);
      std::map<int, double> rhs{{i, 1.0}};
      // The pivots chosen before: c u_e = c (sum a u + sum b v) moves its v part to the right.
      std::vector<std::pair<int, double>> substituted;
      for (const auto& [eq, c] : row) {
        auto it = position.find(eq);
        if (it == position.end()) {
          substituted.emplace_back(eq, c);
          continue;
        }
        const Expr& e = exprs_[it->second];
        for (const auto& [k, a] : e.terms) substituted.emplace_back(k, c * a);
        for (const auto& [l, b] : e.rhs) rhs[l] -= c * b;
      }
      row.clear();
      for (const auto& [eq, c] : substituted) add(eq, c);
      double scale = 0.0;
      for (const auto& [eq, c] : row) scale = std::max(scale, std::abs(c));
      int p = -1;
      double best = 0.0;
      for (const auto& [eq, c] : row)
        if (free(eq) && std::abs(c) > 1e-12 * scale && std::abs(c) > best) p = eq, best = std::abs(c);
      if (p < 0) {
        bool constrained_terms = false;
        for (const auto& [eq, c] : row) constrained_terms |= std::abs(c) > 1e-12 * scale;
        if (constrained_terms) {  // every term imposed: it holds if the Dirichlet values agree with it
          ImposedRelation check;
          check.relation = i;
          for (const auto& [eq, c] : row)
            if (std::abs(c) > 1e-12 * scale) check.terms.emplace_back(eq, c);
          for (const auto& [l, b] : rhs)
            if (b != 0.0) check.rhs.emplace_back(l, b);
          imposed_only_.push_back(std::move(check));
          continue;
        }
        throw DeckError(relation_name(relations[i], i) +
                        " is a combination of the relations before it (with its right-hand side, the same "
                        "relation or a contradiction): remove it");
      }
      double cp = 0.0;
      for (const auto& [eq, c] : row)
        if (eq == p) cp = c;
      Expr e;
      e.eq = p;
      for (const auto& [eq, c] : row)
        if (eq != p && std::abs(c) > 1e-12 * scale) e.terms.emplace_back(eq, -c / cp);
      for (const auto& [l, b] : rhs)
        if (b != 0.0) e.rhs.emplace_back(l, b / cp);
      // Close: the expressions before it that name p (users[p]) name its expression instead.
      const int index = static_cast<int>(exprs_.size());
      auto named = users.find(p);
      if (named != users.end()) {
        const std::vector<int> before = std::move(named->second);
        users.erase(named);
        for (int j : before) {
          Expr& other = exprs_[j];
          double a = 0.0;
          for (auto it = other.terms.begin(); it != other.terms.end(); ++it)
            if (it->first == p) {
              a = it->second;
              other.terms.erase(it);
              break;
            }
          for (const auto& [k, c] : e.terms)
            if (merge(other.terms, k, a * c)) users[k].push_back(j);
          for (const auto& [l, b] : e.rhs) merge(other.rhs, l, a * b);
        }
      }
      for (const auto& [k, c] : e.terms) users[k].push_back(index);
      position[p] = index;
      exprs_.push_back(std::move(e));
      pivot_[i] = p;
    }
    // C_P^T, for the relations' forces: row j is pivot j's column of C over the relations kept.
    kept_.clear();
    for (int i = 0; i < m; ++i)
      if (pivot_[i] >= 0) kept_.push_back(i);
    const int n = static_cast<int>(kept_.size());
    std::map<int, int> column_of_pivot;
    for (int j = 0; j < n; ++j) column_of_pivot[pivot_[kept_[j]]] = j;
    std::vector<Triplet> t;
    for (int j = 0; j < n; ++j)
      for (const auto& term : relations[kept_[j]].terms) {
        auto it = column_of_pivot.find(dofs.dof(term.node, term.component));
        if (it != column_of_pivot.end()) t.emplace_back(it->second, j, term.coef);  // (pivot, relation): C^T
      }
    SparseMatrix ct(n, n);
    ct.setFromTriplets(t.begin(), t.end());
    if (n > 0) {
      lu_.compute(ct);
      LUNASTER_ASSERT(lu_.info() == Eigen::Success, "the relations' pivots make a singular block");
    }
  }

  /// The eliminations at iterate u: du_p = sum a du_k + (sum a u_k + sum b v_l - u_p).
  void eliminations(const Vector& u, const std::function<double(int)>& rhs_value, std::vector<Elimination>& out) const {
    for (const Expr& e : exprs_) {
      Elimination el;
      el.eq = e.eq;
      el.terms = e.terms;
      double target = 0.0;
      for (const auto& [k, a] : e.terms) target += a * u[k];
      for (const auto& [l, b] : e.rhs) target += b * rhs_value(l);
      el.value = target - u[e.eq];
      out.push_back(std::move(el));
    }
  }

  /// Adds the relations' forces C^T lambda to `residual`, lambda making its pivots' rows zero.
  void add_forces(const std::vector<LinearRelation>& relations, const DofMap& dofs, Vector& residual) const {
    const int n = static_cast<int>(kept_.size());
    if (n == 0) return;
    Eigen::VectorXd r(n);
    for (int j = 0; j < n; ++j) r[j] = -residual[pivot_[kept_[j]]];
    const Eigen::VectorXd lambda = lu_.solve(r);
    for (int j = 0; j < n; ++j)
      for (const auto& t : relations[kept_[j]].terms) residual[dofs.dof(t.node, t.component)] += t.coef * lambda[j];
  }

  bool empty() const { return exprs_.empty(); }
  /// The relations left with imposed unknowns only once the pivots before them are substituted.
  const std::vector<ImposedRelation>& imposed_only() const { return imposed_only_; }

 private:
  struct Expr {
    int eq = -1;
    std::vector<std::pair<int, double>> terms;  ///< (equation, a)
    std::vector<std::pair<int, double>> rhs;    ///< (relation, b)
  };
  /// Adds value to key's entry; true when the key was not in the list.
  static bool merge(std::vector<std::pair<int, double>>& list, int key, double value) {
    for (auto& [k, v] : list)
      if (k == key) return v += value, false;
    list.emplace_back(key, value);
    return true;
  }

  std::vector<Expr> exprs_;
  std::vector<int> pivot_;  ///< per relation, its pivot equation; -1 when left out
  std::vector<int> kept_;   ///< relations with a pivot
  std::vector<ImposedRelation> imposed_only_;
  Eigen::SparseLU<SparseMatrix> lu_;
};

class RelationsHook final : public ContactHook {
 public:
  RelationsHook(std::vector<LinearRelation> relations, std::vector<std::function<double(double)>> multipliers,
                std::unique_ptr<ContactHook> contact, bool eliminate)
      : relations_(std::move(relations)),
        multipliers_(std::move(multipliers)),
        contact_(std::move(contact)),
        eliminate_(eliminate) {}

  void set_dirichlet(const std::vector<DirichletValue>& dirichlet) override {
    imposed_.clear();
    for (const auto& d : dirichlet) imposed_.insert({d.node, d.component});
    dirichlet_ = dirichlet;
    if (!contact_) return;
    contact_->set_dirichlet(dirichlet);
    std::vector<std::pair<int, int>> related;
    for (const auto& r : relations_.relations())
      for (const auto& t : r.terms) related.emplace_back(t.node, t.component);
    contact_->set_related(related);
  }
  void add_dofs(DofMap& dofs) override {
    if (contact_) contact_->add_dofs(dofs);  // its carriers first (QUAD8 ties name theirs)
    // Each imposed equation's value and load, the last condition winning as in the driver.
    imposed_value_.clear();
    for (const auto& d : dirichlet_)
      if (dofs.dof(d.node, d.component) >= 0) imposed_value_[dofs.dof(d.node, d.component)] = {d.value, d.load};
    if (!eliminate_) {
      relations_.add_dofs(dofs, imposed_);
      imposed_only_.clear();
      for (size_t i = 0; i < relations_.relations().size(); ++i) {
        const LinearRelation& r = relations_.relations()[i];
        if (r.multiplier >= 0) continue;  // a multiplier holds it
        ImposedRelation check;
        check.relation = static_cast<int>(i);
        for (const auto& t : r.terms) check.terms.emplace_back(dofs.dof(t.node, t.component), t.coef);
        check.rhs.emplace_back(static_cast<int>(i), 1.0);
        imposed_only_.push_back(std::move(check));
      }
      dofs_ = dofs;
      return;
    }
    std::set<int> constrained;
    for (const auto& [node, component] : imposed_)
      if (dofs.dof(node, component) >= 0) constrained.insert(dofs.dof(node, component));
    eliminator_.build(relations_.relations(), dofs, [&constrained](int eq) { return !constrained.count(eq); });
    imposed_only_ = eliminator_.imposed_only();
    dofs_ = dofs;
  }
  void share_among_ranks(const std::vector<char>& owned_nodes) override {
    if (contact_) contact_->share_among_ranks(owned_nodes);
  }
  void set_instant(double t) override {
    t_ = t;
    check_imposed_only();
    if (contact_) contact_->set_instant(t);
  }
  void begin_step(const Vector& u, const Log& log) override {
    if (contact_) contact_->begin_step(u, log);
  }
  // The relations' terms go in first: a contact hook may read the residual it is given (mortar
  // recovers its pressures from the slave nodes' equilibrium, which a relation's force is part of).
  // Eliminated, their forces come from the pivots' rows of the residual, contact forces included:
  // the contact's terms go in first (a hook that reads its residual and eliminates, mortar, is
  // refused beside eliminated relations by the command).
  void add_to_system(const Vector& u, std::vector<Triplet>& tangent, Vector& residual) override {
    if (eliminate_) {
      if (contact_) contact_->add_to_system(u, tangent, residual);
      eliminator_.add_forces(relations_.relations(), dofs_, residual);
      eliminations_ = contact_ ? contact_->eliminations() : std::vector<Elimination>{};
      eliminator_.eliminations(u, rhs_value(), eliminations_);
      return;
    }
    relations_.add_to_system(dofs_, u, tangent, residual, factor());
    if (contact_) contact_->add_to_system(u, tangent, residual);
  }
  bool add_residual(const Vector& u, Vector& residual) override {
    if (eliminate_) {
      if (contact_ && !contact_->add_residual(u, residual)) return false;
      eliminator_.add_forces(relations_.relations(), dofs_, residual);
      return true;
    }
    if (!contact_) {
      relations_.add_residual(dofs_, u, residual, factor());
      return true;
    }
    // Neither part when the contact hook gives none: the entries the relations touch are put
    // back as they were (their equations only, not a copy of the whole residual per iteration).
    std::vector<std::pair<int, double>> given;
    for (const auto& r : relations_.relations()) {
      if (r.multiplier < 0) continue;
      given.emplace_back(r.multiplier, residual[r.multiplier]);
      for (const auto& t : r.terms) {
        const int eq = dofs_.dof(t.node, t.component);
        given.emplace_back(eq, residual[eq]);
      }
    }
    relations_.add_residual(dofs_, u, residual, factor());
    if (!contact_->add_residual(u, residual)) {
      for (auto it = given.rbegin(); it != given.rend(); ++it) residual[it->first] = it->second;
      return false;
    }
    return true;
  }
  const std::vector<int>& condensed_equations() const override {
    return contact_ ? contact_->condensed_equations() : ContactHook::condensed_equations();
  }
  void recover(Vector& u) override {
    if (contact_) contact_->recover(u);
  }
  const std::vector<Elimination>& eliminations() const override {
    if (eliminate_) return eliminations_;
    return contact_ ? contact_->eliminations() : ContactHook::eliminations();
  }
  std::vector<int> surface_equations() const override {
    // Without contact, none: the elastic part kept aside is a contact device (InterfaceSolver).
    std::vector<int> eqs = contact_ ? contact_->surface_equations() : std::vector<int>{};
    if (eqs.empty()) return eqs;  // not known: the driver keeps no elastic part aside
    const std::vector<int> mine = related_equations();
    eqs.insert(eqs.end(), mine.begin(), mine.end());
    std::sort(eqs.begin(), eqs.end());
    eqs.erase(std::unique(eqs.begin(), eqs.end()), eqs.end());
    return eqs;
  }
  std::array<bool, 3> displacement_components() const override {
    std::array<bool, 3> reached = contact_ ? contact_->displacement_components() : std::array<bool, 3>{};
    for (const auto& r : relations_.relations())
      if (r.multiplier >= 0 || eliminate_)
        for (const auto& t : r.terms) reached[t.component] = true;
    return reached;
  }
  bool newton_converged() const override { return contact_ ? contact_->newton_converged() : true; }
  bool settle(const Vector& u, const Log& log) override { return contact_ ? contact_->settle(u, log) : true; }
  long pattern_version() const override { return contact_ ? contact_->pattern_version() : 0; }
  unsigned long long status_key() const override { return contact_ ? contact_->status_key() : 0ULL; }
  MatrixKind matrix_kind() const override {
    if (relations_.any_multiplier()) return MatrixKind::SymmetricIndefinite;
    return contact_ ? contact_->matrix_kind() : MatrixKind::SymmetricPositiveDefinite;
  }
  int n_active() const override { return contact_ ? contact_->n_active() : 0; }
  bool has_contact() const override { return contact_ != nullptr; }
  std::vector<int> related_equations() const override {
    std::vector<int> eqs = contact_ ? contact_->related_equations() : std::vector<int>{};
    for (const auto& r : relations_.relations()) {
      if (r.multiplier < 0 && !eliminate_) continue;
      if (r.multiplier >= 0) eqs.push_back(r.multiplier);
      for (const auto& t : r.terms) eqs.push_back(dofs_.dof(t.node, t.component));
    }
    return eqs;
  }
  void write_fields(const Vector& u, ResultStep& step) const override {
    if (contact_) contact_->write_fields(u, step);
  }
  void write_initial_fields(ResultStep& step) const override {
    if (contact_) contact_->write_initial_fields(step);
  }
  ContactSnapshot snapshot() const override { return contact_ ? contact_->snapshot() : ContactSnapshot{}; }
  void commit_step(const Vector& u) override {
    if (contact_) contact_->commit_step(u);
  }
  std::vector<std::string> failure_hints() const override {
    return contact_ ? contact_->failure_hints() : std::vector<std::string>{};
  }
  void restore(const ContactSnapshot& state) override {
    if (contact_) contact_->restore(state);
  }

 private:
  std::function<double(int)> factor() const {
    return [this](int load) { return multipliers_[load](t_); };
  }
  /// The right-hand side of relation l at this instant.
  std::function<double(int)> rhs_value() const {
    return [this](int l) {
      const LinearRelation& r = relations_.relations()[l];
      return r.load >= 0 ? r.value * multipliers_[r.load](t_) : r.value;
    };
  }

  /// A relation that relates imposed unknowns only holds without any unknown of its own:
  /// the imposed values at this instant must satisfy it (to 1e-9 of its terms), else the
  /// conditions contradict each other and the run stops.
  void check_imposed_only() const {
    const std::function<double(int)> v = rhs_value();
    for (const ImposedRelation& check : imposed_only_) {
      double lhs = 0.0, rhs = 0.0, scale = 0.0;
      for (const auto& [eq, c] : check.terms) {
        const auto it = imposed_value_.find(eq);
        LUNASTER_ASSERT(it != imposed_value_.end(), "a relation's imposed unknown has no imposed value");
        const double value = it->second.second >= 0 ? it->second.first * multipliers_[it->second.second](t_)
                                                    : it->second.first;
        lhs += c * value;
        scale += std::abs(c * value);
      }
      for (const auto& [l, b] : check.rhs) {
        rhs += b * v(l);
        scale += std::abs(b * v(l));
      }
      if (std::abs(lhs - rhs) <= 1e-9 * scale) continue;
      std::ostringstream msg;
      msg.precision(10);
      msg << relation_name(relations_.relations()[check.relation], check.relation)
          << " relates imposed unknowns only"
          << (eliminate_ ? " (once the relations before it are solved for their unknowns)" : "")
          << ", and their imposed values contradict it at t = " << t_ << ": its terms sum to " << lhs
          << ", its right-hand side is " << rhs
          << "; change one of the imposed values it relates, or remove the relation if the deck wrote it";
      throw DeckError(msg.str());
    }
  }

  LinearRelations relations_;
  std::vector<std::function<double(double)>> multipliers_;
  std::unique_ptr<ContactHook> contact_;
  std::set<std::pair<int, int>> imposed_;
  std::vector<DirichletValue> dirichlet_;
  std::map<int, std::pair<double, int>> imposed_value_;  ///< imposed equation -> (value, load)
  std::vector<ImposedRelation> imposed_only_;            ///< relations checked at every instant
  /// The numbering the hook gave (a copy: on a mesh in parts the driver renumbers its own map and
  /// speaks to the hook through RenumberedHook).
  DofMap dofs_;
  double t_ = 0.0;
  const bool eliminate_;
  RelationEliminator eliminator_;
  std::vector<Elimination> eliminations_;  ///< the contact's and the relations', at the last add_to_system
};

}  // namespace

std::unique_ptr<ContactHook> make_relations_hook(std::vector<LinearRelation> relations,
                                                 std::vector<std::function<double(double)>> multipliers,
                                                 std::unique_ptr<ContactHook> contact, bool eliminate) {
  return std::make_unique<RelationsHook>(std::move(relations), std::move(multipliers), std::move(contact),
                                         eliminate);
}

}  // namespace lunaster::engine
