// Obstacles: signed distance and normal against closed forms, n = grad d by finite differences,
// the projection lands on the boundary, invalid data is refused.
#include "contact/obstacle.hpp"
#include "core/error.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <vector>

namespace sig {
namespace {

const std::vector<Eigen::Vector2d> kPoints = {{0.3, 0.7},   {-2, 5},    {4, -1},
                                              {1e-8, 1e-8}, {100, 1e3}, {-0.5, 0.25}};

// The outward normal of a distance function is its gradient (|grad d| = 1).
void expect_normal_is_gradient(const Obstacle& obstacle, const Eigen::Vector2d& x) {
  const double h = 1e-6 * (1 + x.norm());
  Eigen::Vector2d grad;
  for (int k = 0; k < 2; ++k) {
    Eigen::Vector2d e = Eigen::Vector2d::Zero();
    e(k) = h;
    grad(k) = (obstacle.signed_distance(x + e) - obstacle.signed_distance(x - e)) / (2 * h);
  }
  EXPECT_NEAR((grad - obstacle.normal(x)).norm(), 0, 1e-6) << "at " << x.transpose();
}

TEST(HalfPlane, FoundationDistanceIsHeight) {
  const HalfPlane foundation({0, 0}, {0, 1});
  for (const auto& x : kPoints) {
    EXPECT_DOUBLE_EQ(foundation.signed_distance(x), x.y());
    EXPECT_EQ(foundation.normal(x), Eigen::Vector2d(0, 1));
    expect_normal_is_gradient(foundation, x);
  }
  EXPECT_EQ(foundation.kind(), "plane");
}

TEST(HalfPlane, TiltedPlaneNormalizesItsNormal) {
  const Eigen::Vector2d p(1, -2), raw(3, 4); // |raw| = 5
  const HalfPlane plane(p, raw);
  for (const auto& x : kPoints) {
    EXPECT_NEAR(plane.signed_distance(x), (x - p).dot(raw) / 5, 1e-12 * (1 + x.norm()));
    EXPECT_NEAR((plane.normal(x) - raw / 5).norm(), 0, 1e-15);
    EXPECT_NEAR(plane.signed_distance(plane.projection(x)), 0, 1e-12 * (1 + x.norm()));
    expect_normal_is_gradient(plane, x);
  }
  // Outside = the side the normal points to.
  EXPECT_GT(plane.signed_distance(p + 0.1 * raw), 0);
  EXPECT_LT(plane.signed_distance(p - 0.1 * raw), 0);
}

TEST(HalfPlane, ZeroLengthNormalIsAnError) {
  EXPECT_THROW(HalfPlane({0, 0}, {0, 0}), Error);
  EXPECT_THROW(HalfPlane({0, 0}, {NAN, 1}), Error);
}

TEST(Disc, DistanceAndNormalAgainstClosedForm) {
  const Eigen::Vector2d c(10, 10);
  const Disc disc(c, 10);
  EXPECT_EQ(disc.kind(), "disc");
  for (const auto& x : kPoints) {
    const double r = (x - c).norm();
    EXPECT_NEAR(disc.signed_distance(x), r - 10, 1e-12 * (1 + r));
    EXPECT_NEAR((disc.normal(x) - (x - c) / r).norm(), 0, 1e-14);
    EXPECT_NEAR(disc.normal(x).norm(), 1, 1e-15);
    // The projection lies on the circle and the normal there is the same.
    const Eigen::Vector2d q = disc.projection(x);
    EXPECT_NEAR((q - c).norm(), 10, 1e-12 * (1 + r));
    EXPECT_NEAR((disc.normal(q) - disc.normal(x)).norm(), 0, 1e-12);
    expect_normal_is_gradient(disc, x);
  }
  // A point on the circle, inside, outside.
  EXPECT_NEAR(disc.signed_distance({10, 0}), 0, 1e-15);
  EXPECT_EQ(disc.normal({10, 0}), Eigen::Vector2d(0, -1));
  EXPECT_DOUBLE_EQ(disc.signed_distance({10, 23}), 3);
  EXPECT_DOUBLE_EQ(disc.signed_distance({13, 10}), -7);
}

TEST(Disc, InvalidDataIsAnError) {
  EXPECT_THROW(Disc({0, 0}, 0), Error);
  EXPECT_THROW(Disc({0, 0}, -1), Error);
  const Disc disc({1, 2}, 3);
  EXPECT_THROW((void)disc.normal({1, 2}), Error); // undefined at the centre
}

TEST(MakeObstacle, RebuildsFromDescription) {
  const HalfPlane plane({1, 2}, {0, -2});
  const Disc disc({-1, 4}, 2.5);
  for (const Obstacle* original :
       {static_cast<const Obstacle*>(&plane), static_cast<const Obstacle*>(&disc)}) {
    const auto copy = make_obstacle(original->description());
    EXPECT_EQ(copy->kind(), original->kind());
    for (const auto& x : kPoints) {
      EXPECT_DOUBLE_EQ(copy->signed_distance(x), original->signed_distance(x));
      EXPECT_EQ(copy->normal(x), original->normal(x));
    }
  }
  EXPECT_THROW(make_obstacle({"polyline", {0, 0}, {0, 1}, 0}), Error);
}

// A cylinder of axis (1, 2, 2) / 3 through c: the distance of a point is that of its part normal
// to the axis, whatever its position along the axis; n = grad d; the projection keeps the
// position along the axis; the description rebuilds it.
TEST(Cylinder, DistanceAndNormalAgainstClosedForm) {
  const Eigen::Vector3d c(1, -2, 0.5), raw(1, 2, 2), a = raw / 3; // |raw| = 3
  const Cylinder cylinder(c, raw, 2);
  EXPECT_EQ(cylinder.kind(), "cylinder");
  EXPECT_EQ(cylinder.dim(), 3);
  const std::vector<Eigen::Vector3d> points = {{0.3, 0.7, -1},  {-2, 5, 4},   {4, -1, 0},
                                               {100, 1e3, -20}, {1, -2, 3.5}, {2.5, 0.1, -0.3}};
  for (const Eigen::Vector3d& x : points) {
    const Eigen::Vector3d radial = (x - c) - (x - c).dot(a) * a;
    const double r = radial.norm();
    EXPECT_NEAR(cylinder.signed_distance(x), r - 2, 1e-12 * (1 + x.norm()));
    // Sliding along the axis changes nothing.
    EXPECT_NEAR(cylinder.signed_distance(x + 7.5 * a), cylinder.signed_distance(x),
                1e-12 * (1 + x.norm()));
    const Eigen::Vector3d n = cylinder.normal(x);
    EXPECT_NEAR((n - radial / r).norm(), 0, 1e-13);
    EXPECT_NEAR(n.dot(a), 0, 1e-14);
    const Eigen::Vector3d q = cylinder.projection(x);
    EXPECT_NEAR(cylinder.signed_distance(q), 0, 1e-12 * (1 + x.norm()));
    EXPECT_NEAR((q - c).dot(a), (x - c).dot(a), 1e-12 * (1 + x.norm()));
    const double h = 1e-6 * (1 + x.norm());
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d e = h * Eigen::Vector3d::Unit(k);
      EXPECT_NEAR((cylinder.signed_distance(x + e) - cylinder.signed_distance(x - e)) / (2 * h),
                  n(k), 1e-6)
          << "at " << x.transpose();
    }
    const auto copy = make_obstacle(cylinder.description());
    EXPECT_EQ(copy->kind(), "cylinder");
    EXPECT_DOUBLE_EQ(copy->signed_distance(x), cylinder.signed_distance(x));
  }
  // Inside, on the surface, outside along the normal (0, 1, -1) / sqrt 2 to the axis.
  const Eigen::Vector3d m = Eigen::Vector3d(0, 1, -1) / std::sqrt(2.0);
  EXPECT_NEAR(cylinder.signed_distance(c + 0.5 * m), -1.5, 1e-14);
  EXPECT_NEAR(cylinder.signed_distance(c + 2 * m + 4 * a), 0, 1e-14);
  EXPECT_NEAR(cylinder.signed_distance(c + 5 * m), 3, 1e-14);
}

TEST(Cylinder, InvalidDataIsAnError) {
  EXPECT_THROW(Cylinder({0, 0, 0}, {1, 0, 0}, 0), Error);
  EXPECT_THROW(Cylinder({0, 0, 0}, {0, 0, 0}, 1), Error);
  EXPECT_THROW(Cylinder({0, 0}, {1, 0}, 1), Error); // 3D only
  EXPECT_THROW(Cylinder({0, 0, NAN}, {1, 0, 0}, 1), Error);
  const Cylinder cylinder({0, 0, 0}, {1, 0, 0}, 1);
  EXPECT_THROW((void)cylinder.normal({5, 0, 0}), Error); // undefined on the axis
}

} // namespace
} // namespace sig
