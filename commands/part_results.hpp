#pragma once
/// Results on a mesh in parts brought to rank 0 on the whole mesh, for what rank 0 writes.
#include <vector>

#include "engine/assembly/mesh_part.hpp"
#include "engine/fields/fields.hpp"

namespace lunaster::cmd {

/// Every field of `steps` (on this rank's part) gathered to rank 0 on the whole mesh: a node's
/// values from its owner, a cell's from the rank that computes it (part_fields.hpp). On rank 0
/// the steps of the serial run; elsewhere the steps without their fields. Collective.
std::vector<engine::ResultStep> gather_steps_to_root(const engine::MeshPart& part,
                                                     const std::vector<engine::ResultStep>& steps);

}  // namespace lunaster::cmd
