// Whether two meshes discretize one domain (post/same_domain.hpp): a rectangle at two mesh sizes
// and a disc's polygons of 16 and 64 sides pass; the rectangle moved by 5 % of its size, a
// shorter one, and the disc's octagon (its chords 2.7 % of the size inside the circle) do not.
#include "mesh/generators.hpp"
#include "post/same_domain.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace sig {
namespace {

/// The regular polygon of `n` sides inscribed in the circle of radius 1, as a fan of triangles
/// around its centre.
Mesh polygon(int n) {
  Mesh mesh;
  mesh.nodes.emplace_back(0, 0);
  for (int k = 0; k < n; ++k)
    mesh.nodes.emplace_back(std::cos(2 * std::numbers::pi * k / n),
                            std::sin(2 * std::numbers::pi * k / n));
  for (int k = 0; k < n; ++k) {
    mesh.cells.push_back({0, 1 + k, 1 + (k + 1) % n});
    mesh.subdomain.push_back(1);
  }
  mesh.vertex_ref.assign(mesh.nodes.size(), 0);
  return mesh;
}

Mesh moved(Mesh mesh, const Eigen::Vector2d& by) {
  for (Point& x : mesh.nodes)
    x += by;
  return mesh;
}

TEST(SameDomain, MeshesOfOneDomainPassOthersAreNamed) {
  const Mesh coarse = rectangle(4, 1, 4, 2), fine = rectangle(4, 1, 32, 8);
  EXPECT_EQ(domain_mismatch(coarse, "coarse", fine, "fine"), "");
  EXPECT_EQ(domain_mismatch(polygon(16), "16-gon", polygon(64), "64-gon"), "");
  // 5 % of the size 4.12 is 0.21: the moved rectangle's left side is that far from the other.
  const std::string shifted = domain_mismatch(moved(coarse, {0.21, 0}), "moved", fine, "fine");
  EXPECT_NE(shifted.find("moved and fine are not meshes of one domain: the boundary node (0.21, "),
            std::string::npos)
      << shifted;
  EXPECT_NE(shifted.find(" of moved lies 0.21 from the boundary of fine, more than 2 % of the "
                         "reference's size 4.12311"),
            std::string::npos)
      << shifted;
  EXPECT_NE(domain_mismatch(rectangle(3.8, 1, 4, 2), "short", fine, "fine"), "");
  // The octagon's chords lie 1 - cos(pi / 8) = 0.076 inside the circle, 2.7 % of 2 sqrt(2).
  const std::string octagon = domain_mismatch(polygon(8), "8-gon", polygon(64), "64-gon");
  EXPECT_NE(octagon.find("from the boundary of 8-gon"), std::string::npos) << octagon;
}

} // namespace
} // namespace sig
