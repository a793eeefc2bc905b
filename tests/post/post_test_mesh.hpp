#pragma once
// Small meshes for the post tests, built by hand so the tests need no mesh reader.
#include "mesh/mesh.hpp"

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
  m.triangles = {{0, 4, 3}, {4, 1, 2}, {4, 2, 3}};
  m.subdomain = {1, 2, 2};
  m.edges = {{0, 4, 3}, {4, 1, 3}, {1, 2, 2}, {2, 3, 1}, {3, 0, 4}};
  m.vertex_ref = {0, 0, 0, 0, 0};
  return m;
}

} // namespace sig::test
