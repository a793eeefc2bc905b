#pragma once
// FreeFem++ .msh files (MODULEF.md section 5): a line "nv nt nbe", nv lines "x y label", nt
// lines "a b c region", nbe lines "a b label", all 1-based. As in NOPO, region 0 becomes
// sub-domain 1, labels are taken by absolute value and edges labelled 0 carry no reference.
// Triangles are made counter-clockwise (with a warning naming them) and boundary edges point with
// the domain on their left. The header's counts are checked against the file's size before
// anything is allocated for them.
#include "mesh/mesh.hpp"

#include <filesystem>
#include <string>

namespace sig {

/// Read and check a FreeFem mesh; errors are sig::InputError naming the file and the line.
Mesh read_freefem_msh(const std::filesystem::path& path);
/// The same from the bytes of a file called `name` (tests, fuzzing).
Mesh parse_freefem_msh(const std::string& name, std::string contents);

} // namespace sig
