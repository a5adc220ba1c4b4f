#include "engine/io/med_common.hpp"

namespace lunaster::engine::med_detail {

namespace {

struct TypePair {
  CellType type;
  med_geometry_type geo;
};

const TypePair kPairs[] = {
    {CellType::Point1, MED_POINT1}, {CellType::Seg2, MED_SEG2},       {CellType::Seg3, MED_SEG3},
    {CellType::Tria3, MED_TRIA3},   {CellType::Tria6, MED_TRIA6},     {CellType::Quad4, MED_QUAD4},
    {CellType::Quad8, MED_QUAD8},   {CellType::Tetra4, MED_TETRA4},   {CellType::Tetra10, MED_TETRA10},
    {CellType::Pyram5, MED_PYRA5},  {CellType::Penta6, MED_PENTA6},   {CellType::Penta15, MED_PENTA15},
    {CellType::Hexa8, MED_HEXA8},   {CellType::Hexa20, MED_HEXA20},
};

}  // namespace

med_geometry_type to_med(CellType type) {
  for (const auto& p : kPairs)
    if (p.type == type) return p.geo;
  return MED_NONE;
}

bool from_med(med_geometry_type geo, CellType& out) {
  for (const auto& p : kPairs) {
    if (p.geo == geo) {
      out = p.type;
      return true;
    }
  }
  return false;
}

bool append_fixed(std::string& out, const std::string& text, size_t width) {
  if (text.size() > width) return false;
  out += text;
  out.append(width - text.size(), ' ');
  return true;
}

std::string trim_fixed(const char* begin, size_t width) {
  size_t n = 0;
  while (n < width && begin[n] != '\0') ++n;
  while (n > 0 && begin[n - 1] == ' ') --n;
  return std::string(begin, n);
}

}  // namespace lunaster::engine::med_detail
