#include "engine/mesh/mesh_bytes.hpp"

#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <type_traits>
#include <vector>

#include "engine/core/bytes.hpp"
#include "engine/core/error.hpp"

namespace lunaster::engine {

namespace {

using Writer = ByteWriter;
using Reader = ByteReader;

constexpr std::uint32_t kMagic = 0x4c4d5348;  // "LMSH"

}  // namespace

std::string mesh_to_bytes(const Mesh& mesh, std::initializer_list<const std::vector<int>*> extra) {
  Writer w;
  w.value(kMagic);
  w.value<std::int32_t>(mesh.dim);
  w.text(mesh.name);
  w.array(mesh.coords);
  w.texts(mesh.node_names);
  std::vector<std::uint8_t> types(mesh.cell_types.size());
  for (size_t c = 0; c < types.size(); ++c) types[c] = static_cast<std::uint8_t>(mesh.cell_types[c]);
  w.array(types);
  w.array(mesh.cell_offsets);
  w.array(mesh.cell_nodes);
  w.texts(mesh.cell_names);
  w.groups(mesh.node_groups);
  w.groups(mesh.cell_groups);
  w.value<std::uint64_t>(extra.size());
  for (const std::vector<int>* v : extra) w.array(*v);
  return w.take();
}

Mesh mesh_from_bytes(const std::string& bytes, std::initializer_list<std::vector<int>*> extra) {
  Reader r(bytes);
  LUNASTER_ASSERT(r.value<std::uint32_t>() == kMagic, "mesh bytes: not a mesh block");
  Mesh mesh;
  mesh.dim = r.value<std::int32_t>();
  mesh.name = r.text();
  mesh.coords = r.array<double>();
  mesh.node_names = r.texts();
  const std::vector<std::uint8_t> types = r.array<std::uint8_t>();
  mesh.cell_types.resize(types.size());
  for (size_t c = 0; c < types.size(); ++c) {
    LUNASTER_ASSERT(types[c] <= static_cast<std::uint8_t>(CellType::Hexa20), "mesh bytes: unknown cell type");
    mesh.cell_types[c] = static_cast<CellType>(types[c]);
  }
  mesh.cell_offsets = r.array<int>();
  mesh.cell_nodes = r.array<int>();
  mesh.cell_names = r.texts();
  mesh.node_groups = r.groups();
  mesh.cell_groups = r.groups();
  LUNASTER_ASSERT(r.value<std::uint64_t>() == extra.size(), "mesh bytes: not the arrays asked for after the mesh");
  for (std::vector<int>* v : extra) *v = r.array<int>();
  LUNASTER_ASSERT(r.done(), "mesh bytes: bytes left after the mesh");
  LUNASTER_ASSERT(mesh.coords.size() == 3 * mesh.node_names.size() &&
                      mesh.cell_offsets.size() == mesh.cell_types.size() + 1 &&
                      mesh.cell_names.size() == mesh.cell_types.size() &&
                      static_cast<size_t>(mesh.cell_offsets.back()) == mesh.cell_nodes.size(),
                  "mesh bytes: inconsistent sizes");
  return mesh;
}

}  // namespace lunaster::engine
