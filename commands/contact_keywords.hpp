#pragma once
/// Keyword -> engine mapping shared by AFFE_CHAR_MECA/CONTACT (seed syntax)
/// and DEFI_CONTACT (current syntax).
#include "catalog/args.hpp"
#include "commands/concepts.hpp"
#include "commands/session.hpp"
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
/// Warns when two distinct slave nodes of `zone` share one position (an unmerged
/// mesh: contact sees two points there), naming the group, the file and the nodes.
void warn_coincident_slave_nodes(const catalog::Args& zone_args, const engine::ContactZone& zone, const Maillage& ma,
                                 Session& session);

}  // namespace lunaster::cmd
