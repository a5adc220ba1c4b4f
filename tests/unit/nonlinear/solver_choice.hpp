#pragma once
// The two ways the unit tests of the driver's linear solve name its backend.
#include "engine/nonlinear/newton_options.hpp"

namespace lunaster::engine::test {

/// Newton to a relative residual of 1e-10, with the automatic choice of the backend (`automatic`)
/// or MUMPS named.
inline NewtonOptions auto_or_mumps(bool automatic) {
  NewtonOptions options;
  options.resi_glob_rela = 1e-10;
  options.auto_solver = automatic;
  if (!automatic) options.solver = SolverKind::Mumps;
  return options;
}

}  // namespace lunaster::engine::test
