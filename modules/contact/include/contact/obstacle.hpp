#pragma once
// Rigid obstacles as signed-distance objects (GetFEM's habit): contact geometry only asks an
// obstacle for the signed distance d(x) and the outward normal n(x) at the projection of x, so
// the contact elements and every solver stay unaware of the obstacle's shape.
//
// Sign convention (fixed for the whole code): d(x) > 0 outside the obstacle, on the side where
// the deformable body lives; n(x) is the unit normal of the obstacle pointing from the obstacle
// into the body's side. The foundation of the thesis scenes, x2 <= 0, is
// HalfPlane({0, 0}, {0, 1}). Points have the mesh's dimension: a half plane and a disc in 2D, a
// half space, a ball (kind "sphere", its boundary) and an infinite circular cylinder (a wheel
// under a rail, a roller) in 3D, one class each but the cylinder's, which is 3D only.
#include "mesh/mesh.hpp"

#include <Eigen/Core>
#include <memory>
#include <string>

namespace sig {

/// What a contact DS stores about its obstacle, enough to rebuild it (make_obstacle).
struct ObstacleDescription {
  std::string kind; ///< "plane", "disc" (2D), "sphere" or "cylinder" (3D)
  Point point;  ///< plane: a boundary point; disc, sphere: centre; cylinder: a point of its axis
  Point normal; ///< plane: outward unit normal; cylinder: unit axis; disc, sphere: 0
  double radius = 0; ///< disc, sphere and cylinder only
};

class Obstacle {
public:
  virtual ~Obstacle() = default;
  /// d(x): distance to the obstacle boundary, > 0 on the body's side, < 0 inside.
  virtual double signed_distance(const Point& x) const = 0;
  /// n(proj(x)): outward unit normal of the obstacle at the projection of x on its boundary.
  virtual Point normal(const Point& x) const = 0;
  /// The dimension of the space it lives in: 2 or 3.
  virtual int dim() const = 0;
  virtual std::string kind() const = 0;
  virtual ObstacleDescription description() const = 0;
  /// proj(x) = x - d(x) n(x): exact for obstacles whose d is the true distance (all here).
  Point projection(const Point& x) const { return x - signed_distance(x) * normal(x); }
};

/// The half plane (half space in 3D) {x : (x - p).n <= 0}; the body lives where (x - p).n > 0.
class HalfPlane final : public Obstacle {
public:
  /// `normal` is normalized; a zero-length or non-finite normal, or a point and a normal of
  /// different dimensions (not 2 or 3), is a sig::Error.
  HalfPlane(const Point& point, const Point& normal);
  double signed_distance(const Point& x) const override { return (x - point_).dot(n_); }
  Point normal(const Point&) const override { return n_; }
  int dim() const override { return static_cast<int>(n_.size()); }
  std::string kind() const override { return "plane"; }
  ObstacleDescription description() const override;

private:
  Point point_, n_;
};

/// A rigid disc {x : |x - c| <= R} (a ball in 3D, kind "sphere"); the body lives outside it. The
/// normal is undefined at the centre, where asking for it is a sig::Error.
class Disc final : public Obstacle {
public:
  Disc(const Point& centre, double radius); ///< radius > 0, centre of 2 or 3 components
  double signed_distance(const Point& x) const override;
  Point normal(const Point& x) const override;
  int dim() const override { return static_cast<int>(centre_.size()); }
  std::string kind() const override { return dim() == 3 ? "sphere" : "disc"; }
  ObstacleDescription description() const override;

private:
  Point centre_;
  double radius_;
};

/// A rigid circular cylinder {x : |(x - c) - ((x - c).a) a| <= R} of axis a through c, infinite
/// along a (3D only); the body lives outside it. Its distance is that of the disc in the plane
/// normal to the axis, so the normal has no component along the axis, and is undefined on it.
class Cylinder final : public Obstacle {
public:
  /// `axis` is normalized; radius > 0; centre and axis of 3 components, a non-zero axis.
  Cylinder(const Point& centre, const Point& axis, double radius);
  double signed_distance(const Point& x) const override { return radial(x).norm() - radius_; }
  Point normal(const Point& x) const override;
  int dim() const override { return 3; }
  std::string kind() const override { return "cylinder"; }
  ObstacleDescription description() const override;

private:
  /// x - c without its component along the axis.
  Point radial(const Point& x) const;
  Point centre_, axis_;
  double radius_;
};

/// Rebuild an obstacle from its description (as read back from a CONT file).
std::unique_ptr<Obstacle> make_obstacle(const ObstacleDescription& description);

} // namespace sig
