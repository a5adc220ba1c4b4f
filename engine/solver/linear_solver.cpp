/// Backend factory.
#include "engine/solver/linear_solver.hpp"

#include "engine/core/error.hpp"
#include "engine/solver/backends.hpp"

namespace lunaster::engine {

std::unique_ptr<LinearSolver> make_linear_solver(SolverKind kind) {
  switch (kind) {
    case SolverKind::Cholmod: return make_cholmod_solver();
    case SolverKind::Umfpack: return make_umfpack_solver();
    case SolverKind::Mumps: return make_mumps_solver();
  }
  throw InternalError("make_linear_solver: unknown solver kind");
}

}  // namespace lunaster::engine
