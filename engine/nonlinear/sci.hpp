#pragma once
/// A number as the driver's messages write it: scientific, 7 significant digits (%.6e).
#include <cstdio>
#include <string>

namespace lunaster::engine {

inline std::string sci(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6e", v);
  return buf;
}

}  // namespace lunaster::engine
