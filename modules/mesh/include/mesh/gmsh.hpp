#pragma once
// gmsh .msh files (format 2.2 and 4.1, ASCII or binary), 2D P1 meshes:
//  - triangles (type 2): sub-domain = physical tag of their surface (1 when it has none);
//  - lines (type 1) with a physical tag: Facet with ref = that tag;
//  - points (type 15) with a physical tag: vertex_ref of their node.
// An entity in several physical groups (format 4.1) takes the first one. Nodes no triangle uses
// (geometry points gmsh keeps) are dropped and the rest renumbered in file order; triangles are
// made counter-clockwise and boundary edges point with the domain on their left; both with a
// warning naming the nodes and triangles. z is ignored. Quadrangles and elements of second or
// higher order are refused, naming their type: the model is P1. The file is streamed, and every
// count is checked against the bytes left before anything is allocated for it.
#include "mesh/mesh.hpp"

#include <filesystem>
#include <string>

namespace sig {

/// Read and check a gmsh mesh (check_mesh unless `check` is skip); errors are sig::InputError
/// naming the file and the line.
Mesh read_gmsh(const std::filesystem::path& path, MeshCheck check = MeshCheck::run);
/// The same from the bytes of a file called `name` (tests, fuzzing).
Mesh parse_gmsh(const std::string& name, std::string contents);

} // namespace sig
