#include "engine/nonlinear/renumbered_hook.hpp"

#include <algorithm>

#include "engine/core/error.hpp"

namespace lunaster::engine {

RenumberedHook::RenumberedHook(ContactHook& inner, std::vector<int> new_of_old)
    : inner_(inner), new_of_old_(std::move(new_of_old)) {}

void RenumberedHook::add_dofs(DofMap& /*dofs*/) {
  LUNASTER_ASSERT(false, "a renumbered hook has its unknowns already: add_dofs comes before the renumbering");
}

Vector RenumberedHook::to_hook(const Vector& v) const {
  LUNASTER_ASSERT(v.size() == static_cast<Eigen::Index>(new_of_old_.size()), "a vector of another numbering");
  Vector out(v.size());
  for (size_t e = 0; e < new_of_old_.size(); ++e) out[static_cast<Eigen::Index>(e)] = v[new_of_old_[e]];
  return out;
}

Vector RenumberedHook::to_driver(const Vector& v) const {
  Vector out(v.size());
  for (size_t e = 0; e < new_of_old_.size(); ++e) out[new_of_old_[e]] = v[static_cast<Eigen::Index>(e)];
  return out;
}

std::vector<int> RenumberedHook::renumbered(std::vector<int> eqs) const {
  for (int& eq : eqs) eq = new_of_old_[eq];
  std::sort(eqs.begin(), eqs.end());
  return eqs;
}

void RenumberedHook::take_equation_lists() {
  condensed_ = inner_.condensed_equations();
  for (int& eq : condensed_) eq = new_of_old_[eq];
  eliminations_ = inner_.eliminations();
  for (Elimination& e : eliminations_) {
    e.eq = new_of_old_[e.eq];
    for (auto& term : e.terms) term.first = new_of_old_[term.first];
  }
}

void RenumberedHook::add_to_system(const Vector& u, std::vector<Triplet>& tangent, Vector& residual) {
  Vector r = to_hook(residual);
  const size_t first = tangent.size();
  inner_.add_to_system(to_hook(u), tangent, r);
  for (size_t k = first; k < tangent.size(); ++k)
    tangent[k] = Triplet(new_of_old_[tangent[k].row()], new_of_old_[tangent[k].col()], tangent[k].value());
  residual = to_driver(r);
  take_equation_lists();
}

bool RenumberedHook::add_residual(const Vector& u, Vector& residual) {
  Vector r = to_hook(residual);
  if (!inner_.add_residual(to_hook(u), r)) return false;
  residual = to_driver(r);
  return true;
}

void RenumberedHook::recover(Vector& u) {
  Vector mine = to_hook(u);
  inner_.recover(mine);
  u = to_driver(mine);
}

}  // namespace lunaster::engine
