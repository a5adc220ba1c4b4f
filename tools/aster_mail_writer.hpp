#pragma once
/// Writing code_aster text meshes (.mail) from an engine::Mesh, for test meshes
/// (lunaster-meshgen -o FILE.mail). The inverse of engine/io/aster_mail_reader:
/// nodes and cells keep their names, node orders go from MED to code_aster's,
/// cells are written type by type in mesh order (so a mesh whose cells are
/// grouped by type, as the MED files are, reads back in the same order), each
/// group becomes a GROUP_NO / GROUP_MA block.
#include <string>

#include "engine/mesh/mesh.hpp"

namespace lunaster::tools {

/// Writes `mesh` to `path` (replaced atomically). Throws DeckError for a name
/// code_aster's format cannot hold (blank, longer than 24 characters, with a
/// blank, `%`, `=` or `,`) or a write failure.
void write_aster_mail(const std::string& path, const engine::Mesh& mesh);

}  // namespace lunaster::tools
