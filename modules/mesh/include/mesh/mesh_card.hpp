#pragma once
// The datafile MESH card: either a generator with its dimensions or a mesh file.
//   MESH generator=half_disc R=8 N=256 grading=0          (half-disc is accepted too)
//   MESH generator=disc centre=10,10 R=10 N=512 grading=0.05
//   MESH generator=ring centre=0,10 r_in=9 r_out=10 N=128 [layers=7] [gamma1_above=19.9]
//        [gamma3_below=17.07]
//   MESH generator=rectangle lx=5 ly=1 nx=320 ny=64 [refs=3,4,2,1]   (bottom, right, top, left)
//   MESH generator=square lx=1 nx=64 [refs=3,4,2,1]
//   MESH file=meshes/legacy/square3.nopo      (.nopo, gmsh or FreeFem .msh; relative to the
//                                              datafile's folder)
#include "core/datafile.hpp"
#include "mesh/boundary_arcs.hpp"
#include "mesh/mesh.hpp"

#include <filesystem>

namespace sig {

/// Read a mesh file by its extension: .nopo (NOPO), .msh (gmsh when it starts with
/// $MeshFormat, FreeFem otherwise).
Mesh read_mesh_file(const std::filesystem::path& path);

/// The mesh a MESH card describes; `folder` is where relative file names start (the datafile's
/// folder). Card errors name the file, the line and the field.
/// The mesh is one check_mesh accepts: its reader or generator ran it (or it is our own NOPO,
/// whose fingerprint says it is as written).
Mesh mesh_from_card(const Card& card, const std::filesystem::path& folder);

/// The circles a MESH card's generator puts its curved boundary on (mesh/boundary_arcs.hpp):
/// the half disc's arc (reference 3), the disc's four quarters (1-4), the ring's outer (2, 3) and
/// inner (4) circles; none for a rectangle, a square or a mesh file.
std::vector<BoundaryArc> boundary_arcs(const Card& card);

/// The sub-domains a card's `region=` field names (all of the mesh's when absent); a sub-domain
/// the mesh lacks is an InputError on the field, listing those present.
std::vector<int> card_regions(const Card& card, const Mesh& mesh);

} // namespace sig
