#pragma once
/// The concepts (typed results) commands return. Each wraps engine data.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "catalog/args.hpp"
#include "catalog/concept.hpp"
#include "engine/assembly/mesh_part.hpp"
#include "engine/contact/contact_definition.hpp"
#include "engine/fe/fe_model.hpp"
#include "engine/fields/fields.hpp"
#include "engine/material/isotropic_hardening.hpp"
#include "engine/mesh/mesh.hpp"
#include "engine/nonlinear/loads.hpp"
#include "engine/nonlinear/static_solver.hpp"

namespace lunaster::cmd {

using catalog::Concept;
using catalog::ConceptPtr;

/// LIRE_MAILLAGE, DEFI_GROUP (reuse), MODI_MAILLAGE (reuse).
struct Maillage : Concept {
  /// The mesh the commands work on: the whole mesh, or this rank's part of a mesh in parts.
  std::shared_ptr<engine::Mesh> mesh = std::make_shared<engine::Mesh>();
  std::string source_file;  ///< file the mesh was read from, for messages
  /// A mesh in parts (PARTITIONNEUR): this rank's part (`mesh` is its part.mesh), and on rank
  /// 0 the whole mesh it read, which IMPR_RESU writes the gathered fields on. Null otherwise.
  std::shared_ptr<engine::MeshPart> part;
  std::shared_ptr<engine::Mesh> whole;
  std::string type_name() const override { return "maillage"; }
  bool in_parts() const override { return part != nullptr; }
  /// The meshes a change of the mesh (DEFI_GROUP, MODI_MAILLAGE) applies to: `mesh`, and on rank
  /// 0 of a mesh in parts the whole mesh too; the last is the one the log speaks of.
  std::vector<engine::Mesh*> changed_meshes() const {
    std::vector<engine::Mesh*> out{mesh.get()};
    if (whole) out.push_back(whole.get());
    return out;
  }
};

/// AFFE_MODELE: which cells carry which mechanical element.
struct Modele : Concept {
  std::shared_ptr<Maillage> maillage;
  int dim = 0;
  std::vector<engine::Modelisation> modelisation;  ///< per cell
  std::string type_name() const override { return "modele"; }
  bool in_parts() const override { return maillage && maillage->in_parts(); }
};

/// DEFI_MATERIAU.
struct Mater : Concept {
  engine::ElasticMaterial elas;
  bool has_elas = false;
  /// ECRO_LINE: R(p) = SY + H p with H = E D_SIGM_EPSI / (E - D_SIGM_EPSI), E of ELAS.
  std::optional<engine::IsotropicHardening> ecro_line;
  /// TRACTION: the curve's E (first point) and R(p); NU comes from ELAS.
  std::optional<engine::TractionCurve> traction;
  std::string type_name() const override { return "mater"; }
};

/// AFFE_MATERIAU: material per cell.
struct ChamMater : Concept {
  std::shared_ptr<Maillage> maillage;
  std::vector<int> material;                      ///< per cell, index into materials, -1 none
  std::vector<engine::ElasticMaterial> materials;
  std::vector<std::shared_ptr<const Mater>> maters;  ///< per index of materials: its DEFI_MATERIAU
  std::string type_name() const override { return "cham_mater"; }
  bool in_parts() const override { return maillage && maillage->in_parts(); }
};

/// AFFE_CHAR_MECA: Dirichlet values, pressures, distributed and nodal forces and (seed syntax) contact.
/// Load indices inside are all 0; STAT_NON_LINE renumbers them per EXCIT.
struct CharMeca : Concept {
  std::shared_ptr<Modele> modele;
  std::vector<engine::DirichletValue> dirichlet;
  std::vector<engine::PressureLoad> pressures;
  std::vector<engine::NodalForce> forces;
  /// FORCE_CONTOUR, FORCE_FACE, FORCE_ARETE, FORCE_INTERNE and PESANTEUR (per_mass).
  std::vector<engine::DistributedForce> distributed;
  /// LIAISON_DDL and LIAISON_UNIF, as written (load -1); on a mesh in parts their nodes are the
  /// whole mesh's numbers (a relation may tie nodes of several parts), the same on every rank.
  std::vector<engine::LinearRelation> relations;
  bool has_contact = false;
  engine::ContactDefinition contact;
  std::string type_name() const override { return "char_meca"; }
  bool in_parts() const override { return modele && modele->in_parts(); }
};

/// DEFI_CONTACT.
struct CharContact : Concept {
  std::shared_ptr<Modele> modele;
  engine::ContactDefinition contact;
  std::string type_name() const override { return "char_contact"; }
  bool in_parts() const override { return modele && modele->in_parts(); }
};

/// DEFI_LIST_REEL.
struct ListR8 : Concept {
  std::vector<double> values;
  std::string type_name() const override { return "listr8"; }
};

/// A function of named real parameters: DEFI_FONCTION, DEFI_CONSTANTE, FORMULE, a deck's own function.
struct RealFunction : Concept {
  /// The parameter names, in the order of a call; empty for a deck's function (any number of arguments).
  virtual std::vector<std::string> parameters() const = 0;
  /// The value for these parameter values; DeckError where it is not defined.
  virtual double evaluate(const std::vector<double>& values) const = 0;
};

/// DEFI_FONCTION: piecewise linear function of one parameter (DEFI_CONSTANTE: one point, constant).
struct Fonction : RealFunction {
  std::string nom_para = "INST";
  std::vector<double> abscissas, ordinates;
  char prol_gauche = 'E', prol_droite = 'E';  ///< 'E' exclu, 'C' constant, 'L' linéaire
  /// Value at x; throws DeckError outside the range when prolongation is 'E'.
  double operator()(double x) const;
  std::vector<std::string> parameters() const override { return {nom_para}; }
  double evaluate(const std::vector<double>& values) const override;
  std::string type_name() const override { return "fonction"; }
};

/// FORMULE: an expression of named parameters (commands/formula.hpp reads it).
struct Formule : RealFunction {
  std::vector<std::string> nom_para;
  std::string vale;  ///< the expression as given
  std::function<double(const std::vector<double>&)> compiled;
  std::vector<std::string> parameters() const override { return nom_para; }
  double evaluate(const std::vector<double>& values) const override;
  std::string type_name() const override { return "formule"; }
};

/// STAT_NON_LINE result (and CALC_CHAMP reuse).
struct EvolNoli : Concept {
  std::shared_ptr<Modele> modele;
  std::shared_ptr<ChamMater> cham_mater;
  std::vector<engine::ResultStep> steps;
  /// The loads of the EXCIT that made it, with their multipliers: REAC_NODA subtracts them.
  engine::MechanicalLoads loads;
  engine::SolverStats stats;  ///< cost of the STAT_NON_LINE that made it (IMPR_MESURE)
  /// With a model shared among MPI ranks: per mesh cell, the rank that held it (CALC_CHAMP
  /// computes each cell there); empty otherwise.
  std::vector<int> cell_rank;
  /// Some cells in large rotations (DEFORMATION='GROT_GDEP'): CALC_CHAMP's stresses from the
  /// displacement would be small strain's, so it refuses them.
  bool large_rotations = false;
  std::string type_name() const override { return "evol_noli"; }
  bool in_parts() const override { return modele && modele->in_parts(); }
};

}  // namespace lunaster::cmd

namespace lunaster::cmd {

/// CREA_CHAMP: one field on a mesh, a copy of a result's field at one time step, or built at
/// nodes (AFFE, ASSE, COMB, EVAL).
struct ChamGd : Concept {
  std::shared_ptr<Maillage> maillage;
  std::string type_cham;    ///< code_aster's field type: "NOEU_DEPL_R", "ELNO_SIEF_R", "ELGA_SIEF_R" ...
  std::string nom_cham;     ///< the result's field it was taken from (a built field: its quantity, DEPL ...)
  engine::NodalField nodal; ///< a NOEU_* field (a NOEU_*_F field: where each function is defined)
  engine::ElgaField cells;  ///< an ELNO_* field (no point layouts) or an ELGA_* field
  /// A NOEU_*_F field: the function of each node and component, laid out as nodal.values.
  std::vector<std::shared_ptr<const RealFunction>> functions;
  bool at_nodes() const { return type_cham.rfind("NOEU_", 0) == 0; }
  bool of_functions() const { return type_cham.size() > 2 && type_cham.compare(type_cham.size() - 2, 2, "_F") == 0; }
  std::string type_name() const override { return "cham_gd"; }
};

/// DEFI_LIST_INST: instants plus what to do when a step fails.
struct ListInst : Concept {
  std::vector<double> instants;
  bool subdivide = false;  ///< ECHEC/ACTION='DECOUPE'
  int subd_pas = 4;        ///< SUBD_PAS: sub-steps per failed step
  int subd_niveau = 3;     ///< SUBD_NIVEAU: maximum nesting of subdivisions
  std::string type_name() const override { return "list_inst"; }
};

/// Builds the engine model from AFFE_MODELE and AFFE_MATERIAU results; DeckError
/// (at `kw`) naming the first modelled cell without a material.
engine::FeModel build_fe_model(const Modele& mo, const ChamMater& cm, const catalog::Args& args, const std::string& kw);

}  // namespace lunaster::cmd
