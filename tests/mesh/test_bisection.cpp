// Longest-edge bisection (mesh/bisection.hpp): conforming, every reference and sub-domain kept,
// new nodes of curved boundaries on the circle, angles bounded, the node limit enforced. On each
// generator and on a gmsh and a FreeFem file.
#include "core/datafile.hpp"
#include "core/error.hpp"
#include "mesh/bisection.hpp"
#include "mesh/generators.hpp"
#include "mesh/mesh_card.hpp"
#include "mesh_testing.hpp"

#include <algorithm>
#include <map>
#include <numbers>

namespace sig {
namespace {

double area(const Mesh& mesh, int subdomain) {
  double sum = 0;
  for (int t = 0; t < mesh.num_cells(); ++t)
    if (mesh.subdomain[t] == subdomain) sum += 0.5 * signed_double_area(mesh, t);
  return sum;
}

double total_length(const Mesh& mesh, const std::vector<Facet>& edges) {
  double sum = 0;
  for (const Facet& e : edges)
    sum += (mesh.nodes[e.node[0]] - mesh.nodes[e.node[1]]).norm();
  return sum;
}

/// The edges that one triangle only has: the boundary, and every side of a hanging node.
std::vector<Facet> lone_edges(const Mesh& mesh) {
  std::map<std::uint64_t, int> uses;
  for (const auto& v : mesh.cells)
    for (int k = 0; k < 3; ++k)
      ++uses[edge_key(v[k], v[(k + 1) % 3])];
  std::vector<Facet> lone;
  for (const auto& [key, count] : uses) {
    EXPECT_LE(count, 2) << "an edge of more than two triangles";
    if (count == 1)
      lone.push_back({Simplex{static_cast<int>(key >> 32), static_cast<int>(key & 0xffffffff)}, 0});
  }
  return lone;
}

/// Smallest angle of the mesh, in radians.
double smallest_angle(const Mesh& mesh) {
  double smallest = std::numbers::pi;
  for (const auto& v : mesh.cells)
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector2d p = mesh.nodes[v[(k + 1) % 3]] - mesh.nodes[v[k]];
      const Eigen::Vector2d q = mesh.nodes[v[(k + 2) % 3]] - mesh.nodes[v[k]];
      smallest = std::min(smallest, std::acos(p.dot(q) / (p.norm() * q.norm())));
    }
  return smallest;
}

/// What every refinement keeps, on a mesh with straight sides: the area of each sub-domain, the
/// boundary (no hanging node: the lone edges are as long as before), each reference with its
/// length on edges of the refined triangles, and the vertex references.
void expect_kept(const Mesh& coarse, const Bisection& refined) {
  const Mesh& fine = refined.mesh;
  EXPECT_EQ(fine.num_nodes(), coarse.num_nodes() + refined.bisected_edges);
  EXPECT_EQ(fine.subdomains(), coarse.subdomains());
  for (int s : coarse.subdomains())
    EXPECT_NEAR(area(fine, s), area(coarse, s), 1e-12 * area(coarse, s)) << "sub-domain " << s;
  EXPECT_NEAR(total_length(fine, lone_edges(fine)), total_length(coarse, lone_edges(coarse)),
              1e-12 * total_length(coarse, lone_edges(coarse)));
  EXPECT_EQ(fine.references(), coarse.references());
  for (int ref : coarse.references()) {
    const double before = total_length(coarse, coarse.facets_with_ref(ref));
    EXPECT_NEAR(total_length(fine, fine.facets_with_ref(ref)), before, 1e-12 * (1 + before))
        << "reference " << ref;
  }
  for (int i = 0; i < coarse.num_nodes(); ++i)
    EXPECT_EQ(fine.vertex_ref[i], coarse.vertex_ref[i]) << "node " << i + 1;
}

TEST(Bisection, OneMarkedTriangleStaysConformingWithItsReferences) {
  const Mesh coarse = square(1.0, 4);
  const Bisection refined = bisect(coarse, {0});
  expect_kept(coarse, refined);
  EXPECT_GT(refined.mesh.num_cells(), coarse.num_cells() + 1);
}

TEST(Bisection, EveryTriangleMarkedQuartersIt) {
  const Mesh coarse = rectangle(2.0, 1.0, 4, 2);
  std::vector<int> all(coarse.cells.size());
  for (int t = 0; t < coarse.num_cells(); ++t)
    all[t] = t;
  const Bisection refined = bisect(coarse, all);
  expect_kept(coarse, refined);
  EXPECT_EQ(refined.mesh.num_cells(), 4 * coarse.num_cells());
  EXPECT_EQ(refined.mesh.num_nodes(), 9 * 5);
}

TEST(Bisection, RepeatedRefinementAtACornerKeepsTheAngles) {
  Mesh mesh = square(1.0, 2);
  const double initial = smallest_angle(mesh);
  for (int step = 0; step < 10; ++step) {
    // The triangles at the origin.
    std::vector<int> marked;
    for (int t = 0; t < mesh.num_cells(); ++t)
      for (int v : mesh.cells[t])
        if (mesh.nodes[v].norm() == 0) marked.push_back(t);
    const Bisection refined = bisect(mesh, marked);
    expect_kept(mesh, refined);
    mesh = refined.mesh;
  }
  EXPECT_GE(smallest_angle(mesh), 0.5 * initial - 1e-12);
  EXPECT_GT(mesh.num_cells(), 40);
}

TEST(Bisection, SubdomainsOfAFreeFemFileAndReferencesOfAGmshFile) {
  for (const auto& path :
       {testing::legacy_mesh("tworeg.msh"),
        std::filesystem::path(SIG_SOURCE_DIR) / "tests/fuzz/corpus/gmsh/square_v41_ascii.msh"}) {
    const Mesh coarse = read_mesh_file(path);
    std::vector<int> marked;
    for (int t = 0; t < coarse.num_cells(); t += 3)
      marked.push_back(t);
    expect_kept(coarse, bisect(coarse, marked));
  }
}

/// Every triangle refined: the new nodes of the arcs' edges on their circles.
void expect_arc_nodes_on_circle(const Mesh& coarse, const std::vector<BoundaryArc>& arcs) {
  std::vector<int> marked;
  for (int t = 0; t < coarse.num_cells(); ++t)
    marked.push_back(t);
  const Bisection refined = bisect(coarse, marked, arcs);
  const Mesh& fine = refined.mesh;
  EXPECT_EQ(fine.references(), coarse.references());
  EXPECT_EQ(fine.subdomains(), coarse.subdomains());
  for (const BoundaryArc& arc : arcs) {
    const std::vector<int> nodes = fine.nodes_with_ref(arc.ref);
    // A new node per edge (the ring's inner circle is closed, the arcs are open).
    EXPECT_EQ(nodes.size(),
              coarse.nodes_with_ref(arc.ref).size() + coarse.facets_with_ref(arc.ref).size())
        << "ref " << arc.ref;
    for (int i : nodes)
      EXPECT_NEAR((fine.nodes[i] - arc.centre).norm(), arc.radius, 1e-12 * arc.radius)
          << "node " << i + 1 << " of reference " << arc.ref;
  }
  // The refined domain is the coarse one plus the slivers between the chords and the arcs.
  EXPECT_GT(area(fine, 1), area(coarse, 1));
}

std::vector<BoundaryArc> arcs_of(const std::string& card) {
  return boundary_arcs(Datafile::parse(card + "\n", "deck.dat").require("MESH"));
}

TEST(Bisection, RingArcsStayOnTheirCircles) {
  const std::string card = "MESH generator=ring centre=0,10 r_in=9 r_out=10 N=16 layers=3";
  const std::vector<BoundaryArc> arcs = arcs_of(card);
  ASSERT_EQ(arcs.size(), 3u);
  expect_arc_nodes_on_circle(
      mesh_from_card(Datafile::parse(card + "\n", "deck.dat").require("MESH"), "."), arcs);
}

TEST(Bisection, HalfDiscAndDiscArcsStayOnTheirCircles) {
  if (!testing::have_gmsh()) GTEST_SKIP() << "gmsh not installed";
  EXPECT_TRUE(arcs_of("MESH generator=rectangle lx=1 ly=1 nx=1 ny=1").empty());
  const auto half = arcs_of("MESH generator=half-disc R=2 N=8");
  ASSERT_EQ(half.size(), 1u);
  EXPECT_EQ(half[0].centre, Eigen::Vector2d(0, 2));
  expect_arc_nodes_on_circle(half_disc(2.0, 8), half);
  const auto whole = arcs_of("MESH generator=disc centre=1,3 R=0.5 N=8");
  ASSERT_EQ(whole.size(), 4u);
  expect_arc_nodes_on_circle(disc({1, 3}, 0.5, 8), whole);
}

/// The MESH card's mesh refined twice where every third triangle is marked (the closure then
/// cuts its neighbours too), the arcs of the card's generator: each refinement keeps the coarse
/// mesh's references, Gamma3 (3) among them, and sub-domains, the vertex references of its nodes,
/// the length of each straight reference and every node of an arc's reference on its circle.
void expect_references_kept(const std::string& text) {
  SCOPED_TRACE(text);
  const Datafile deck = Datafile::parse(text + "\n", "deck.dat");
  const std::vector<BoundaryArc> arcs = boundary_arcs(deck.require("MESH"));
  Mesh mesh = mesh_from_card(deck.require("MESH"), SIG_SOURCE_DIR);
  ASSERT_FALSE(mesh.facets_with_ref(3).empty()) << "no Gamma3 to keep";
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<int> marked;
    for (int t = pass; t < mesh.num_cells(); t += 3)
      marked.push_back(t);
    const Bisection refined = bisect(mesh, marked, arcs);
    const Mesh& fine = refined.mesh;
    EXPECT_EQ(fine.num_nodes(), mesh.num_nodes() + refined.bisected_edges);
    EXPECT_GT(fine.facets_with_ref(3).size(), mesh.facets_with_ref(3).size()) << "pass " << pass;
    EXPECT_EQ(fine.references(), mesh.references()) << "pass " << pass;
    EXPECT_EQ(fine.subdomains(), mesh.subdomains()) << "pass " << pass;
    for (int i = 0; i < mesh.num_nodes(); ++i)
      ASSERT_EQ(fine.vertex_ref[i], mesh.vertex_ref[i]) << "node " << i + 1 << ", pass " << pass;
    for (int ref : mesh.references()) {
      const auto arc = std::find_if(arcs.begin(), arcs.end(),
                                    [&](const BoundaryArc& a) { return a.ref == ref; });
      if (arc == arcs.end()) {
        const double before = total_length(mesh, mesh.facets_with_ref(ref));
        EXPECT_NEAR(total_length(fine, fine.facets_with_ref(ref)), before, 1e-12 * (1 + before))
            << "reference " << ref << ", pass " << pass;
        continue;
      }
      for (int i : fine.nodes_with_ref(ref))
        ASSERT_NEAR((fine.nodes[i] - arc->centre).norm(), arc->radius, 1e-12 * arc->radius)
            << "node " << i + 1 << " of reference " << ref << ", pass " << pass;
    }
    mesh = fine;
  }
}

// The generators' cards as the scenes' decks write them, smaller: scene 4's square, scene 5's
// union-jack strip, the thin slab's refs, the rim's ring with its Gamma1 and Gamma3 cut-offs;
// scene 7a's graded half disc and the disc need gmsh; a gmsh file (MESH file=).
TEST(Bisection, EveryGeneratorAndAGmshFileKeepGamma3AndEveryReference) {
  expect_references_kept("MESH generator=square lx=1 nx=4");
  expect_references_kept("MESH generator=rectangle lx=5 ly=1 nx=8 ny=2 pattern=union-jack "
                         "refs=3,4,2,1");
  expect_references_kept("MESH generator=rectangle lx=2 ly=0.1 nx=8 ny=4 refs=3,1,2,1");
  expect_references_kept("MESH generator=ring centre=0,10 r_in=9 r_out=10 N=32 "
                         "gamma1_above=19.9 gamma3_below=17.08");
  expect_references_kept("MESH file=tests/fuzz/corpus/gmsh/square_v41_ascii.msh");
  if (!testing::have_gmsh()) GTEST_SKIP() << "gmsh not installed";
  expect_references_kept("MESH generator=half-disc R=8 N=16 grading=0.1");
  expect_references_kept("MESH generator=disc centre=10,10 R=10 N=16 grading=0.03 arcs=uniform");
}

TEST(Bisection, RefusesToPassTheNodeLimit) {
  const Mesh coarse = square(1.0, 4);
  try {
    bisect(coarse, {0, 1, 2}, {}, coarse.num_nodes() + 1);
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("beyond the limit"), std::string::npos) << e.what();
  }
  EXPECT_EQ(max_mesh_nodes, 1e8);
}

} // namespace
} // namespace sig
