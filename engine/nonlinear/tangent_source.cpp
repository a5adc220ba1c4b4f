#include "engine/nonlinear/tangent_source.hpp"

#include "engine/assembly/assembly.hpp"
#include "engine/assembly/tangent.hpp"
#include "engine/nonlinear/sci.hpp"

namespace lunaster::engine {

namespace {

class ElasticTangent final : public TangentSource {
 public:
  ElasticTangent(const FeModel& model, const DofMap& dofs, const std::vector<char>* owned_nodes)
      : model_(model), dofs_(dofs), owned_nodes_(owned_nodes) {}
  bool constant() const override { return true; }
  bool assemble(const Vector& u, SparseMatrix* k, Vector* f_int) override {
    SparseMatrix assembled = assemble_stiffness_matrix(model_, dofs_, owned_nodes_);
    if (f_int) *f_int = assembled * u;
    if (k) k->swap(assembled);  // Eigen 3.4's sparse assignment would copy it
    return true;
  }

 private:
  const FeModel& model_;
  const DofMap& dofs_;
  const std::vector<char>* owned_nodes_;
};

/// The behaviours' tangent: assembly's Tangent, whose states follow the driver's steps.
class BehaviourTangent final : public TangentSource {
 public:
  BehaviourTangent(const CellBehaviours& behaviours, const DofMap& dofs)
      : tangent_(behaviours, dofs), positive_definite_(behaviours.tangents_positive_definite()) {}
  bool constant() const override { return tangent_.constant(); }
  bool positive_definite() const override { return positive_definite_; }
  bool assemble(const Vector& u, SparseMatrix* k, Vector* f_int) override { return tangent_.assemble(u, k, f_int); }
  void commit() override { tangent_.commit(); }
  void restore() override { tangent_.restore(); }
  const MaterialStates* states() const override { return &tangent_.states(); }

 private:
  Tangent tangent_;
  bool positive_definite_;
};

}  // namespace

std::unique_ptr<TangentSource> make_behaviour_tangent(const CellBehaviours& behaviours, const DofMap& dofs,
                                                      RankLayout::Kind layout) {
  if (behaviours.all_linear()) return nullptr;
  if (layout != RankLayout::Kind::Whole) {
    const bool in_parts = layout == RankLayout::Kind::InParts;
    DeckError refused(std::string("a nonlinear behaviour is integrated on a model whole on each rank, not on a ") +
                      (in_parts ? "mesh in parts" : "model shared among the ranks"));
    refused.failure().what = Failure::What::SharedBehaviour;
    refused.failure().count = in_parts ? 1 : 0;
    throw refused;
  }
  return std::make_unique<BehaviourTangent>(behaviours, dofs);
}

ConvergenceError integration_failure(double t) {
  ConvergenceError err("a behaviour's integration failed at an integration point at instant " + sci(t),
                       {"no admissible state at the step's end: a smaller step may have one"});
  err.failure().what = Failure::What::BehaviourIntegration;
  return err;
}

ConvergenceError tangent_solve_failure(const SolveError& err, double t) {
  std::vector<std::string> hints{"the linear solver: " + err.message()};
  hints.insert(hints.end(), err.hints().begin(), err.hints().end());
  hints.push_back("a behaviour may have lost its stiffness: no equilibrium at this load, or a step too large");
  return ConvergenceError("the behaviours' tangent could not be solved at instant " + sci(t), hints);
}

std::unique_ptr<TangentSource> make_elastic_tangent(const FeModel& model, const DofMap& dofs,
                                                    const std::vector<char>* owned_nodes) {
  return std::make_unique<ElasticTangent>(model, dofs, owned_nodes);
}

}  // namespace lunaster::engine
