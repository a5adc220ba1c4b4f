// STAT_NON_LINE: quasi-static incremental analysis (Newton), with contact.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <unordered_map>

#include "commands/commands.hpp"
#include "commands/concepts.hpp"
#include "commands/contact_keywords.hpp"
#include "commands/part_results.hpp"
#include "commands/parts.hpp"
#include "commands/selection.hpp"
#include "commands/failures.hpp"
#include "engine/contact/contact_factory.hpp"
#include "engine/assembly/halo.hpp"
#include "engine/io/med_writer.hpp"
#include "engine/material/cell_behaviours.hpp"
#include "engine/material/elasticity.hpp"
#include "engine/material/von_mises.hpp"
#include "engine/nonlinear/relations_hook.hpp"
#include "engine/parallel/mpi_runtime.hpp"

namespace lunaster::cmd {

namespace {

engine::SolverKind solver_kind(const std::string& methode) {
  if (methode == "MUMPS") return engine::SolverKind::Mumps;
  if (methode == "PETSC") return engine::SolverKind::Petsc;
  if (methode == "UMFPACK") return engine::SolverKind::Umfpack;
  return engine::SolverKind::Cholmod;  // AUTO, CHOLMOD, LDLT, MULT_FRONT: Cholmod, Mumps if not SPD (engine)
}

/// Instants to compute: LIST_INST restricted to [INST_INIT, INST_FIN].
std::vector<double> instants(const Args& inc, engine::NewtonOptions& options) {
  std::vector<double> all;
  auto list = inc.concept_value("LIST_INST");
  if (auto l = std::dynamic_pointer_cast<ListR8>(list)) {
    all = l->values;
  } else if (auto li = std::dynamic_pointer_cast<ListInst>(list)) {
    all = li->instants;
    if (li->subdivide) {
      options.subdivide_levels = li->subd_niveau;
      options.subdivide_parts = li->subd_pas;
    }
  } else {
    throw inc.error("LIST_INST", "a listr8 or list_inst", list ? list->type_name() : "nothing");
  }
  const double t0 = inc.has("INST_INIT") ? inc.real("INST_INIT") : all.front();
  double t1 = inc.has("INST_FIN") ? inc.real("INST_FIN") : all.back();
  if (inc.has("NUME_INST_FIN")) {  // an index in the list as given, its first time 0 (code_aster's numbering)
    const long long last = inc.integer("NUME_INST_FIN");
    if (last >= static_cast<long long>(all.size()))
      throw inc.error("NUME_INST_FIN", "an index of LIST_INST, 1 to " + std::to_string(all.size() - 1) +
                                           " (its first time is index 0)",
                      std::to_string(last));
    t1 = all[static_cast<size_t>(last)];
  }
  std::vector<double> out;
  if (t0 < all.front() - 1e-12) out.push_back(t0);
  for (double t : all)
    if (t >= t0 - 1e-12 && t <= t1 + 1e-12) out.push_back(t);
  if (out.size() < 2)
    throw inc.error("LIST_INST", "at least one instant after INST_INIT", std::to_string(out.size()) + " instant(s)");
  return out;
}

/// On a failed solve, the steps that converged are not lost: they go atomically to
/// <deck>_converged.rmed in the output folder (the deck stops, exit 3, so the
/// concept itself is never assigned) and the error says where they are.
void save_converged_steps(const std::vector<engine::ResultStep>& steps, const engine::Mesh& mesh, Session& session,
                          Error& err) {
  if (steps.size() < 2) return;  // only the initial state
  const auto path = session.output_file(session.deck_path.stem().string() + "_converged.rmed");
  try {
    engine::write_med(path.string(), mesh, {{"RESU", &steps}});
    err.add_hint("the " + std::to_string(steps.size() - 1) + " converged step(s) are saved in " + path.string());
  } catch (const Error& write_error) {
    err.add_hint("the converged steps could not be saved: " + write_error.message());
  }
}

/// COMPORTEMENT / COMP_ELAS: each occurrence's RELATION on its cells (TOUT / GROUP_MA; unknown
/// or empty groups are errors), built from each cell's DEFI_MATERIAU. Null when every relation
/// is ELAS under DEFORMATION='PETIT': the solver keeps the model's linear elasticity (its elastic
/// tangent path). DEFORMATION='GROT_GDEP': the occurrence's cells in large rotations (total
/// Lagrangian; ELAS is then Saint-Venant-Kirchhoff, as code_aster).
std::unique_ptr<engine::CellBehaviours> read_behaviours(const Args& args, const engine::FeModel& model,
                                                        const ChamMater& cham_mater) {
  std::unique_ptr<engine::CellBehaviours> behaviours;
  const std::vector<int> volume = model.volume_cells();
  std::vector<char> is_volume(model.mesh->n_cells(), 0);
  for (int c : volume) is_volume[c] = 1;
  for (const char* kw : {"COMP_ELAS", "COMPORTEMENT"})
    for (const auto& occ : args.declares(kw) ? args.factors(kw) : std::vector<Args>{}) {
      const std::string deformation = occ.text("DEFORMATION");
      if (deformation != "PETIT" && deformation != "GROT_GDEP")
        throw occ.error("DEFORMATION", "'PETIT' (small strains) or 'GROT_GDEP' (large rotations)",
                        "'" + deformation + "'",
                        {"'" + deformation + "' is not built in lunaster; 'PETIT' is right while strains and rotations "
                         "stay small, 'GROT_GDEP' while strains stay small under any rotation"});
      const bool large = deformation == "GROT_GDEP";
      const std::vector<int> cells = select_cells(occ, *model.mesh);
      const std::string relation = occ.text("RELATION");
      std::map<int, std::vector<int>> cells_of_material;  // the occurrence's volume cells per material
      std::vector<int> its_volume;
      for (int c : cells)
        if (is_volume[c] && model.material[c] >= 0) {
          cells_of_material[model.material[c]].push_back(c);
          its_volume.push_back(c);
        }
      if (large) {
        for (int c : its_volume)
          if (model.modelisation[c] == engine::Modelisation::PlaneStress)
            throw occ.error("DEFORMATION", "'PETIT' on the cells of a C_PLAN model",
                            "'GROT_GDEP' on the C_PLAN cell " + model.mesh->cell_names[c],
                            {"large rotations are not built in plane stress (the thickness stretch is unknown to "
                             "them): model the part in D_PLAN or 3D, or keep DEFORMATION = 'PETIT'"});
        // Saint-Venant-Kirchhoff for ELAS: the model's elasticity, on the Green-Lagrange strain.
        if (!behaviours) behaviours = std::make_unique<engine::CellBehaviours>(model);
      }
      if (behaviours)
        behaviours->set_kinematics(its_volume, large ? engine::Kinematics::TotalLagrangian
                                                     : engine::Kinematics::SmallStrain);
      if (relation == "ELAS") {
        if (behaviours)  // an earlier occurrence's plasticity on these cells gives way to elasticity
          for (const auto& [m, its_cells] : cells_of_material)
            behaviours->assign(its_cells, std::make_shared<engine::Elasticity>(model.materials[m]));
        continue;
      }
      engine::PlaneStressIteration local;
      if (occ.has("RESI_INTE_RELA")) local.tolerance = occ.real("RESI_INTE_RELA");
      if (occ.has("ITER_INTE_MAXI")) local.max_iterations = static_cast<int>(occ.integer("ITER_INTE_MAXI"));
      for (const auto& [m, its_cells] : cells_of_material) {
        const Mater& mater = *cham_mater.maters.at(static_cast<size_t>(m));
        const std::string name = "'" + mater.user_name + "'";
        std::shared_ptr<const engine::Behaviour> law;
        if (relation == "VMIS_ISOT_LINE") {
          if (!mater.ecro_line)
            throw occ.error("RELATION", "a material with ECRO_LINE on the cells of 'VMIS_ISOT_LINE'",
                            "'VMIS_ISOT_LINE' on the material " + name + " without ECRO_LINE",
                            {"add ECRO_LINE = _F{ D_SIGM_EPSI = ..., SY = ... } to the DEFI_MATERIAU of " + name});
          law = std::make_shared<engine::VonMises>(mater.elas, *mater.ecro_line, local);
        } else {  // VMIS_ISOT_TRAC
          if (!mater.traction)
            throw occ.error("RELATION", "a material with TRACTION on the cells of 'VMIS_ISOT_TRAC'",
                            "'VMIS_ISOT_TRAC' on the material " + name + " without TRACTION",
                            {"add TRACTION = _F{ SIGM = <the curve> } to the DEFI_MATERIAU of " + name});
          engine::ElasticMaterial elastic = mater.elas;
          elastic.young = mater.traction->young;  // the curve's first point sets E, ELAS gives NU
          law = std::make_shared<engine::VonMises>(elastic, mater.traction->hardening, local);
        }
        if (!behaviours) behaviours = std::make_unique<engine::CellBehaviours>(model);
        behaviours->assign(its_cells, law);
      }
    }
  return behaviours;
}

/// SOLVEUR METHODE='PETSC': the Krylov method and its preconditioner, by code_aster's names.
void read_petsc(const Args& solveur, engine::IterativeSettings& settings) {
  using S = engine::IterativeSettings;
  const std::string algorithm = solveur.text("ALGORITHME"), precond = solveur.text("PRE_COND");
  settings.krylov = algorithm == "CG" ? S::Krylov::CG : algorithm == "GMRES" ? S::Krylov::GMRES : S::Krylov::FGMRES;
  settings.preconditioner = precond == "GAMG"     ? S::Preconditioner::Gamg
                            : precond == "ML"     ? S::Preconditioner::Ml
                            : precond == "BOOMER" ? S::Preconditioner::Boomer
                            : precond == "JACOBI" ? S::Preconditioner::Jacobi
                            : precond == "SOR"    ? S::Preconditioner::Sor
                            : precond == "SANS"   ? S::Preconditioner::None
                                                  : S::Preconditioner::LdltSp;
  settings.krylov_label = algorithm;  // the log and the messages name them as the deck does
  settings.preconditioner_label = precond;
  settings.relative_residual = solveur.real("RESI_RELA");
  settings.max_iterations = static_cast<int>(solveur.integer("NMAX_ITER"));
  // code_aster's LDLT_SP: 100 iterations when NMAX_ITER is 0, REAC_PRECOND, PCENT_PIVOT and
  // LOW_RANK_SEUIL (block low rank when not zero).
  if (settings.preconditioner == S::Preconditioner::LdltSp) {
    if (settings.max_iterations == 0) settings.max_iterations = 100;
    settings.reac_precond = static_cast<int>(solveur.integer("REAC_PRECOND"));
    settings.workspace_relaxation = static_cast<int>(solveur.integer("PCENT_PIVOT"));
    const double threshold = solveur.real("LOW_RANK_SEUIL");
    settings.low_rank = {threshold != 0.0, threshold};
  }
}

/// SOLVEUR NPREC and STOP_SINGULIER (the factorising methods), RENUM (the fill-reducing
/// ordering, by code_aster's names for each METHODE) and, for MUMPS, GESTION_MEMOIRE,
/// MATR_DISTRIBUEE, PCENT_PIVOT, RESI_RELA, PRETRAITEMENTS, POSTTRAITEMENTS, TYPE_RESOL,
/// ACCELERATION, LOW_RANK_SEUIL, MIXER_PRECISION and FILTRAGE_MATRICE. `say` takes the lines
/// the log gets about them.
void read_direct_solver(const Args& solveur, engine::NewtonOptions& options,
                        const std::function<void(const std::string&)>& say) {
  using O = engine::FactorOrdering;
  const std::string methode = solveur.text("METHODE");
  if (solveur.has("NPREC")) {  // the methods that factorise (catalogue default 8, code_aster's)
    options.factor.singularity.digits = static_cast<int>(solveur.integer("NPREC"));
    options.factor.singularity.stop = solveur.text("STOP_SINGULIER") == "OUI";
  }
  if (methode == "MULT_FRONT" || methode == "LDLT") {
    if (!solveur.has("RENUM")) return;  // lunaster's choice
    const std::string renum = solveur.text("RENUM");
    options.factor.ordering = renum == "METIS"  ? O::Metis
                       : renum == "RCMK" ? O::Rcm
                       : renum == "SANS" ? O::Natural
                                         : O::Amd;  // MD, MDA
    return;
  }
  if (methode != "MUMPS") return;
  const std::string memory = solveur.text("GESTION_MEMOIRE");
  options.factor.memory = memory == "IN_CORE"       ? engine::FactorMemory::InCore
                   : memory == "OUT_OF_CORE" ? engine::FactorMemory::OutOfCore
                                             : engine::FactorMemory::Auto;
  options.share_model = solveur.text("MATR_DISTRIBUEE") == "OUI";
  if (solveur.has("PCENT_PIVOT"))
    options.factor.workspace_relaxation = static_cast<int>(solveur.integer("PCENT_PIVOT"));
  if (solveur.has("RESI_RELA")) options.direct_solve_tolerance = solveur.real("RESI_RELA");
  using R = engine::NewtonOptions::Refinement;
  const std::string post = solveur.text("POSTTRAITEMENTS");
  options.refinement = post == "SANS" ? R::None : post == "MINI" ? R::Two : post == "FORCE" ? R::Force : R::Auto;
  options.factor.preprocessing = solveur.text("PRETRAITEMENTS") == "AUTO";
  // ACCELERATION as code_aster runs it on a public MUMPS (Debian's 5.5): AUTO and FR in full
  // rank, LR in block low rank at LOW_RANK_SEUIL; FR+, FR++, LR+ and LR++ add settings of the
  // MUMPS consortium's version, so code_aster falls back to FR or LR and says so, as here.
  const std::string acceleration = solveur.text("ACCELERATION");
  const bool low_rank = acceleration.rfind("LR", 0) == 0;
  const double threshold = solveur.real("LOW_RANK_SEUIL");
  if (!low_rank && threshold != 0.0)
    throw solveur.error("LOW_RANK_SEUIL", "0 (its default) with ACCELERATION = '" + acceleration + "' (full rank)",
                        number_text(threshold),
                        {"LOW_RANK_SEUIL is the threshold of the block low-rank factorisation: give ACCELERATION "
                         "= 'LR' beside it, or remove it"});
  options.factor.low_rank = {low_rank, threshold};
  options.single_precision = solveur.text("MIXER_PRECISION") == "OUI";
  options.factor.filter = solveur.real("FILTRAGE_MATRICE");
  if (acceleration.size() > 2 && acceleration != "AUTO")
    say("  SOLVEUR ACCELERATION = '" + acceleration + "': its extra settings are the MUMPS consortium's, not in "
        "Debian's MUMPS; factorising with '" + acceleration.substr(0, 2) + "', as code_aster does with a public MUMPS");
  const std::string type = solveur.text("TYPE_RESOL");
  options.factor.by_kind = type == "AUTO";
  options.factor.factorisation = type == "NONSYM"   ? engine::MatrixKind::General
                          : type == "SYMDEF" ? engine::MatrixKind::SymmetricPositiveDefinite
                                             : engine::MatrixKind::SymmetricIndefinite;
  const std::string renum = solveur.text("RENUM");
  options.factor.ordering = renum == "METIS" ? O::Metis
                     : renum == "AMD" ? O::Amd
                     : renum == "AMF" ? O::Amf
                     : renum == "QAMD" ? O::Qamd
                     : renum == "PORD" ? O::Pord
                                       : O::Auto;
}

/// NEWTON: which matrix Newton factorises, and how often (engine's matrix policy).
void read_newton(const Args& newton, bool has_contact, engine::NewtonOptions& options,
                 const std::function<void(const std::string&)>& say) {
  options.reac_iter = static_cast<int>(newton.integer("REAC_ITER"));
  // REAC_INCR: the driver forms the matrix at the first iteration of every increment (and
  // factorises it unless it equals the last one factorised), which is code_aster's REAC_INCR = 1.
  if (newton.has("REAC_INCR")) {
    const long long every = newton.integer("REAC_INCR");
    if (every != 1)
      throw newton.error("REAC_INCR", "1 (the matrix formed anew at the first iteration of every increment, as "
                                      "lunaster's driver does)",
                         std::to_string(every),
                         {every == 0 ? "0 keeps the matrix of the previous increment, which lunaster does not offer: "
                                       "remove REAC_INCR or give 1"
                                     : "keeping the matrix for several increments is not offered: remove REAC_INCR or "
                                       "give 1"});
    say("  NEWTON REAC_INCR = 1: the matrix is formed anew at the first iteration of every increment");
  }
  options.elastic_matrix = newton.text("MATRICE") == "ELASTIQUE";
  // code_aster keeps the contact terms in the matrix whatever MATRICE says (without them the
  // multiplier equations are empty, or the penalty stiffness is missing), and with an elastic
  // material the elastic stiffness plus the contact terms is the tangent: that matrix it is.
  if (options.elastic_matrix && has_contact) {
    options.elastic_matrix = false;
    say("  NEWTON MATRICE = 'ELASTIQUE' with contact: the matrix is the elastic stiffness plus the contact terms, "
        "as code_aster's (with linear elasticity, the tangent)");
  }
}

}  // namespace

namespace {

/// AXIS: the measure r dl vanishes on the axis, so a nodal rule gives a slave node at r = 0 no
/// weight and its multiplier no equation. INTEGRATION='AUTO' (nodal on SEG2/SEG3) becomes Gauss
/// with 3 points on an AXIS model (exact for the r-weighted products of SEG2 and SEG3 shapes);
/// an explicit 'NOEUD' with a slave node on the axis is refused.
void axis_integration(engine::ContactDefinition& definition, const engine::Mesh& mesh, Session& session) {
  if (definition.method != engine::ContactMethod::Continuous && definition.method != engine::ContactMethod::ContinuousPenalty)
    return;
  for (auto& zone : definition.zones) {
    if (zone.integration == engine::IntegrationScheme::Auto) {
      zone.integration = engine::IntegrationScheme::Gauss;
      zone.integration_order = 3;
      session.log().info("  contact zone " + zone.slave_group + "/" + zone.master_group +
                         ": INTEGRATION='AUTO' on an AXIS model is Gauss with ORDRE_INT=3 (a nodal rule would give "
                         "slave nodes on the axis, where r dl vanishes, no weight)");
    } else if (zone.integration == engine::IntegrationScheme::Nodes) {
      double scale = 0.0;  // the largest radius of the slave surface: "on the axis" is relative to it
      for (int c : zone.slave_cells)
        for (int a = 0; a < mesh.cell_n_nodes(c); ++a) scale = std::max(scale, mesh.node(mesh.cell(c)[a])[0]);
      for (int c : zone.slave_cells)
        for (int a = 0; a < mesh.cell_n_nodes(c); ++a)
          if (mesh.node(mesh.cell(c)[a])[0] <= 1e-12 * scale) {
            const std::string node = mesh.node_names[mesh.cell(c)[a]];
            throw DeckError("contact zone " + zone.slave_group + "/" + zone.master_group + ": INTEGRATION='NOEUD' on an AXIS "
                            "model gives slave node " + node + ", on the axis (r = 0), no weight: its pressure would have no equation",
                            {"use INTEGRATION='GAUSS' (or 'AUTO', which is Gauss on AXIS models), 'SIMPSON' or 'NCOTES'"});
          }
    }
  }
}

/// Imposed displacements in the whole mesh's node numbers (one-term relations on a mesh in
/// parts) on the nodes `part` holds, in its numbers; the others are other ranks' (a ghost's
/// condition is its owner's in the solve).
std::vector<engine::DirichletValue> held_by_part(std::vector<engine::DirichletValue> whole,
                                                 const engine::MeshPart& part) {
  const std::unordered_map<int, int> local = engine::local_nodes(part);
  std::vector<engine::DirichletValue> out;
  for (engine::DirichletValue d : whole) {
    const auto it = local.find(d.node);
    if (it != local.end()) d.node = it->second, out.push_back(d);
  }
  return out;
}

/// On a mesh in parts: the relations' nodes (the whole mesh's numbers, AFFE_CHAR_MECA) join
/// `numbered` as ghosts where it lacks them, with the nodes around them in `part` when the
/// relations are solved for one unknown each (their whole stiffness columns), and their terms take
/// numbered's numbers. Collective (every rank has every relation).
void number_relations(std::vector<engine::LinearRelation>& relations, engine::MeshPart& numbered,
                      const engine::MeshPart& part, bool eliminate) {
  std::vector<int> nodes;
  for (const auto& r : relations)
    for (const auto& t : r.terms) nodes.push_back(t.node);
  engine::add_ghost_nodes(numbered, nodes, eliminate ? &part : nullptr);
  const std::unordered_map<int, int> local = engine::local_nodes(numbered);
  for (auto& r : relations)
    for (auto& t : r.terms) t.node = local.at(t.node);
}

/// EXCIT's loads, each with its multiplier (FONC_MULT, a function of INST alone), and the
/// contact definition a load carries (at most one), with the keyword path that gave it.
struct ExcitLoads {
  engine::MechanicalLoads loads;
  const engine::ContactDefinition* contact = nullptr;
  std::string contact_source;
};

ExcitLoads read_excit(const Args& args, const engine::FeModel& model, const std::shared_ptr<Modele>& modele) {
  ExcitLoads out;
  for (const auto& excit : args.factors("EXCIT")) {
    auto charge = excit.concept_as<CharMeca>("CHARGE");
    if (charge->modele != modele)
      throw excit.error("CHARGE", "a load defined on MODELE", "'" + charge->user_name + "' defined on another model");
    const int index = static_cast<int>(out.loads.multipliers.size());
    if (excit.has("FONC_MULT")) {
      auto f = excit.concept_as<RealFunction>("FONC_MULT");
      if (std::dynamic_pointer_cast<Formule>(f) && f->parameters() != std::vector<std::string>{"INST"})
        throw excit.error("FONC_MULT", "a function of INST alone",
                          "a FORMULE of " + std::to_string(f->parameters().size()) + " parameter(s), the first '" +
                              f->parameters().front() + "'",
                          {"write the multiplier as FORMULE(VALE=..., NOM_PARA='INST')"});
      out.loads.multipliers.push_back([f](double t) { return f->evaluate({t}); });
    } else {
      out.loads.multipliers.push_back([](double) { return 1.0; });
    }
    for (auto d : charge->dirichlet) { d.load = index; out.loads.dirichlet.push_back(d); }
    for (auto p : charge->pressures) { p.load = index; out.loads.pressures.push_back(p); }
    for (auto f : charge->forces) { f.load = index; out.loads.forces.push_back(f); }
    for (auto d : charge->distributed) {
      // PESANTEUR weighs each cell with its material's RHO: said here, where the materials meet the
      // load (on a mesh in parts the ranks agree, the cell being on one part only).
      auto weighed = [&] {
        for (int c : d.cells) {
          const int mat = model.material.at(c);
          if (mat < 0 || std::isnan(model.materials[mat].density))
            throw excit.error("CHARGE", "RHO in DEFI_MATERIAU ELAS for every cell PESANTEUR weighs",
                              "cell " + model.mesh->cell_names[c] + ", whose material (CHAM_MATER) has " +
                                  (mat < 0 ? "none" : "no RHO"),
                              {"add RHO = ... to the material's ELAS"});
        }
      };
      if (d.per_mass && modele->in_parts()) agreed(weighed);
      else if (d.per_mass) weighed();
      d.load = index;
      out.loads.distributed.push_back(d);
    }
    for (auto r : charge->relations) {
      r.load = index;
      r.label += charge->user_name.empty() ? " of " + excit.path("CHARGE") : " of CHARGE '" + charge->user_name + "'";
      out.loads.relations.push_back(r);
    }
    if (charge->has_contact) {
      if (out.contact) throw excit.error("CHARGE", "a single contact definition", "a second one in '" + charge->user_name + "'");
      out.contact = &charge->contact;
      out.contact_source = excit.path("CHARGE");
    }
  }
  return out;
}

ConceptPtr nonlinear_analysis(const Args& args, Session& session, bool meca_non_line) {
  const auto start = std::chrono::steady_clock::now();
  auto result = std::make_shared<EvolNoli>();
  result->modele = args.concept_as<Modele>("MODELE");
  result->cham_mater = args.concept_as<ChamMater>("CHAM_MATER");
  const engine::FeModel model = build_fe_model(*result->modele, *result->cham_mater, args, "CHAM_MATER");
  const std::unique_ptr<engine::CellBehaviours> behaviours = read_behaviours(args, model, *result->cham_mater);

  ExcitLoads excit_loads = read_excit(args, model, result->modele);
  engine::MechanicalLoads& loads = excit_loads.loads;
  const engine::ContactDefinition*& contact = excit_loads.contact;
  const std::string& contact_source = excit_loads.contact_source;
  std::shared_ptr<CharContact> defi_contact;
  if (meca_non_line ? !args.factors("CONTACT").empty() : args.has("CONTACT")) {
    if (contact) throw args.error("CONTACT", "a single contact definition", "one here and one in " + contact_source);
    defi_contact = meca_non_line ? args.factor("CONTACT").concept_as<CharContact>("DEFINITION")
                                 : args.concept_as<CharContact>("CONTACT");
    if (defi_contact->modele != result->modele)
      throw args.error("CONTACT", "a contact definition on MODELE", "'" + defi_contact->user_name + "' defined on another model");
    contact = &defi_contact->contact;
  }

  engine::NewtonOptions options;
  const Args conv = args.factor("CONVERGENCE");
  // As code_aster: RESI_GLOB_RELA = 1e-6 unless only RESI_GLOB_MAXI is given.
  if (conv.has("RESI_GLOB_MAXI")) options.resi_glob_maxi = conv.real("RESI_GLOB_MAXI");
  options.resi_glob_rela = conv.has("RESI_GLOB_RELA") ? conv.real("RESI_GLOB_RELA")
                           : conv.has("RESI_GLOB_MAXI") ? -1.0
                                                        : 1e-6;
  options.iter_glob_maxi = static_cast<int>(conv.integer("ITER_GLOB_MAXI"));
  if (conv.text("ARRET") != "OUI")
    throw conv.error("ARRET", "'OUI' (a step that does not converge stops the run)", "'" + conv.text("ARRET") + "'",
                     {"ARRET = 'NON' would go on from a step's last iterate as if it had converged, a state out of "
                      "equilibrium passed to the next steps and the results: lunaster does not offer it (raise "
                      "ITER_GLOB_MAXI, or let DEFI_LIST_INST split the step)"});
  options.solver = solver_kind(args.factor("SOLVEUR").text("METHODE"));
  options.auto_solver = args.factor("SOLVEUR").text("METHODE") == "AUTO";
  if (options.solver == engine::SolverKind::Petsc) read_petsc(args.factor("SOLVEUR"), options.iterative);
  read_direct_solver(args.factor("SOLVEUR"), options,
                     [&session](const std::string& line) { session.log().info(line); });
  if (session.solveur_override == "MUMPS") {
    // --solveur=MUMPS on the command line: MUMPS whatever the deck asked for, the model shared
    // among the ranks (each assembles its own nodes' stiffness, MUMPS takes the matrix given
    // distributed), as METHODE='MUMPS' with MATR_DISTRIBUEE='OUI' would.
    const std::string asked = args.factor("SOLVEUR").text("METHODE");
    options.solver = engine::SolverKind::Mumps, options.auto_solver = false, options.share_model = true;
    session.log().info("  SOLVEUR METHODE = 'MUMPS', MATR_DISTRIBUEE = 'OUI' from the command line (--solveur=MUMPS)" +
                       (asked == "MUMPS" ? std::string() : ", in place of the deck's METHODE = '" + asked + "'"));
  }
  const std::shared_ptr<engine::MeshPart> part = result->modele->maillage->part;
  if (part && options.solver == engine::SolverKind::Mumps && !options.share_model)
    // Each rank holds its part only: no rank can assemble the whole system MATR_DISTRIBUEE='NON' asks for.
    throw args.factor("SOLVEUR").error("MATR_DISTRIBUEE", "'OUI' on a mesh in parts (each rank holds its part, the "
                                                          "matrix is given in parts)",
                                       "'NON'", {"remove MATR_DISTRIBUEE, or read the mesh without PARTITIONNEUR"});
  if (part && options.auto_solver) {
    // On a mesh in parts the matrix is in parts too: MUMPS takes it as given (code_aster's
    // default METHODE), where AUTO would choose among solvers of one process.
    options.solver = engine::SolverKind::Mumps, options.auto_solver = false;
    session.log().info("  SOLVEUR METHODE = 'AUTO' on a mesh in parts: MUMPS, the matrix given in parts");
  }
  options.krylov_history = args.integer("INFO") >= 2;
  read_newton(args.factor("NEWTON"), contact != nullptr, options,
              [&session](const std::string& line) { session.log().info(line); });
  const std::vector<double> times = instants(args.factor("INCREMENT"), options);

  const Args solveur = args.factor("SOLVEUR");
  const bool eliminate = solveur.has("ELIM_LAGR") && solveur.text("ELIM_LAGR") == "OUI";
  // LIAISON_DDL, LIAISON_UNIF: a relation of one term is an imposed displacement; the others get
  // a multiplier each (or are solved for one unknown each: ELIM_LAGR='OUI'), in the system beside
  // the contact terms. On a mesh in parts the relations are in the whole mesh's node numbers.
  {
    std::vector<engine::DirichletValue> one_term;
    loads.relations = engine::split_dirichlet(std::move(loads.relations), one_term);
    if (part) one_term = held_by_part(std::move(one_term), *part);
    loads.dirichlet.insert(loads.dirichlet.end(), one_term.begin(), one_term.end());
  }

  // On a mesh in parts the hook works on the contact surfaces whole on every rank and on the
  // relations' nodes, ghosts of the part where it lacks them (they outlive it: declared first).
  ContactSurfaces surfaces;
  std::shared_ptr<engine::MeshPart> numbered;
  std::unique_ptr<engine::ContactHook> hook;
  const bool discrete = contact && (contact->method == engine::ContactMethod::DiscreteLagrange ||
                                    contact->method == engine::ContactMethod::DiscretePenalty);
  if (contact) surfaces = contact_surfaces(*contact, *result->modele, discrete && eliminate);
  if (part && (contact || !loads.relations.empty())) {
    agree_over_ranks(nullptr);  // before the gathering: no rank has stopped (commands/parts.hpp)
    numbered = surfaces.part ? std::shared_ptr<engine::MeshPart>(surfaces.part, &surfaces.part->part)
                             : std::make_shared<engine::MeshPart>(engine::nodes_only(*part));
    if (!loads.relations.empty()) number_relations(loads.relations, *numbered, *part, eliminate);
  }
  if (contact) {
    engine::ContactDefinition& definition = surfaces.definition;
    // The contact measures follow the model: r dl per radian on an AXIS model (MODL_AXIS, when
    // given, was checked against the model by AFFE_CHAR_MECA).
    definition.axisymmetric = model.axisymmetric();
    if (definition.axisymmetric) axis_integration(definition, *surfaces.mesh, session);
    for (const auto& m : model.materials) definition.modulus = std::max(definition.modulus, m.young);
    if (part) definition.modulus = engine::parallel::max_over_ranks(definition.modulus);
    hook = engine::make_contact_hook(definition, *surfaces.mesh, model.dim);
  }
  // Solved for one unknown each, the relations discrete contact puts on QUAD8 faces (mid-side
  // ties) join the deck's, as code_aster's kinematic relations do; with multipliers they stay
  // the contact's own, but for those between imposed unknowns only: no multiplier holds them,
  // and the deck's relations' check of their imposed values is theirs too. On a mesh in parts
  // the imposed unknowns of the hook's nodes are their owners'.
  std::set<std::pair<int, int>> imposed;
  if (numbered && (!loads.relations.empty() || discrete)) {
    const engine::NodeHalo node_halo(*numbered);
    for (const auto& d : engine::owners_dirichlet(*numbered, node_halo, loads.dirichlet))
      imposed.insert({d.node, d.component});
  } else {
    for (const auto& d : loads.dirichlet) imposed.insert({d.node, d.component});
  }
  std::vector<engine::LinearRelation> relations = loads.relations;
  size_t n_ties = 0;
  if (hook) {
    std::vector<engine::LinearRelation> ties = hook->take_relations(
        [&](const engine::LinearRelation& r) { return eliminate || engine::imposed_only(r, imposed); });
    n_ties = ties.size();
    relations.insert(relations.end(), ties.begin(), ties.end());
  }
  if (eliminate && relations.empty())
    session.log().info("  SOLVEUR ELIM_LAGR = 'OUI': no linear relation to solve for one of its unknowns (DDL_IMPO "
                       "conditions are eliminated whatever ELIM_LAGR says; contact treats its multipliers its own "
                       "way)");
  if (!relations.empty()) {
    if (eliminate && contact && contact->method == engine::ContactMethod::MortarLagrange)
      throw solveur.error("ELIM_LAGR", "'NON' with mortar contact (ALGO_CONT = 'LAGRANGIEN'), which eliminates "
                                       "unknowns itself",
                          "'OUI' and " + std::to_string(relations.size()) + " linear relation(s)");
    const std::string ties_said =
        n_ties ? "(" + std::to_string(n_ties) + " of them discrete contact's QUAD8 mid-side ties) " : "";
    // A relation between imposed unknowns only gets no multiplier: the imposed values are
    // checked against it at each instant (relations_hook.hpp).
    const auto n_checked = std::count_if(relations.begin(), relations.end(), [&](const engine::LinearRelation& r) {
      return engine::imposed_only(r, imposed);
    });
    const std::string checked_said =
        !eliminate && n_checked
            ? ", except " + std::to_string(n_checked) + " between imposed unknowns only, which need none (the "
                  "imposed values are checked against them)"
            : "";
    session.log().info("  " + std::to_string(relations.size()) + " linear relation(s) " + ties_said +
                       (eliminate ? "each solved for one of its unknowns (SOLVEUR ELIM_LAGR = 'OUI'): no multipliers"
                                  : "with a Lagrange multiplier each (SOLVEUR ELIM_LAGR = 'OUI' would solve each "
                                    "for one of its unknowns instead)") +
                       checked_said);
    hook = engine::make_relations_hook(std::move(relations), loads.multipliers, std::move(hook), eliminate);
    if (options.elastic_matrix) {
      // As contact terms, the relations' belong in the matrix (code_aster keeps them there whatever
      // MATRICE says); with elasticity it is the same matrix at every iteration, factorised once.
      options.elastic_matrix = false;
      session.log().info("  NEWTON MATRICE = 'ELASTIQUE' with linear relations: the matrix keeps their terms, and "
                         "is factorised once while it does not change");
    }
  }
  result->loads = loads;
  engine::StaticSolver solver(model, loads, options, hook.get(), session.log());
  if (part) {
    // Every rank has read its part of the deck's model and loads before the first collective
    // call of the solve: one that failed stops all alike (commands/parts.hpp).
    agree_over_ranks(nullptr);
    solver.set_part(part.get(), numbered.get());
  }
  if (behaviours) solver.set_behaviours(behaviours.get());
  {
    Session::Timer timer(session, "solve");
    try {
      result->steps = solver.run(times);
    } catch (Error& err) {
      // A failed solve, or a choice of the deck the system turned out not to allow (TYPE_RESOL).
      if (!dynamic_cast<SolveError*>(&err) && !dynamic_cast<DeckError*>(&err)) throw;
      say_in_keywords(err);
      if (dynamic_cast<engine::ConvergenceError*>(&err) && options.reac_iter != 1)
        err.add_hint("NEWTON: REAC_ITER = " + std::to_string(options.reac_iter) +
                     " reuses the factorisation between iterations (a modified Newton, slower to converge); "
                     "REAC_ITER = 1 refactorises at every iteration");
      if (!part) {
        save_converged_steps(solver.converged_steps(), *model.mesh, session, err);
      } else if (solver.converged_steps().size() > 1) {
        // The ranks fail together (the solve's decisions are theirs alike): the steps are gathered
        // to rank 0 on the whole mesh it read, which writes the serial run's file.
        const std::vector<engine::ResultStep> whole = gather_steps_to_root(*part, solver.converged_steps());
        if (engine::parallel::rank() == 0)
          save_converged_steps(whole, *result->modele->maillage->whole, session, err);
      }
      throw;
    }
  }
  result->large_rotations = behaviours && !behaviours->all_linear() &&
                            [&] {
                              for (int c : model.volume_cells())
                                if (behaviours->kinematics(c) != engine::Kinematics::SmallStrain) return true;
                              return false;
                            }();
  result->stats = solver.stats();
  result->cell_rank = solver.cell_ranks();
  report_times(session, result->stats, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return result;
}

}  // namespace

ConceptPtr stat_non_line(const Args& args, Session& session) { return nonlinear_analysis(args, session, false); }
ConceptPtr meca_non_line(const Args& args, Session& session) { return nonlinear_analysis(args, session, true); }

}  // namespace lunaster::cmd
