#pragma once
/// Keyword -> engine mapping shared by AFFE_CHAR_MECA/CONTACT (seed syntax)
/// and DEFI_CONTACT (current syntax).
#include "catalog/args.hpp"
#include "commands/concepts.hpp"
#include "commands/session.hpp"
#include <memory>

#include "engine/assembly/mesh_part.hpp"
#include "engine/contact/contact_definition.hpp"
#include "engine/mesh/mesh.hpp"

namespace lunaster::cmd {

/// Reads one contact zone (slave/master groups, integration, coefficients, CONTACT_INIT).
engine::ContactZone read_contact_zone(const catalog::Args& zone, const engine::Mesh& mesh, int model_dim,
                                      engine::ContactMethod method);
/// Reads the loop settings (ALGO_RESO_*, REAC_GEOM, ITER_*_MAXI, RESI_GEOM) present in `args`.
void read_contact_loops(const catalog::Args& args, engine::ContactDefinition& def);
/// Logs the compatibility warnings: slave/master cell pairs the integration cannot handle and,
/// for the continuous method, rules with fewer points than a slave cell has LAGS_C unknowns.
void warn_incompatible_pairs(const engine::ContactDefinition& def, const engine::Mesh& mesh, Session& session);
/// Warns when two distinct slave nodes of `zone` (cells of `mesh`) share one position (an
/// unmerged mesh: contact sees two points there), naming the group, the file and the nodes.
void warn_coincident_slave_nodes(const catalog::Args& zone_args, const engine::ContactZone& zone,
                                 const engine::Mesh& mesh, const Maillage& ma, Session& session);

/// A contact definition's surfaces as a serial run sees them: the model's mesh and the
/// definition itself, or, on a mesh in parts (docs/distributed-model.md, step 5), the surfaces
/// whole on every rank (engine::with_whole_surfaces) and the definition's cells renumbered on
/// them. Collective on a mesh in parts: every rank calls it; the ranks agree first on what the
/// command has read (commands/parts.hpp), so none gathers while another has stopped.
/// With `tie_columns` (discrete contact's QUAD8 ties solved for one unknown each, ELIM_LAGR),
/// every surface also brings the volume cells around its nodes: the ties' whole stiffness columns.
struct ContactSurfaces {
  std::shared_ptr<engine::SurfacePart> part;  ///< null on a whole mesh
  engine::ContactDefinition definition;
  const engine::Mesh* mesh = nullptr;
};
ContactSurfaces contact_surfaces(const engine::ContactDefinition& def, const Modele& mo, bool tie_columns = false);
/// The warnings a contact definition gets where the deck names it, on its surfaces as a serial
/// run sees them: coincident slave nodes per zone (`zone_args[z]` the zone's occurrence) and, with
/// `pairs`, the incompatible slave/master pairs.
void warn_contact_surfaces(const std::vector<catalog::Args>& zone_args, const ContactSurfaces& surfaces,
                           const Maillage& ma, Session& session, bool pairs);

}  // namespace lunaster::cmd
