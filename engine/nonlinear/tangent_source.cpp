#include "engine/nonlinear/tangent_source.hpp"

#include "engine/assembly/assembly.hpp"

namespace lunaster::engine {

namespace {

class ElasticTangent final : public TangentSource {
 public:
  ElasticTangent(const FeModel& model, const DofMap& dofs, const std::vector<char>* owned_nodes)
      : model_(model), dofs_(dofs), owned_nodes_(owned_nodes) {}
  bool constant() const override { return true; }
  void assemble(const Vector& u, SparseMatrix* k, Vector* f_int) override {
    SparseMatrix assembled = assemble_stiffness_matrix(model_, dofs_, owned_nodes_);
    if (f_int) *f_int = assembled * u;
    if (k) k->swap(assembled);  // Eigen 3.4's sparse assignment would copy it
  }

 private:
  const FeModel& model_;
  const DofMap& dofs_;
  const std::vector<char>* owned_nodes_;
};

}  // namespace

std::unique_ptr<TangentSource> make_elastic_tangent(const FeModel& model, const DofMap& dofs,
                                                    const std::vector<char>* owned_nodes) {
  return std::make_unique<ElasticTangent>(model, dofs, owned_nodes);
}

}  // namespace lunaster::engine
