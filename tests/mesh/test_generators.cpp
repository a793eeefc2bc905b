// Generated thesis geometries: counts, references, exact areas of the inscribed polygons,
// mirror symmetry of the ring. half_disc and disc run gmsh at small N.
#include "core/error.hpp"
#include "mesh/generators.hpp"
#include "mesh_testing.hpp"

#include <bit>
#include <numbers>
#include <set>

namespace sig {
namespace {

double area(const Mesh& mesh) {
  double sum = 0;
  for (int t = 0; t < mesh.num_cells(); ++t)
    sum += 0.5 * signed_double_area(mesh, t);
  return sum;
}

/// Every referenced edge that bounds one triangle runs as in that triangle (domain on the left).
void expect_domain_on_the_left(const Mesh& mesh) {
  std::set<std::pair<int, int>> sides;
  for (const auto& t : mesh.cells) {
    for (int j = 0; j < 3; ++j)
      sides.insert({t[j], t[(j + 1) % 3]});
  }
  for (const auto& e : mesh.facets) {
    EXPECT_TRUE(sides.count({e.node[0], e.node[1]}))
        << "edge " << e.node[0] << "-" << e.node[1] << " ref " << e.ref;
  }
}

int find_node(const Mesh& mesh, const Eigen::Vector2d& x) {
  for (int i = 0; i < mesh.num_nodes(); ++i) {
    if (mesh.nodes[i] == x) return i;
  }
  return -1;
}

TEST(HalfDisc, ArcNodesReferencesAndArea) {
  if (!testing::have_gmsh()) GTEST_SKIP() << "gmsh not installed";
  const double R = 8;
  const int N = 16;
  const Mesh mesh = half_disc(R, N);
  const std::vector<int> arc = mesh.nodes_with_ref(3);
  EXPECT_EQ(arc.size(), static_cast<std::size_t>(N + 1));
  EXPECT_EQ(mesh.facets_with_ref(3).size(), static_cast<std::size_t>(N));
  for (const auto& e : mesh.facets_with_ref(3)) { // uniform chords pi R / N subtends
    EXPECT_NEAR((mesh.nodes[e.node[0]] - mesh.nodes[e.node[1]]).norm(),
                2 * R * std::sin(std::numbers::pi / (2 * N)), 1e-12);
  }
  for (int i : arc)
    EXPECT_NEAR((mesh.nodes[i] - Eigen::Vector2d(0, R)).norm(), R, 1e-12);
  const int top = find_node(mesh, {0, R});
  ASSERT_GE(top, 0) << "top centre is not a node";
  EXPECT_EQ(mesh.vertex_ref[top], 1);
  EXPECT_EQ(mesh.nodes_with_ref(1), std::vector<int>{top});
  EXPECT_GE(find_node(mesh, {0, 0}), 0) << "lowest arc node must be (0, 0)";
  for (const auto& e : mesh.facets_with_ref(2)) {
    EXPECT_EQ(mesh.nodes[e.node[0]].y(), R);
    EXPECT_EQ(mesh.nodes[e.node[1]].y(), R);
  }
  expect_domain_on_the_left(mesh);
  // The polygon is N triangles of apex angle pi / N at the centre; close to pi R^2 / 2.
  EXPECT_NEAR(area(mesh), N * 0.5 * R * R * std::sin(std::numbers::pi / N), 1e-11);
  EXPECT_NEAR(area(mesh), std::numbers::pi * R * R / 2, std::numbers::pi * R * R / N);
}

TEST(HalfDisc, DeterministicAndGraded) {
  if (!testing::have_gmsh()) GTEST_SKIP() << "gmsh not installed";
  const Mesh a = half_disc(1, 32), b = half_disc(1, 32);
  EXPECT_EQ(a.nodes, b.nodes);
  EXPECT_EQ(a.cells, b.cells);
  const Mesh graded = half_disc(1, 32, 0.5);
  EXPECT_LT(graded.num_cells(), a.num_cells());
  EXPECT_EQ(graded.nodes_with_ref(3).size(), 33u);
  // Uniform size h = pi / 32: about (pi / 2) / (sqrt(3) h^2 / 4) equilateral triangles.
  const double h = std::numbers::pi / 32;
  const double equilateral = (std::numbers::pi / 2) / (std::sqrt(3.0) * h * h / 4);
  EXPECT_GT(a.num_cells(), 0.7 * equilateral);
  EXPECT_LT(a.num_cells(), 1.5 * equilateral);
}

TEST(HalfDisc, RejectsOddN) {
  EXPECT_THROW(half_disc(1, 15), Error);
}

TEST(Disc, QuartersAndArea) {
  if (!testing::have_gmsh()) GTEST_SKIP() << "gmsh not installed";
  const Eigen::Vector2d c(10, 10);
  const double R = 10;
  const int N = 32;
  const Mesh mesh = disc(c, R, N);
  const double s = R / std::sqrt(2.0);
  for (int ref = 1; ref <= 4; ++ref) {
    EXPECT_EQ(mesh.facets_with_ref(ref).size(), static_cast<std::size_t>(N / 4)) << ref;
    for (int i : mesh.nodes_with_ref(ref)) {
      const Eigen::Vector2d d = mesh.nodes[i] - c;
      EXPECT_NEAR(d.norm(), R, 1e-12);
      if (ref == 1) {
        EXPECT_LE(d.x(), -s + 1e-12);
      }
      if (ref == 2) {
        EXPECT_GE(d.y(), s - 1e-12);
      }
      if (ref == 3) {
        EXPECT_LE(d.y(), -s + 1e-12);
      }
      if (ref == 4) {
        EXPECT_GE(d.x(), s - 1e-12);
      }
    }
  }
  EXPECT_GE(find_node(mesh, {10, 0}), 0) << "lowest node must touch x2 = 0";
  expect_domain_on_the_left(mesh);
  EXPECT_NEAR(area(mesh), N * 0.5 * R * R * std::sin(2 * std::numbers::pi / N), 1e-10);
}

TEST(Disc, GradedArcsAreFineOnlyNearTheBottom) {
  if (!testing::have_gmsh()) GTEST_SKIP() << "gmsh not installed";
  // Scene 4: 128 uniform segments on Gamma3 (the bottom quarter), the rest coarsening away.
  const Eigen::Vector2d c(10, 10);
  const double R = 10;
  const int N = 512;
  const Mesh uniform = disc(c, R, N, 0.1), graded = disc(c, R, N, 0.1, true);
  EXPECT_EQ(graded.facets_with_ref(3).size(), static_cast<std::size_t>(N / 4));
  for (const auto& e : graded.facets_with_ref(3)) // uniform chords of 2 pi / N
    EXPECT_NEAR((graded.nodes[e.node[0]] - graded.nodes[e.node[1]]).norm(),
                2 * R * std::sin(std::numbers::pi / N), 1e-12);
  for (int ref : {1, 2, 4}) {
    EXPECT_LT(graded.facets_with_ref(ref).size(), static_cast<std::size_t>(N / 8)) << ref;
    for (int i : graded.nodes_with_ref(ref))
      EXPECT_NEAR((graded.nodes[i] - c).norm(), R, 1e-12) << ref;
  }
  // The top quarter, farthest from Gamma3, is the coarsest.
  EXPECT_LT(graded.facets_with_ref(2).size(), graded.facets_with_ref(1).size());
  EXPECT_EQ(graded.facets_with_ref(1).size(), graded.facets_with_ref(4).size());
  EXPECT_LT(graded.num_cells(), uniform.num_cells());
  EXPECT_GE(find_node(graded, {10, 0}), 0) << "lowest node must touch x2 = 0";
  expect_domain_on_the_left(graded);
  EXPECT_NEAR(area(graded), std::numbers::pi * R * R, 2 * std::numbers::pi * R * R / 64);
}

TEST(Ring, ThesisCountsAtN128) {
  const Mesh mesh = ring({0, 10}, 9, 10, 128);
  EXPECT_EQ(mesh.num_nodes(), 896); // 1792 dofs
  EXPECT_EQ(mesh.num_cells(), 2 * 128 * 6);
  EXPECT_EQ(mesh.nodes_with_ref(3).size(), 97u);
  EXPECT_EQ(mesh.facets_with_ref(3).size(), 96u); // 3N/4
  EXPECT_EQ(mesh.facets_with_ref(2).size(), 32u);
  EXPECT_EQ(mesh.facets_with_ref(4).size(), 128u);
  std::vector<int> ab;
  for (int i = 0; i < mesh.num_nodes(); ++i) {
    if (mesh.vertex_ref[i] == 1) ab.push_back(i);
  }
  EXPECT_EQ(ab.size(), 5u); // outer nodes with x2 >= 19.9
  for (int i : ab)
    EXPECT_GE(mesh.nodes[i].y(), 19.9);
  int bottom = 0;
  for (const auto& x : mesh.nodes)
    bottom += x.y() == 0.0;
  EXPECT_EQ(bottom, 1);
  EXPECT_GE(find_node(mesh, {0, 0}), 0);
  EXPECT_EQ(ring({0, 10}, 9, 10, 256).num_cells(), 6144); // thesis, N = 256
}

TEST(Ring, ExactMirrorSymmetry) {
  // x1 - cx is exact for cx = 0 and within one binade (cx = 100); cx = 12 spans 2 .. 22.
  for (const Eigen::Vector2d& c :
       {Eigen::Vector2d(0, 10), Eigen::Vector2d(100, 100), Eigen::Vector2d(12, 5)}) {
    const int N = 64, layers = 4;
    const Mesh mesh = ring(c, 9, 10, N, {layers, {}, {}});
    EXPECT_EQ(mesh.num_nodes(), N * layers);
    EXPECT_EQ(mesh.num_cells(), 2 * N * (layers - 1));
    // Bits of (x1 - cx, x2) -> node; each node's mirror has -(x1 - cx) bit for bit.
    std::map<std::pair<std::uint64_t, std::uint64_t>, int> at;
    auto key = [](double dx, double y) {
      return std::make_pair(std::bit_cast<std::uint64_t>(dx + 0.0),
                            std::bit_cast<std::uint64_t>(y));
    };
    for (int i = 0; i < mesh.num_nodes(); ++i)
      at[key(mesh.nodes[i].x() - c.x(), mesh.nodes[i].y())] = i;
    std::vector<int> mirror(mesh.num_nodes(), -1);
    for (int i = 0; i < mesh.num_nodes(); ++i) {
      const auto it = at.find(key(-(mesh.nodes[i].x() - c.x()), mesh.nodes[i].y()));
      ASSERT_NE(it, at.end()) << "node " << i << " has no exact mirror";
      mirror[i] = it->second;
      EXPECT_EQ(std::abs(mesh.nodes[i].x() - c.x()), std::abs(mesh.nodes[mirror[i]].x() - c.x()));
      EXPECT_EQ(mesh.vertex_ref[i], mesh.vertex_ref[mirror[i]]);
    }
    // Triangles and referenced edges map onto triangles and edges of the same reference.
    std::set<std::array<int, 3>> triangles;
    for (const auto& cell : mesh.cells) {
      std::array<int, 3> t{cell[0], cell[1], cell[2]};
      std::sort(t.begin(), t.end());
      triangles.insert(t);
    }
    for (const auto& t : mesh.cells) {
      std::array<int, 3> m = {mirror[t[0]], mirror[t[1]], mirror[t[2]]};
      std::sort(m.begin(), m.end());
      EXPECT_TRUE(triangles.count(m));
    }
    std::map<std::uint64_t, int> edges;
    for (const auto& e : mesh.facets)
      edges[edge_key(e.node[0], e.node[1])] = e.ref;
    for (const auto& e : mesh.facets)
      EXPECT_EQ(edges.at(edge_key(mirror[e.node[0]], mirror[e.node[1]])), e.ref);
    expect_domain_on_the_left(mesh);
    const double polygon = N * 0.5 * std::sin(2 * std::numbers::pi / N) * (100 - 81);
    EXPECT_NEAR(area(mesh), polygon, 1e-9);
  }
}

TEST(Ring, DefaultLayers) {
  EXPECT_EQ(default_ring_layers(128), 7);
  EXPECT_EQ(default_ring_layers(256), 13);
  EXPECT_EQ(default_ring_layers(512), 25);
  EXPECT_EQ(default_ring_layers(16), 2);
  EXPECT_THROW(ring({0, 0}, 10, 9, 16), Error);
  EXPECT_THROW(ring({0, 0}, 9, 10, 15), Error);
}

TEST(Rectangle, CountsReferencesAndArea) {
  const Mesh mesh = rectangle(5, 1, 10, 2);
  EXPECT_EQ(mesh.num_nodes(), 33);
  EXPECT_EQ(mesh.num_cells(), 40);
  EXPECT_EQ(mesh.facets_with_ref(3).size(), 10u); // bottom
  EXPECT_EQ(mesh.facets_with_ref(4).size(), 2u);  // right
  EXPECT_EQ(mesh.facets_with_ref(2).size(), 10u); // top
  EXPECT_EQ(mesh.facets_with_ref(1).size(), 2u);  // left
  for (int i : mesh.nodes_with_ref(3))
    EXPECT_EQ(mesh.nodes[i].y(), 0.0);
  for (int i : mesh.nodes_with_ref(4))
    EXPECT_EQ(mesh.nodes[i].x(), 5.0);
  EXPECT_EQ(mesh.vertex_ref[find_node(mesh, {0, 0})], 3);
  EXPECT_EQ(mesh.vertex_ref[find_node(mesh, {5, 0})], 3);
  EXPECT_EQ(mesh.vertex_ref[find_node(mesh, {0, 1})], 2);
  EXPECT_EQ(mesh.vertex_ref[find_node(mesh, {5, 1})], 2);
  EXPECT_NEAR(area(mesh), 5.0, 1e-12);
  expect_domain_on_the_left(mesh);
  // Alternating diagonals: both directions occur, and node (1, 1) (index 12) has 8 triangles.
  int around = 0;
  for (const auto& t : mesh.cells)
    around += std::count(t.begin(), t.end(), 12);
  EXPECT_EQ(around, 8);

  const Mesh sq = square(1, 4, {1, 1, 2, 1});
  EXPECT_EQ(sq.num_nodes(), 25);
  EXPECT_EQ(sq.facets_with_ref(1).size(), 12u);
  EXPECT_EQ(sq.references(), (std::vector<int>{1, 2}));
}

// The thesis's scene 5 mesh (ALGORITHMS.md 0.2): 64 x 12 union-jack cells on (0,5) x (0,1) have
// 3072 triangles and 1613 nodes, i.e. 3226 displacement dofs plus 2 x 64 multipliers = 3354.
TEST(Rectangle, UnionJackIsTheThesisScene5Mesh) {
  const Mesh mesh = rectangle(5, 1, 64, 12, {3, 4, 2, 1}, CellPattern::union_jack);
  EXPECT_EQ(mesh.num_cells(), 3072);
  EXPECT_EQ(mesh.num_nodes(), 1613);
  EXPECT_EQ(2 * mesh.num_nodes() + 2 * 64, 3354);
  EXPECT_EQ(mesh.facets_with_ref(3).size(), 64u);
  EXPECT_EQ(mesh.nodes_with_ref(3).size(), 65u);
  EXPECT_NEAR(area(mesh), 5.0, 1e-12);
  expect_domain_on_the_left(mesh);
  // Every centre has four triangles, every inner corner eight.
  const int centre = 65 * 13 + 5 * 64 + 7, corner = 3 * 65 + 4;
  EXPECT_EQ(mesh.nodes[centre], Eigen::Vector2d(5.0 * 7.5 / 64, 5.5 / 12));
  int at_centre = 0, at_corner = 0;
  for (const auto& t : mesh.cells) {
    at_centre += std::count(t.begin(), t.end(), centre);
    at_corner += std::count(t.begin(), t.end(), corner);
  }
  EXPECT_EQ(at_centre, 4);
  EXPECT_EQ(at_corner, 8);
}

// Halving the cells of a union-jack mesh nests the meshes: every coarse node is a fine node and
// every coarse edge's midpoint is a fine node, so coarse P1 fields prolongate exactly.
TEST(Rectangle, UnionJackRefinementIsNested) {
  const Mesh coarse = rectangle(5, 1, 8, 2, {3, 4, 2, 1}, CellPattern::union_jack);
  const Mesh fine = rectangle(5, 1, 16, 4, {3, 4, 2, 1}, CellPattern::union_jack);
  const auto is_fine_node = [&](const Eigen::Vector2d& x) {
    for (const Point& y : fine.nodes)
      if ((x - y).norm() < 1e-12) return true;
    return false;
  };
  for (const Point& x : coarse.nodes)
    EXPECT_TRUE(is_fine_node(x));
  for (const auto& t : coarse.cells)
    for (int j = 0; j < 3; ++j)
      EXPECT_TRUE(is_fine_node(0.5 * (coarse.nodes[t[j]] + coarse.nodes[t[(j + 1) % 3]])));
}

} // namespace
} // namespace sig
