#pragma once
// The element array NOP5 of a NOPO file turned into a Mesh (MODULEF.md section 3.3). Private to
// the NOPO reader.
#include "mesh/mesh.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace sig {

/// Positions of the NOP2 words used here (MODULEF.md section 3.2), 0-based.
namespace word {
enum Word {
  NDIM = 0,
  NCOPNP = 3,
  NE = 4,
  NSEG = 6,
  NTRI = 7,
  NQUA = 8,
  NTET = 9,
  NSUP = 12,
  NP = 21,
  NTACOO = 26
};
} // namespace word

/// Walk the NOP2[NE] elements of NOP5 (NCGE NMAE NDSDE NNO nodes [NPO points] [INING refs]):
/// triangles keep their order, quadrilaterals are split (1,2,3) + (3,4,1), references become
/// edges (kept once, domain on the left) and vertex_ref. `coordinates` is NOP4 (x, y per point).
/// Errors name `file`, the element and its word in NOP5.
Mesh walk_nop5(const std::vector<std::int64_t>& nop5, const std::array<std::int64_t, 27>& nop2,
               std::vector<double> coordinates, const std::string& file);

} // namespace sig
