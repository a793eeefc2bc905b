// sig-mesh DATAFILE [-o OUTDIR]: the mesh stage (MODULEF's APNOPO). Builds or reads the mesh of
// the MESH card, checks it and writes OUTDIR/case.nopo, MODULEF's NOPO structure in the i8r8
// variant (double-precision coordinates, so later stages see the exact generator nodes).
#include "mesh/stage_main.hpp"

#include "core/datafile.hpp"
#include "core/stage.hpp"
#include "core/stage_cards.hpp"
#include "mesh/mesh_card.hpp"
#include "mesh/nopo.hpp"

#include <iostream>
#include <map>
#include <sstream>

namespace {

/// "refs 1 (vertices: 5), 2 (edges: 32), ..." for the summary line.
std::string describe_references(const sig::Mesh& mesh) {
  std::map<int, int> edges, vertices;
  for (const auto& e : mesh.facets)
    ++edges[e.ref];
  for (int r : mesh.vertex_ref) {
    if (r != 0) ++vertices[r];
  }
  std::ostringstream out;
  for (int ref : mesh.references()) {
    out << " " << ref << " (";
    if (edges.count(ref)) out << edges[ref] << (mesh.dim == 3 ? " faces" : " edges");
    if (edges.count(ref) && vertices.count(ref)) out << ", ";
    if (vertices.count(ref)) out << vertices[ref] << " vertices";
    out << ")";
  }
  return out.str();
}

} // namespace

namespace sig {

int mesh_main(int argc, char** argv) {
  const sig::StageHelp help{
      .name = "sig-mesh",
      .purpose = "The mesh stage (MODULEF's APNOPO): builds the mesh of the MESH card (a generator "
                 "of the thesis's geometries, or a gmsh, FreeFem or NOPO file), checks it and "
                 "writes it as a NOPO structure with double-precision coordinates.",
      .reads = {"DATAFILE, and the mesh file its MESH card names (file=, relative to the "
                "datafile's folder)"},
      .writes = {"OUTDIR/case.nopo (NOPO mesh: nodes, triangles or tetrahedra, sub-domains, "
                 "references of vertices and edges or faces)",
                 "OUTDIR/case.nopo.prov (what case.nopo was made from: the MESH card's values)"},
      .cards = sig::stage_cards("mesh").cards};
  return sig::run_stage("sig-mesh", [&] {
    // 1. Command line and datafile.
    const sig::StageArgs args = sig::parse_stage_args(argc, argv, help);
    const sig::Datafile& datafile = args.deck;

    // 2. Mesh from the MESH card (generator or file), relative paths from the datafile folder.
    const sig::Card& card = datafile.require("MESH");
    const sig::Mesh mesh = sig::mesh_from_card(card, args.datafile.parent_path());

    // 3. Write the NOPO structure. mesh_from_card's mesh is checked (its reader or generator
    //    ran check_mesh, or it is our own stamped NOPO), so the writer does not check it again.
    const auto nopo = args.ds_path("nopo");
    sig::write_nopo(nopo, mesh, sig::NopoVariant::i8r8, datafile.title(), "sig-mesh",
                    sig::MeshCheck::skip);

    // 4. One-line summary.
    std::cout << "sig-mesh: " << (mesh.dim == 3 ? "3D, " : "") << mesh.num_nodes() << " nodes, "
              << mesh.num_cells() << (mesh.dim == 3 ? " tetrahedra" : " triangles")
              << ", sub-domains " << mesh.subdomains().size() << ", references"
              << describe_references(mesh) << " -> " << nopo.string() << "\n";
  });
}

} // namespace sig
