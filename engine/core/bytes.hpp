#pragma once
/// Values, arrays and texts as one block of bytes and back, in this build's native layout (not a
/// file format: what the ranks of one MPI run send each other, e.g. a mesh, engine/mesh/mesh_bytes.hpp).
#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <type_traits>
#include <vector>

#include "engine/core/error.hpp"

namespace lunaster::engine {

/// Appends values, arrays and texts to a byte string of this build's native layout.
class ByteWriter {
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
    for (size_t i = 0; i < names.size(); ++i) {
      lengths[i] = static_cast<std::uint32_t>(names[i].size());
      total += names[i].size();
    }
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

/// Reads back what a ByteWriter wrote, in the same order; a block read past its end is an
/// internal error.
class ByteReader {
 public:
  explicit ByteReader(const std::string& in) : in_(in) {}
  template <class T>
  T value() {
    T v;
    std::memcpy(&v, take(sizeof v), sizeof v);
    return v;
  }
  template <class T>
  std::vector<T> array() {
    const auto n = value<std::uint64_t>();
    LUNASTER_ASSERT(n <= (in_.size() - at_) / sizeof(T), "bytes: an array runs past the end");
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
    LUNASTER_ASSERT(n <= in_.size() - at_, "bytes: truncated block");
    const char* p = in_.data() + at_;
    at_ += n;
    return p;
  }
  const std::string& in_;
  size_t at_ = 0;
};

}  // namespace lunaster::engine
