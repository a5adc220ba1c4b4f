#include "engine/mesh/mesh_bytes.hpp"

#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <type_traits>
#include <vector>

#include "engine/core/error.hpp"

namespace lunaster::engine {

namespace {

class Writer {
 public:
  template <class T>
  void value(T v) {
    static_assert(std::is_trivially_copyable_v<T>);
    out_.append(reinterpret_cast<const char*>(&v), sizeof v);
  }
  template <class T>
  void array(const std::vector<T>& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    value<std::uint64_t>(v.size());
    out_.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
  }
  void text(const std::string& s) {
    value<std::uint64_t>(s.size());
    out_.append(s);
  }
  /// Names as one block: their lengths, then their characters end to end.
  void texts(const std::vector<std::string>& names) {
    std::vector<std::uint32_t> lengths(names.size());
    size_t total = 0;
    for (size_t i = 0; i < names.size(); ++i) lengths[i] = static_cast<std::uint32_t>(names[i].size()), total += names[i].size();
    array(lengths);
    out_.reserve(out_.size() + total);
    for (const std::string& name : names) out_.append(name);
  }
  void groups(const std::map<std::string, std::vector<int>>& groups) {
    value<std::uint64_t>(groups.size());
    for (const auto& [name, members] : groups) text(name), array(members);
  }
  std::string take() { return std::move(out_); }

 private:
  std::string out_;
};

class Reader {
 public:
  explicit Reader(const std::string& in) : in_(in) {}
  template <class T>
  T value() {
    T v;
    std::memcpy(&v, take(sizeof v), sizeof v);
    return v;
  }
  template <class T>
  std::vector<T> array() {
    const auto n = value<std::uint64_t>();
    LUNASTER_ASSERT(n <= (in_.size() - at_) / sizeof(T), "mesh bytes: an array runs past the end");
    std::vector<T> v(n);
    if (n) std::memcpy(v.data(), take(n * sizeof(T)), n * sizeof(T));
    return v;
  }
  std::string text() {
    const auto n = value<std::uint64_t>();
    const char* p = take(n);
    return std::string(p, n);
  }
  std::vector<std::string> texts() {
    const std::vector<std::uint32_t> lengths = array<std::uint32_t>();
    std::vector<std::string> names(lengths.size());
    for (size_t i = 0; i < lengths.size(); ++i) names[i].assign(take(lengths[i]), lengths[i]);
    return names;
  }
  std::map<std::string, std::vector<int>> groups() {
    std::map<std::string, std::vector<int>> out;
    const auto n = value<std::uint64_t>();
    for (std::uint64_t i = 0; i < n; ++i) {
      std::string name = text();
      out.emplace(std::move(name), array<int>());
    }
    return out;
  }
  bool done() const { return at_ == in_.size(); }

 private:
  const char* take(size_t n) {
    LUNASTER_ASSERT(n <= in_.size() - at_, "mesh bytes: truncated block");
    const char* p = in_.data() + at_;
    at_ += n;
    return p;
  }
  const std::string& in_;
  size_t at_ = 0;
};

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
