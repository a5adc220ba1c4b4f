#pragma once
/// Internal helpers shared by the MED reader and writer (includes med.h: only
/// for engine/io/*.cpp, never for a public header).
// Debian's libmedc is built with MPI: med.h declares MEDparFileOpen(MPI_Comm,
// MPI_Info) and expects mpi.h to come with the parallel hdf5.h, which CMake puts
// on the include path (see CMakeLists.txt). lunaster never calls the parallel API.
#include <hdf5.h>
#include <med.h>

#include <string>
#include <vector>

#include "engine/mesh/cell_type.hpp"

namespace lunaster::engine::med_detail {

/// MED geometry type of a cell type.
med_geometry_type to_med(CellType type);
/// Cell type of a MED geometry type; false if lunaster does not support it.
bool from_med(med_geometry_type geo, CellType& out);

/// Fixed-width MED string: `text` padded with spaces to `width` characters.
/// Returns false (and leaves `out` untouched) if `text` is longer than `width`.
bool append_fixed(std::string& out, const std::string& text, size_t width);
/// Trims trailing spaces and NULs of a fixed-width field.
std::string trim_fixed(const char* begin, size_t width);

/// Closes a MED file on scope exit.
class MedFile {
 public:
  explicit MedFile(med_idt fid) : fid_(fid) {}
  ~MedFile() { close(); }
  MedFile(const MedFile&) = delete;
  MedFile& operator=(const MedFile&) = delete;
  med_idt id() const { return fid_; }
  bool ok() const { return fid_ >= 0; }
  /// Returns false if closing failed (data may not be flushed).
  bool close() {
    if (fid_ < 0) return true;
    const med_err rc = MEDfileClose(fid_);
    fid_ = -1;
    return rc >= 0;
  }

 private:
  med_idt fid_;
};

}  // namespace lunaster::engine::med_detail
