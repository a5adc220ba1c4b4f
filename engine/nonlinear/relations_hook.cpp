#include "engine/nonlinear/relations_hook.hpp"

#include <algorithm>
#include <set>
#include <utility>

#include "engine/assembly/linear_relations.hpp"

namespace lunaster::engine {

namespace {

class RelationsHook final : public ContactHook {
 public:
  RelationsHook(std::vector<LinearRelation> relations, std::vector<std::function<double(double)>> multipliers,
                std::unique_ptr<ContactHook> contact)
      : relations_(std::move(relations)), multipliers_(std::move(multipliers)), contact_(std::move(contact)) {}

  void set_dirichlet(const std::vector<DirichletValue>& dirichlet) override {
    imposed_.clear();
    for (const auto& d : dirichlet) imposed_.insert({d.node, d.component});
    if (contact_) contact_->set_dirichlet(dirichlet);
  }
  void add_dofs(DofMap& dofs) override {
    if (contact_) contact_->add_dofs(dofs);  // its carriers first (QUAD8 ties name theirs)
    relations_.add_dofs(dofs, imposed_);
    dofs_ = &dofs;
  }
  void share_among_ranks(const std::vector<char>& owned_nodes) override {
    if (contact_) contact_->share_among_ranks(owned_nodes);
  }
  void set_instant(double t) override {
    t_ = t;
    if (contact_) contact_->set_instant(t);
  }
  void begin_step(const Vector& u, const Log& log) override {
    if (contact_) contact_->begin_step(u, log);
  }
  // The relations' terms go in first: a contact hook may read the residual it is given (mortar
  // recovers its pressures from the slave nodes' equilibrium, which a relation's force is part of).
  void add_to_system(const Vector& u, std::vector<Triplet>& tangent, Vector& residual) override {
    relations_.add_to_system(*dofs_, u, tangent, residual, factor());
    if (contact_) contact_->add_to_system(u, tangent, residual);
  }
  bool add_residual(const Vector& u, Vector& residual) override {
    if (!contact_) {
      relations_.add_residual(*dofs_, u, residual, factor());
      return true;
    }
    const Vector given = residual;
    relations_.add_residual(*dofs_, u, residual, factor());
    if (!contact_->add_residual(u, residual)) {
      residual = given;  // neither part: the driver calls add_to_system instead
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
      if (r.multiplier >= 0)
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
      if (r.multiplier < 0) continue;
      eqs.push_back(r.multiplier);
      for (const auto& t : r.terms) eqs.push_back(dofs_->dof(t.node, t.component));
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
  void restore(const ContactSnapshot& state) override {
    if (contact_) contact_->restore(state);
  }

 private:
  std::function<double(int)> factor() const {
    return [this](int load) { return multipliers_[load](t_); };
  }

  LinearRelations relations_;
  std::vector<std::function<double(double)>> multipliers_;
  std::unique_ptr<ContactHook> contact_;
  std::set<std::pair<int, int>> imposed_;
  const DofMap* dofs_ = nullptr;
  double t_ = 0.0;
};

}  // namespace

std::unique_ptr<ContactHook> make_relations_hook(std::vector<LinearRelation> relations,
                                                 std::vector<std::function<double(double)>> multipliers,
                                                 std::unique_ptr<ContactHook> contact) {
  return std::make_unique<RelationsHook>(std::move(relations), std::move(multipliers), std::move(contact));
}

}  // namespace lunaster::engine
