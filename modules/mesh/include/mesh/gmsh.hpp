#pragma once
// gmsh .msh files (ASCII, format 2.2 and 4.1), 2D P1 meshes:
//  - triangles (type 2): sub-domain = physical tag of their surface (1 when it has none);
//  - lines (type 1) with a physical tag: BoundaryEdge with ref = that tag;
//  - points (type 15) with a physical tag: vertex_ref of their node.
// An entity in several physical groups (format 4.1) takes the first one. Nodes no triangle uses
// (geometry points gmsh keeps) are dropped and the rest renumbered in file order; triangles are
// made counter-clockwise and boundary edges point with the domain on their left. z is ignored.
#include "mesh/mesh.hpp"

#include <filesystem>

namespace sig {

/// Read and check a gmsh mesh; errors are sig::InputError naming the file and the line.
Mesh read_gmsh(const std::filesystem::path& path);

} // namespace sig
