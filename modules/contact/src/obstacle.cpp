#include "contact/obstacle.hpp"

#include "core/error.hpp"

#include <cmath>

namespace sig {

HalfPlane::HalfPlane(const Point& point, const Point& normal) : point_(point) {
  SIG_VERIFY((normal.size() == 2 || normal.size() == 3) && point.size() == normal.size(),
             "half plane: a point of " << point.size() << " and a normal of " << normal.size()
                                       << " components; both must have 2 (2D) or 3 (3D)");
  const double length = normal.norm();
  SIG_VERIFY(std::isfinite(length) && length > 0,
             "half plane: the normal " << coordinates(normal)
                                       << " has zero length; give the outward normal of the "
                                          "obstacle, e.g. (0, 1) for the foundation x2 <= 0");
  SIG_VERIFY(point.allFinite(), "half plane: the point is not finite");
  n_ = normal / length;
}

ObstacleDescription HalfPlane::description() const {
  return {"plane", point_, n_, 0.0};
}

Disc::Disc(const Point& centre, double radius) : centre_(centre), radius_(radius) {
  SIG_VERIFY(centre.size() == 2 || centre.size() == 3,
             "disc obstacle: a centre of " << centre.size() << " components; 2 or 3");
  SIG_VERIFY(std::isfinite(radius) && radius > 0,
             kind() << " obstacle: radius " << radius << " must be > 0");
  SIG_VERIFY(centre.allFinite(), kind() << " obstacle: the centre is not finite");
}

double Disc::signed_distance(const Point& x) const {
  return (x - centre_).norm() - radius_;
}

Point Disc::normal(const Point& x) const {
  const Point radial = x - centre_;
  const double length = radial.norm();
  SIG_VERIFY(length > 0,
             kind() << " obstacle: the normal is undefined at the centre " << coordinates(centre_));
  return radial / length;
}

ObstacleDescription Disc::description() const {
  return {kind(), centre_, Point(Point::Zero(centre_.size())), radius_};
}

Cylinder::Cylinder(const Point& centre, const Point& axis, double radius)
    : centre_(centre), radius_(radius) {
  SIG_VERIFY(centre.size() == 3 && axis.size() == 3,
             "cylinder obstacle: a centre of " << centre.size() << " and an axis of " << axis.size()
                                               << " components; a cylinder is 3D (3 each)");
  SIG_VERIFY(std::isfinite(radius) && radius > 0,
             "cylinder obstacle: radius " << radius << " must be > 0");
  SIG_VERIFY(centre.allFinite(), "cylinder obstacle: the centre is not finite");
  const double length = axis.norm();
  SIG_VERIFY(std::isfinite(length) && length > 0,
             "cylinder obstacle: the axis " << coordinates(axis) << " has zero length");
  axis_ = axis / length;
}

Point Cylinder::radial(const Point& x) const {
  const Point r = x - centre_;
  return r - r.dot(axis_) * axis_;
}

Point Cylinder::normal(const Point& x) const {
  const Point r = radial(x);
  const double length = r.norm();
  SIG_VERIFY(length > 0,
             "cylinder obstacle: the normal is undefined on the axis, at " << coordinates(x));
  return r / length;
}

ObstacleDescription Cylinder::description() const {
  return {"cylinder", centre_, axis_, radius_};
}

std::unique_ptr<Obstacle> make_obstacle(const ObstacleDescription& description) {
  if (description.kind == "plane")
    return std::make_unique<HalfPlane>(description.point, description.normal);
  if (description.kind == "disc" || description.kind == "sphere") {
    SIG_VERIFY(description.point.size() == (description.kind == "sphere" ? 3 : 2),
               "a " << description.kind << " obstacle with a centre of " << description.point.size()
                    << " components");
    return std::make_unique<Disc>(description.point, description.radius);
  }
  if (description.kind == "cylinder")
    return std::make_unique<Cylinder>(description.point, description.normal, description.radius);
  SIG_VERIFY(false, "obstacle kind '" << description.kind
                                      << "' is unknown; known: plane, disc, sphere, cylinder");
  return nullptr; // not reached
}

} // namespace sig
