#pragma once
/// Compatibility of slave/master cell types for integrating the continuous
/// contact terms (R5.03.52, SSNP121 remarks): a quadrangle slave (QUAD4,
/// QUAD8) facing a quadratic triangle master (TRIA6) does not satisfy the
/// compatibility conditions; same-type pairs (QUAD8/QUAD8, TRIA6/TRIA6) and a
/// triangle slave on a quadrangle master (TRIA6 on QUAD8, TRIA3 on QUAD8) do.
#include <string>
#include <vector>

#include "engine/contact/contact_definition.hpp"
#include "engine/mesh/mesh.hpp"

namespace lunaster::engine {

/// True when a slave cell of type `slave` may face a master cell of type `master`.
bool contact_pairing_compatible(CellType slave, CellType master);

/// The warning text for one incompatible pairing, naming the cells
/// (`zone_index` is 0-based, printed 1-based).
std::string contact_pairing_warning(int zone_index, CellType slave, const std::string& slave_cell, CellType master,
                                    const std::string& master_cell);

/// Static check of a zone from the cell types present on each side: one
/// message per incompatible (slave type, master type) combination, naming the
/// first cell of each type. Empty when compatible. Commands may call it when a
/// zone is defined; the contact hook repeats it on the actual pairs.
std::vector<std::string> check_contact_zone_compatibility(const Mesh& mesh, const ContactZone& zone,
                                                          int zone_index);

/// Continuous method only: warnings for slave cell types on which the zone's
/// integration rule has fewer points than the cell carries LAGS_C unknowns
/// (e.g. GAUSS ORDRE_INT=1 on SEG2, GAUSS 3 on TRIA6): the multipliers are then
/// under-determined and the answer is either a singular system or garbage.
struct IntegrationWarning {
  enum class Kind {
    VerticesOnlyOnQuadraticMaster,  ///< remedy: a rule with interior points, or a quadratic slave
    TooFewPoints,                   ///< remedy: a higher order, or the automatic/Simpson/Newton-Cotes rule
  };
  Kind kind;
  std::string text;  ///< names the cells; engine terms only
};
std::vector<IntegrationWarning> check_contact_zone_integration(const Mesh& mesh, const ContactZone& zone,
                                                               int zone_index);

}  // namespace lunaster::engine
