#pragma once
// Reading back an ELGA field of QUAD4 cells from a MED file with the MED library, for the tests
// that write the points' history (VARI_ELGA, SIEF_ELGA) through the result's MED writer.
#include <filesystem>
#include <string>
#include <vector>

#include <med.h>

#include "engine/io/med_writer.hpp"

namespace lunaster::engine::test {

/// One step of a QUAD4 ELGA field as stored: its cells, points per cell, localization and
/// values (cell by cell, point by point, `n_components` each). n_cells < 0: not read.
struct Quad4Elga {
  int n_cells = -1, n_points = 0;
  std::string localization;
  std::vector<double> values;
};

/// Step `numdt` of field `field` (e.g. "RESU____VARI_ELGA") of `n_components` components.
inline Quad4Elga read_quad4_elga(const std::string& path, const std::string& field, int numdt, int n_components) {
  Quad4Elga out;
  const med_idt fid = MEDfileOpen(path.c_str(), MED_ACC_RDONLY);
  if (fid < 0) return out;
  char profile[MED_NAME_SIZE + 1] = "", localization[MED_NAME_SIZE + 1] = "";
  med_int profile_size = 0, n_points = 0;
  const med_int n = MEDfieldnValueWithProfile(fid, field.c_str(), numdt, MED_NO_IT, MED_CELL, MED_QUAD4, 1,
                                              MED_COMPACT_STMODE, profile, &profile_size, localization, &n_points);
  if (n > 0) {
    std::vector<med_float> values(static_cast<size_t>(n) * n_points * n_components);
    if (MEDfieldValueWithProfileRd(fid, field.c_str(), numdt, MED_NO_IT, MED_CELL, MED_QUAD4, MED_COMPACT_STMODE,
                                   profile, MED_FULL_INTERLACE, MED_ALL_CONSTITUENT,
                                   reinterpret_cast<unsigned char*>(values.data())) >= 0) {
      out.n_cells = static_cast<int>(n);
      out.n_points = static_cast<int>(n_points);
      out.localization = localization;
      out.values.assign(values.begin(), values.end());
    }
  }
  MEDfileClose(fid);
  return out;
}

/// Writes `steps` as result RESU on `mesh` (named BAR) into the build's scratch folder
/// `folder`, as the result's writer does for IMPR_RESU; returns the file's path.
inline std::string write_bar_result(Mesh& mesh, const std::vector<ResultStep>& steps, const std::string& folder) {
  mesh.name = "BAR";
  const std::string dir = std::string(LUNASTER_BINARY_DIR) + "/test-scratch/" + folder;
  std::filesystem::create_directories(dir);
  const std::string path = dir + "/bar.med";
  write_med(path, mesh, {{"RESU", &steps}});
  return path;
}

}  // namespace lunaster::engine::test
