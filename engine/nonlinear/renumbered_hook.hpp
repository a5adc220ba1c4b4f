#pragma once
/// A contact hook seen through a renumbering of the unknowns. On a mesh in parts the driver
/// wants a rank's owned unknowns first (engine/assembly/global_dofs.hpp), while a hook adds its
/// multipliers (LAGS_C) after every node's displacements, the ghosts' included: the driver then
/// renumbers its unknowns and talks to the hook through this adapter, which gives the hook its
/// own numbering (vectors permuted in and out, triplets and equation lists renumbered).
#include <vector>

#include "engine/contact/contact_hook.hpp"

namespace lunaster::engine {

class RenumberedHook final : public ContactHook {
 public:
  /// `new_of_old[e]`: the driver's number of the hook's equation e (a permutation).
  RenumberedHook(ContactHook& inner, std::vector<int> new_of_old);

  void set_dirichlet(const std::vector<DirichletValue>& dirichlet) override { inner_.set_dirichlet(dirichlet); }
  void set_related(const std::vector<std::pair<int, int>>& related) override { inner_.set_related(related); }
  void add_dofs(DofMap& /*dofs*/) override;
  void set_instant(double t) override { inner_.set_instant(t); }
  void begin_step(const Vector& u, const Log& log) override { inner_.begin_step(to_hook(u), log); }
  void add_to_system(const Vector& u, std::vector<Triplet>& tangent, Vector& residual) override;
  bool add_residual(const Vector& u, Vector& residual) override;
  const std::vector<int>& condensed_equations() const override { return condensed_; }
  void recover(Vector& u) override;
  const std::vector<Elimination>& eliminations() const override { return eliminations_; }
  std::vector<int> surface_equations() const override { return renumbered(inner_.surface_equations()); }
  std::array<bool, 3> displacement_components() const override { return inner_.displacement_components(); }
  bool newton_converged() const override { return inner_.newton_converged(); }
  bool settle(const Vector& u, const Log& log) override { return inner_.settle(to_hook(u), log); }
  long pattern_version() const override { return inner_.pattern_version(); }
  unsigned long long status_key() const override { return inner_.status_key(); }
  MatrixKind matrix_kind() const override { return inner_.matrix_kind(); }
  int n_active() const override { return inner_.n_active(); }
  bool has_contact() const override { return inner_.has_contact(); }
  std::vector<int> related_equations() const override { return renumbered(inner_.related_equations()); }
  void write_fields(const Vector& u, ResultStep& step) const override { inner_.write_fields(to_hook(u), step); }
  void write_initial_fields(ResultStep& step) const override { inner_.write_initial_fields(step); }
  ContactSnapshot snapshot() const override { return inner_.snapshot(); }
  void restore(const ContactSnapshot& state) override { inner_.restore(state); }
  void commit_step(const Vector& u) override { inner_.commit_step(to_hook(u)); }
  std::vector<std::string> failure_hints() const override { return inner_.failure_hints(); }

 private:
  Vector to_hook(const Vector& v) const;
  Vector to_driver(const Vector& v) const;
  /// The driver's numbers of the hook's equations, sorted.
  std::vector<int> renumbered(std::vector<int> eqs) const;
  /// condensed_ and eliminations_ from the hook's, after its add_to_system.
  void take_equation_lists();

  ContactHook& inner_;
  std::vector<int> new_of_old_;
  std::vector<int> condensed_;
  std::vector<Elimination> eliminations_;
};

}  // namespace lunaster::engine
