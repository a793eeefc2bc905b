#pragma once
// Small meshes, materials and files for the post tests, built by hand so the tests need no mesh
// reader.
#include "core/ds.hpp"
#include "material/mili.hpp"
#include "mesh/mesh.hpp"

#include <vtkNew.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cstdint>
#include <filesystem>
#include <vector>

namespace sig::test {

/// The rectangle [0,2] x [0,1] in three counter-clockwise triangles (sub-domain 1 on the left,
/// 2 on the right); edge references 3 bottom (through node 4), 2 right, 1 top, 4 left.
///   3 ------- 2
///   | \    /  |
///   |  \  /   |
///   0 -- 4 -- 1
inline Mesh small_mesh() {
  Mesh m;
  m.nodes = {{0, 0}, {2, 0}, {2, 1}, {0, 1}, {1, 0}};
  m.cells = {{0, 4, 3}, {4, 1, 2}, {4, 2, 3}};
  m.subdomain = {1, 2, 2};
  m.facets = {{{0, 4}, 3}, {{4, 1}, 3}, {{1, 2}, 2}, {{2, 3}, 1}, {{3, 0}, 4}};
  m.vertex_ref = {0, 0, 0, 0, 0};
  return m;
}

/// Contact on the bottom nodes 1, 5, 2 (1-based) of small_mesh against the plane x2 = -0.1,
/// normal (0, 1), tangent (1, 0); Signorini, frictionless.
inline Ds bottom_contact() {
  Ds cont("CONT", "bottom", "test");
  cont.put("node", std::vector<std::int64_t>{1, 5, 2});
  cont.put("lagrange_node", std::vector<std::int64_t>{6, 7, 8});
  cont.put("normal", std::vector<double>{0, 1, 0, 1, 0, 1}, {3, 2});
  cont.put("tangent", std::vector<double>{1, 0, 1, 0, 1, 0}, {3, 2});
  cont.put("gap", std::vector<double>{0.1, 0.1, 0.1});
  cont.put("weight", std::vector<double>{0.5, 1.0, 0.5});
  cont.put("law", std::vector<std::int64_t>{1, 1, 1});
  return cont;
}

/// Hooke, plane strain, E = 100 and this nu, on both sub-domains of small_mesh.
inline MaterialTable two_materials(double nu) {
  MaterialTable table;
  for (int s : {1, 2}) {
    SubdomainMaterial m;
    m.subdomain = s;
    m.hooke = {100.0, nu, PlaneMode::strain};
    table.entries.push_back(m);
  }
  return table;
}

/// The .vtu at `path` read through VTK's own reader (not through our writer's code).
inline vtkSmartPointer<vtkUnstructuredGrid> read_vtu(const std::filesystem::path& path) {
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  return reader->GetOutput();
}

} // namespace sig::test
