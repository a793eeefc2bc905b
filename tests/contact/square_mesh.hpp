#pragma once
// A hand-made test mesh: the square [0, side] x [lift, lift + side] cut into n x n cells, two
// counter-clockwise triangles each; boundary edges oriented with the domain on the left:
// bottom ref 3 (left to right), right and top ref 2, left ref 1. `permutation` renumbers the
// nodes (new = permutation[old]) so that tests can tell boundary order from node order.
#include "mesh/mesh.hpp"

#include <numeric>
#include <vector>

namespace sig::test {

inline int square_node(int n, int i, int j) {
  return j * (n + 1) + i;
}

inline Mesh square_mesh(int n, double side = 1.0, double lift = 0.0,
                        std::vector<int> permutation = {}) {
  const int count = (n + 1) * (n + 1);
  if (permutation.empty()) {
    permutation.resize(count);
    std::iota(permutation.begin(), permutation.end(), 0);
  }
  const auto id = [&](int i, int j) { return permutation[square_node(n, i, j)]; };
  Mesh mesh;
  mesh.nodes.resize(count);
  mesh.vertex_ref.assign(count, 0);
  const double h = side / n;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      mesh.nodes[id(i, j)] = {i * h, lift + j * h};
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      mesh.cells.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      mesh.cells.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      mesh.subdomain.push_back(1);
      mesh.subdomain.push_back(1);
    }
  for (int i = 0; i < n; ++i)
    mesh.facets.push_back({{id(i, 0), id(i + 1, 0)}, 3});
  for (int j = 0; j < n; ++j)
    mesh.facets.push_back({{id(n, j), id(n, j + 1)}, 2});
  for (int i = n; i > 0; --i)
    mesh.facets.push_back({{id(i, n), id(i - 1, n)}, 2});
  for (int j = n; j > 0; --j)
    mesh.facets.push_back({{id(0, j), id(0, j - 1)}, 1});
  return mesh;
}

/// A fixed scrambled numbering of the (n+1)^2 nodes (stride coprime with the count).
inline std::vector<int> scrambled(int n) {
  const int count = (n + 1) * (n + 1);
  std::vector<int> p(count);
  int stride = 7;
  while (std::gcd(stride, count) != 1)
    ++stride;
  for (int k = 0; k < count; ++k)
    p[k] = (k * stride + 3) % count;
  return p;
}

} // namespace sig::test
