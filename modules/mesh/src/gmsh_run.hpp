#pragma once
// Run gmsh on a .geo script in a temporary folder and read the mesh it writes. Private to the
// generators.
#include "mesh/mesh.hpp"

#include <string>
#include <utility>
#include <vector>

namespace sig {

/// `gmsh NAME.geo -DIM -format msh41 -setnumber KEY VALUE ...` with `script` as NAME.geo, in a
/// scratch folder of the case (core/temporary_folder.hpp); the binary is $SIG_GMSH or `gmsh`,
/// killed with the stage. Throws sig::Error with the end of gmsh's log on failure.
Mesh mesh_with_gmsh(const std::string& name, const std::string& script,
                    const std::vector<std::pair<std::string, double>>& numbers, int dim = 2);

} // namespace sig
