// Contact geometry in 3D (issue 26): the nodal frames, the half space and the sphere, the contact
// elements of a face reference (tributary areas against an independent sum over the faces), B_N
// and the CONT round trip.
#include "contact/contact_elements.hpp"
#include "contact/obstacle.hpp"
#include "core/error.hpp"
#include "mesh/generators.hpp"
#include "scratch_folder.hpp"

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <cmath>
#include <gtest/gtest.h>
#include <map>
#include <vector>

namespace sig {
namespace {

const std::vector<Eigen::Vector3d> kNormals = {{0, 0, 1}, {0, 0, -1},      {1, 0, 0},
                                               {0, 1, 0}, {0.6, 0, 0.8},   {0.48, -0.6, 0.64},
                                               {1, 1, 1}, {-1, 1e-9, 1e-9}};

TEST(ContactFrame3d, OrthonormalWithMinusNormalLast) {
  for (Eigen::Vector3d n : kNormals) {
    n.normalize();
    const ContactFrame R = contact_frame(n);
    ASSERT_EQ(R.rows(), 3);
    EXPECT_NEAR((R.transpose() * R - Eigen::Matrix3d::Identity()).norm(), 0, 1e-14) << n;
    EXPECT_NEAR((R.col(2) + n).norm(), 0, 1e-15);
    // Oriented as the 2D frame (t, -n), whose determinant is -1.
    EXPECT_NEAR(Eigen::Matrix3d(R).determinant(), -1, 1e-14);
  }
}

TEST(ContactFrame3d, FoundationTangentsAreTheAxes) {
  const ContactFrame R = contact_frame(Eigen::Vector3d(0, 0, 1));
  EXPECT_EQ(Eigen::Vector3d(R.col(0)), Eigen::Vector3d(1, 0, 0));
  EXPECT_EQ(Eigen::Vector3d(R.col(1)), Eigen::Vector3d(0, 1, 0));
}

TEST(Obstacle3d, HalfSpaceAndSphere) {
  const HalfPlane plane(Point(0, 0, 1), Point(0, 0, 2));
  EXPECT_EQ(plane.dim(), 3);
  EXPECT_DOUBLE_EQ(plane.signed_distance(Point(5, -3, 4)), 3);
  EXPECT_EQ(plane.normal(Point(1, 2, 3)), Point(0, 0, 1));
  const Disc sphere(Point(1, 2, 3), 2);
  EXPECT_EQ(sphere.kind(), "sphere");
  EXPECT_DOUBLE_EQ(sphere.signed_distance(Point(1, 2, 8)), 3);
  EXPECT_NEAR((sphere.normal(Point(1, 5, 7)) - Point(0, 0.6, 0.8)).norm(), 0, 1e-15);
  EXPECT_NEAR((sphere.projection(Point(1, 5, 7)) - Point(1, 3.2, 4.6)).norm(), 0, 1e-15);
  EXPECT_EQ(Disc(Point(0, 0), 1).kind(), "disc");
  EXPECT_THROW(HalfPlane(Point(0, 0), Point(0, 0, 1)), Error);
  ObstacleDescription wrong = sphere.description();
  wrong.kind = "disc";
  EXPECT_THROW(make_obstacle(wrong), Error);
}

// The box [0, 2] x [0, 1] x [0, 1] on the plane x3 = 0: its base (reference 1) touches it.
const Mesh& box_mesh() {
  static const Mesh mesh = box(2, 1, 1, 0.5);
  return mesh;
}

TEST(ContactElements3d, TributaryAreasAreThirdsOfTheFaces) {
  const Mesh& mesh = box_mesh();
  const HalfPlane plane(Point(0, 0, 0), Point(0, 0, 1));
  const ContactElements e = build_contact_elements(mesh, 1, plane);
  EXPECT_EQ(e.dim, 3);
  std::map<int, double> third; // independent: a third of each base face's area per vertex
  for (const Facet& f : mesh.facets) {
    if (f.ref != 1) continue;
    const Eigen::Vector3d a = mesh.nodes[f.node[0]], b = mesh.nodes[f.node[1]],
                          c = mesh.nodes[f.node[2]];
    for (int k : f.node)
      third[k] += (b - a).cross(c - a).norm() / 6;
  }
  ASSERT_EQ(e.size(), static_cast<int>(third.size()));
  EXPECT_NEAR(e.weight.sum(), 2.0, 1e-12); // the base's area
  for (int i = 0; i < e.size(); ++i) {
    EXPECT_NEAR(e.weight[i], third.at(e.node[i]), 1e-15);
    EXPECT_NEAR(mesh.nodes[e.node[i]].z(), 0, 1e-12);
    EXPECT_EQ(e.gap[i], 0);
    EXPECT_EQ(e.normal[i], Point(0, 0, 1));
    EXPECT_EQ(e.tangent[i], Point(1, 0, 0));
    EXPECT_EQ(e.lagrange_node[i], mesh.num_nodes() + i);
    if (i > 0) {
      EXPECT_LT(e.node[i - 1], e.node[i]); // node order in 3D
    }
  }
  EXPECT_TRUE(nodes_facing_away(mesh, e).empty());
  // The obstacle given the wrong way round faces every node from inside.
  const HalfPlane inverted(Point(0, 0, 2), Point(0, 0, -1)); // above the box, facing down
  EXPECT_EQ(nodes_facing_away(mesh, build_contact_elements(mesh, 1, inverted)).size(),
            static_cast<std::size_t>(e.size()));
}

TEST(ContactElements3d, NormalOperatorIsMinusNormalDotU) {
  const Mesh& mesh = box_mesh();
  const Disc sphere(Point(1, 0.5, -3), 3); // touches the base at its centre
  const ContactElements e = build_contact_elements(mesh, 1, sphere);
  const int ndof = 3 * mesh.num_nodes();
  const Eigen::VectorXd u = Eigen::VectorXd::LinSpaced(ndof, -1, 2);
  const Eigen::VectorXd un = normal_operator(e, ndof) * u;
  for (int i = 0; i < e.size(); ++i) {
    const Eigen::Vector3d ui = u.segment<3>(3 * e.node[i]);
    EXPECT_NEAR(un[i], -Eigen::Vector3d(e.normal[i]).dot(ui), 1e-14);
    EXPECT_NEAR(e.gap[i], sphere.signed_distance(mesh.nodes[e.node[i]]), 1e-15);
  }
}

TEST(ContactElements3d, NodeInsideTheObstacleIsRefused) {
  const HalfPlane above(Point(0, 0, 0.1), Point(0, 0, 1));
  EXPECT_THROW(build_contact_elements(box_mesh(), 1, above), Error);
  const HalfPlane flat(Point(0, 0), Point(0, 1));
  EXPECT_THROW(build_contact_elements(box_mesh(), 1, flat), Error); // a 2D obstacle
}

TEST(ContIo3d, RoundTripAndDimensionChecked) {
  static const testing::ScratchFolder dir;
  const Mesh& mesh = box_mesh();
  ContactLaw law;
  law.normal = NormalLaw::compliance;
  law.cn = 3;
  const ContactElements e = build_contact_elements(mesh, 1, Disc(Point(1, 0.5, -3), 3), law);
  write_cont(dir / "box.cont", e);
  const ContactElements back = read_cont(dir / "box.cont", mesh);
  EXPECT_EQ(back.dim, 3);
  EXPECT_EQ(back.node, e.node);
  EXPECT_EQ(back.normal, e.normal);
  EXPECT_EQ(back.tangent, e.tangent);
  EXPECT_EQ(back.gap, e.gap);
  EXPECT_EQ(back.weight, e.weight);
  EXPECT_EQ(back.law, e.law);
  EXPECT_EQ(back.obstacle.kind, "sphere");
  EXPECT_EQ(back.obstacle.point, e.obstacle.point);
  EXPECT_EQ(back.obstacle.radius, 3);
  // The file of a 3D mesh read against a 2D mesh of as many nodes is refused.
  Mesh flat = mesh;
  flat.dim = 2;
  for (Point& x : flat.nodes)
    x = Point(x.x(), x.y());
  EXPECT_THROW(read_cont(dir / "box.cont", flat), Error);
}

} // namespace
} // namespace sig
