#include "tools/gmsh_writer.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <sstream>
#include <vector>

#include "engine/core/error.hpp"
#include "engine/io/atomic_file.hpp"
#include "engine/io/gmsh_reader.hpp"

namespace lunaster::tools {

namespace {

using engine::CellType;
using engine::Mesh;

/// One element to write: a mesh cell, or a point element of a node group.
struct Element {
  CellType type;
  std::vector<int> nodes;   ///< mesh node indices, MED order
  int dim;
  std::set<int> physicals;  ///< physical tags
};

/// An elementary entity: the elements of one dimension sharing one set of physical tags.
struct Entity {
  int dim;
  int tag;
  std::set<int> physicals;
  std::vector<int> elements;
};

std::vector<int> gmsh_order(const Element& e) {
  const std::vector<int>& to_med = engine::gmsh_to_med_order(e.type);
  if (to_med.empty()) return e.nodes;
  std::vector<int> out(e.nodes.size());
  for (size_t k = 0; k < out.size(); ++k) out[k] = e.nodes[static_cast<size_t>(to_med[k])];
  return out;
}

}  // namespace

void write_gmsh(const std::string& path, const Mesh& mesh, const std::string& version) {
  if (version != "2.2" && version != "4.1")
    throw DeckError("Gmsh writer: unsupported version '" + version + "' (2.2 or 4.1)");
  const bool v41 = version == "4.1";

  // Physical groups: one tag per cell group, then per node group.
  std::map<std::string, std::pair<int, int>> physical;  // name -> (dim, tag)
  std::vector<Element> elements;
  for (int c = 0; c < mesh.n_cells(); ++c)
    elements.push_back({mesh.cell_types[c], std::vector<int>(mesh.cell(c), mesh.cell(c) + mesh.cell_n_nodes(c)),
                        engine::cell_info(mesh.cell_types[c]).dim, {}});
  int next_tag = 1;
  for (const auto& [name, cells] : mesh.cell_groups) {
    if (cells.empty()) continue;
    const int dim = elements[cells.front()].dim;
    const int tag = next_tag++;
    physical[name] = {dim, tag};
    for (int c : cells) {
      if (elements[c].dim != dim)
        throw DeckError("Gmsh writer: group '" + name + "' mixes cells of dimensions " + std::to_string(dim) +
                        " and " + std::to_string(elements[c].dim));
      elements[c].physicals.insert(tag);
    }
  }
  std::map<int, int> point_element;  // node -> its point element
  for (const auto& [name, nodes] : mesh.node_groups) {
    if (nodes.empty() || physical.count(name)) continue;
    const int tag = next_tag++;
    physical[name] = {0, tag};
    for (int n : nodes) {
      auto [it, fresh] = point_element.emplace(n, static_cast<int>(elements.size()));
      if (fresh) elements.push_back({CellType::Point1, {n}, 0, {}});
      elements[it->second].physicals.insert(tag);
    }
  }
  if (!v41)
    for (size_t e = 0; e < elements.size(); ++e)
      if (elements[e].physicals.size() > 1)
        throw DeckError("Gmsh writer: element " + std::to_string(e + 1) +
                        " is in several groups, which format 2.2 cannot hold (use 4.1)");

  // Entities: per dimension, one per set of physical tags (points: one per element).
  std::vector<Entity> entities;
  std::map<std::pair<int, std::set<int>>, int> entity_of;
  std::vector<int> element_entity(elements.size());
  int next_entity[4] = {1, 1, 1, 1};
  for (size_t e = 0; e < elements.size(); ++e) {
    const Element& el = elements[e];
    const auto key = std::make_pair(el.dim, el.physicals);
    auto it = entity_of.find(key);
    if (it == entity_of.end() || el.dim == 0) {
      entities.push_back({el.dim, next_entity[el.dim]++, el.physicals, {}});
      it = entity_of.insert_or_assign(key, static_cast<int>(entities.size()) - 1).first;
    }
    entities[it->second].elements.push_back(static_cast<int>(e));
    element_entity[e] = it->second;
  }

  std::ostringstream os;
  os.precision(17);
  os << "$MeshFormat\n" << version << " 0 8\n$EndMeshFormat\n";
  if (!physical.empty()) {
    os << "$PhysicalNames\n" << physical.size() << "\n";
    std::vector<std::pair<int, std::string>> by_tag;
    for (const auto& [name, dt] : physical) by_tag.push_back({dt.second, name});
    std::sort(by_tag.begin(), by_tag.end());
    for (const auto& [tag, name] : by_tag) os << physical[name].first << " " << tag << " \"" << name << "\"\n";
    os << "$EndPhysicalNames\n";
  }
  const int n_nodes = mesh.n_nodes();
  if (v41) {
    int counts[4] = {0, 0, 0, 0};
    for (const Entity& en : entities) ++counts[en.dim];
    os << "$Entities\n" << counts[0] << " " << counts[1] << " " << counts[2] << " " << counts[3] << "\n";
    for (int dim = 0; dim < 4; ++dim)
      for (const Entity& en : entities) {
        if (en.dim != dim) continue;
        double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
        for (int e : en.elements)
          for (int n : elements[e].nodes)
            for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], mesh.node(n)[k]), hi[k] = std::max(hi[k], mesh.node(n)[k]);
        os << en.tag;
        for (int k = 0; k < 3; ++k) os << " " << lo[k];
        if (dim > 0)
          for (int k = 0; k < 3; ++k) os << " " << hi[k];
        os << " " << en.physicals.size();
        for (int p : en.physicals) os << " " << p;
        if (dim > 0) os << " 0";
        os << "\n";
      }
    os << "$EndEntities\n";
    // All nodes in one block, attached to the first entity of the highest dimension.
    const Entity* top = &entities.front();
    for (const Entity& en : entities)
      if (en.dim > top->dim) top = &en;
    os << "$Nodes\n1 " << n_nodes << " 1 " << n_nodes << "\n" << top->dim << " " << top->tag << " 0 " << n_nodes
       << "\n";
    for (int n = 0; n < n_nodes; ++n) os << n + 1 << "\n";
    for (int n = 0; n < n_nodes; ++n) os << mesh.node(n)[0] << " " << mesh.node(n)[1] << " " << mesh.node(n)[2] << "\n";
    os << "$EndNodes\n";
    // One block per (entity, type); element tags follow the element order.
    std::vector<std::pair<int, CellType>> blocks;
    std::map<std::pair<int, int>, std::vector<int>> block_elements;
    for (size_t e = 0; e < elements.size(); ++e) {
      const auto key = std::make_pair(element_entity[e], static_cast<int>(elements[e].type));
      if (!block_elements.count(key)) blocks.push_back({element_entity[e], elements[e].type});
      block_elements[key].push_back(static_cast<int>(e));
    }
    os << "$Elements\n" << blocks.size() << " " << elements.size() << " 1 " << elements.size() << "\n";
    for (const auto& [entity, type] : blocks) {
      const auto& list = block_elements[{entity, static_cast<int>(type)}];
      os << entities[entity].dim << " " << entities[entity].tag << " " << engine::gmsh_element_type(type) << " "
         << list.size() << "\n";
      for (int e : list) {
        os << e + 1;
        for (int n : gmsh_order(elements[e])) os << " " << n + 1;
        os << "\n";
      }
    }
    os << "$EndElements\n";
  } else {
    os << "$Nodes\n" << n_nodes << "\n";
    for (int n = 0; n < n_nodes; ++n)
      os << n + 1 << " " << mesh.node(n)[0] << " " << mesh.node(n)[1] << " " << mesh.node(n)[2] << "\n";
    os << "$EndNodes\n$Elements\n" << elements.size() << "\n";
    for (size_t e = 0; e < elements.size(); ++e) {
      const Element& el = elements[e];
      const int phys = el.physicals.empty() ? 0 : *el.physicals.begin();
      os << e + 1 << " " << engine::gmsh_element_type(el.type) << " 2 " << phys << " "
         << entities[element_entity[e]].tag;
      for (int n : gmsh_order(el)) os << " " << n + 1;
      os << "\n";
    }
    os << "$EndElements\n";
  }
  engine::write_file_atomically(path, [&](std::ostream& out) { out << os.str(); });
}

}  // namespace lunaster::tools
