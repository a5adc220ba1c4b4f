// CALC_CHAMP: stresses (SIGM_ELNO, SIGM_NOEU, SIEF_ELNO, SIEF_NOEU), equivalent stresses (SIEQ_*) and nodal
// forces (FORC_NODA, REAC_NODA) from DEPL.
#include <algorithm>
#include <memory>

#include "commands/commands.hpp"
#include "commands/concepts.hpp"
#include "commands/parts.hpp"
#include "engine/assembly/global_dofs.hpp"
#include "engine/assembly/halo.hpp"
#include "engine/assembly/stress.hpp"
#include "engine/nonlinear/nodal_forces.hpp"
#include "engine/parallel/mpi_runtime.hpp"

namespace lunaster::cmd {

namespace {

/// Rebuilds the displacement vector of a stored step from its DEPL field.
engine::Vector displacement_vector(const engine::DofMap& dofs, const engine::NodalField& depl) {
  engine::Vector u = engine::Vector::Zero(dofs.n_dofs());
  const int ncmp = dofs.dim();
  for (int node = 0; node < depl.n_nodes; ++node)
    for (int c = 0; c < ncmp; ++c) {
      const int eq = dofs.dof(node, c);
      if (eq >= 0 && depl.has(node, c)) u[eq] = depl.value(node, c);
    }
  return u;
}

std::vector<size_t> calc_steps(const Args& args, const EvolNoli& resu) {
  std::vector<size_t> out;
  for (size_t i = 0; i < resu.steps.size(); ++i) {
    const auto& s = resu.steps[i];
    bool take = true;
    if (args.has("NUME_ORDRE")) {
      const auto wanted = args.integers("NUME_ORDRE");
      take = std::find(wanted.begin(), wanted.end(), s.nume_ordre) != wanted.end();
    } else if (args.has("INST")) {
      take = false;
      for (double t : args.reals("INST")) take |= std::abs(t - s.inst) <= 1e-6 * std::max(1.0, std::abs(t));
    }
    if (take) out.push_back(i);
  }
  if (out.empty()) throw args.error(args.has("INST") ? "INST" : "NUME_ORDRE", "a stored step of the result", "none matched");
  return out;
}

}  // namespace

ConceptPtr calc_champ(const Args& args, Session& session) {
  Session::Timer timer(session, "post");
  auto resu = args.concept_as<EvolNoli>("RESULTAT");
  std::vector<std::string> wanted;
  if (args.has("CONTRAINTE")) wanted = args.texts("CONTRAINTE");
  for (const char* kw : {"CRITERES", "FORCE"})
    if (args.has(kw))
      for (const auto& c : args.texts(kw)) wanted.push_back(c);
  auto want = [&](const char* name) { return std::find(wanted.begin(), wanted.end(), name) != wanted.end(); };
  if (resu->large_rotations)
    for (const char* name : {"SIGM_ELNO", "SIGM_NOEU", "SIEQ_ELNO", "SIEQ_NOEU", "SIEF_ELNO", "SIEF_NOEU"})
      if (want(name))
        throw args.error(std::string(name).rfind("SIEQ", 0) == 0 ? "CRITERES" : "CONTRAINTE",
                         "a result in small strains (DEFORMATION = 'PETIT')",
                         "'" + std::string(name) + "' on a result with DEFORMATION = 'GROT_GDEP'",
                         {"CALC_CHAMP computes these stresses from the displacement in small strains, wrong under "
                          "large rotations; the result's SIEF_ELGA holds the Cauchy stresses (CREA_CHAMP "
                          "OPERATION = 'EXTR' reads them)"});
  const engine::FeModel model = build_fe_model(*resu->modele, *resu->cham_mater, args, "RESULTAT");
  const engine::DofMap dofs(*model.mesh, model.volume_cells(), model.dim);
  const std::vector<size_t> chosen = calc_steps(args, *resu);
  // On a mesh in parts each rank computes its part: its own cells' forces summed into the owners
  // and copied to the ghosts through the halo of its unknowns, every cell's stresses (a part
  // holds all the nodes of its cells), nodal means from the owners.
  const engine::MeshPart* part = resu->modele->maillage->part.get();
  std::unique_ptr<engine::Halo> equations;
  if (part) {
    agree_over_ranks(nullptr);
    equations = std::make_unique<engine::Halo>(
        engine::equation_halo(*part, dofs, engine::number_across_ranks(*part, dofs, engine::NodeHalo(*part))));
  }
  auto to_noeu = [&](const engine::ElnoField& elno) {
    return part ? engine::elno_to_noeu(*part, elno) : engine::elno_to_noeu(*model.mesh, elno);
  };
  // A model shared among MPI ranks by STAT_NON_LINE: each rank computes the cells it held and
  // the ranks sum their parts, so every rank has the whole fields (IMPR_RESU, TEST_RESU).
  const std::vector<int>* cell_rank =
      !part && resu->cell_rank.size() == static_cast<size_t>(model.mesh->n_cells()) ? &resu->cell_rank : nullptr;
  if (cell_rank) {
    const long mine = std::count(cell_rank->begin(), cell_rank->end(), engine::parallel::rank());
    const long all = static_cast<long>(cell_rank->size()) - std::count(cell_rank->begin(), cell_rank->end(), -1);
    session.log().info("CALC_CHAMP: each rank computes the cells it held in STAT_NON_LINE (this rank " +
                       std::to_string(mine) + " of " + std::to_string(all) + ")");
  }
  for (size_t i : chosen) {
    auto& step = resu->steps[i];
    const engine::Vector u = displacement_vector(dofs, step.nodal.at("DEPL"));
    if (want("FORC_NODA"))
      step.nodal["FORC_NODA"] = part ? engine::internal_nodal_forces(model, dofs, u, *part, *equations)
                                     : engine::internal_nodal_forces(model, dofs, u, cell_rank);
    if (want("REAC_NODA")) {
      try {
        step.nodal["REAC_NODA"] =
            part ? engine::reaction_forces(model, dofs, u, resu->loads, step.inst, *part, *equations)
                 : engine::reaction_forces(model, dofs, u, resu->loads, step.inst, cell_rank);
      } catch (const DeckError& err) {  // a FONC_MULT outside its range at this instant
        throw args.error("FORCE", "loads of RESULTAT defined at instant " + std::to_string(step.inst), err.message());
      }
    }
    const bool stresses = want("SIGM_ELNO") || want("SIGM_NOEU") || want("SIEQ_ELNO") || want("SIEQ_NOEU") ||
                          want("SIEF_ELNO") || want("SIEF_NOEU");
    if (!stresses) continue;
    engine::ElnoField sigm = engine::compute_sigm_elno(model, dofs, u, cell_rank);
    if (want("SIGM_NOEU")) step.nodal["SIGM_NOEU"] = to_noeu(sigm);
    // The stresses of the behaviour (SIEF): with linear elasticity, the stresses of the displacement.
    if (want("SIEF_ELNO") || want("SIEF_NOEU")) {
      if (want("SIEF_NOEU")) step.nodal["SIEF_NOEU"] = to_noeu(sigm);
      step.elno["SIEF_ELNO"] = sigm;
    }
    if (want("SIEQ_ELNO") || want("SIEQ_NOEU")) {
      engine::ElnoField sieq = engine::compute_sieq_elno(sigm);
      if (want("SIEQ_NOEU")) step.nodal["SIEQ_NOEU"] = to_noeu(sieq);
      step.elno["SIEQ_ELNO"] = std::move(sieq);
    }
    step.elno["SIGM_ELNO"] = std::move(sigm);  // *_NOEU needs *_ELNO: code_aster computes it too
  }
  return resu;
}

}  // namespace lunaster::cmd
