#pragma once
/// Turning GROUP_MA / MAILLE / GROUP_NO / NOEUD / TOUT keywords into index
/// lists, with errors that name the keyword and the missing entity.
#include <string>
#include <vector>

#include "catalog/args.hpp"
#include "engine/mesh/mesh.hpp"

namespace lunaster::cmd {

/// Cells selected by TOUT='OUI', GROUP_MA and/or MAILLE in `args` (whichever the spec declares).
std::vector<int> select_cells(const catalog::Args& args, const engine::Mesh& mesh);
/// Nodes selected by TOUT, GROUP_NO, NOEUD, or the nodes of GROUP_MA / MAILLE.
std::vector<int> select_nodes(const catalog::Args& args, const engine::Mesh& mesh);
/// Cells of one named group; DeckError at `kw` (with a suggestion) if unknown or empty.
const std::vector<int>& cell_group(const catalog::Args& args, const std::string& kw, const engine::Mesh& mesh,
                                   const std::string& group);
/// A node group or, failing that, the nodes of a cell group of that name.
std::vector<int> node_group(const catalog::Args& args, const std::string& kw, const engine::Mesh& mesh,
                            const std::string& group);

}  // namespace lunaster::cmd
