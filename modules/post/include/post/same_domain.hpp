#pragma once
// Whether two meshes discretize one domain, before an error between their solutions means
// anything (sig-error). The test: the Hausdorff distance of their boundaries (every boundary node
// of each mesh within the distance of a boundary side of the other) is at most
// kDomainTolerance of the reference mesh's size, the diagonal of its bounding box. Meshes of one
// domain differ on its boundary by their discretization only: the chords of a curved boundary
// cut into N segments lie R (1 - cos(pi / N)) inside it, 0.7 % of a disc's size at N = 16 and
// 2.7 % at N = 8. Other domains, moved ones or one with a hole the other lacks, are farther.
#include "mesh/mesh.hpp"

#include <string>

namespace sig {

inline constexpr double kDomainTolerance = 0.02;

/// "" if `mesh` and `reference` discretize one domain by the test above, else why not, naming
/// them as `mesh_name` and `reference_name`: the boundary node farthest from the other boundary,
/// its distance and the tolerance.
std::string domain_mismatch(const Mesh& mesh, const std::string& mesh_name, const Mesh& reference,
                            const std::string& reference_name);

} // namespace sig
