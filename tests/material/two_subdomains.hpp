#pragma once
// The mesh of the material-table tests: two triangles of sub-domains 1 and 3, enough for the
// table, which only looks at sub-domains.
#include "mesh/mesh.hpp"

namespace sig::test {

inline Mesh two_subdomains() {
  Mesh mesh;
  mesh.nodes = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  mesh.subdomain = {1, 3};
  mesh.vertex_ref.assign(4, 0);
  return mesh;
}

} // namespace sig::test
