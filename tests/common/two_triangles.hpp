#pragma once
// The smallest mesh of the unit tests: the unit square cut along its diagonal into two triangles
// of the given sub-domains, no boundary edge and no reference on its vertices.
#include "mesh/mesh.hpp"

namespace sig::test {

inline Mesh two_triangle_square(int first_subdomain = 1, int second_subdomain = 1) {
  Mesh mesh;
  mesh.nodes = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  mesh.cells = {{0, 1, 2}, {0, 2, 3}};
  mesh.subdomain = {first_subdomain, second_subdomain};
  mesh.vertex_ref.assign(4, 0);
  return mesh;
}

} // namespace sig::test
