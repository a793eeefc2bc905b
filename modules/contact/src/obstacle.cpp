#include "contact/obstacle.hpp"

#include "core/error.hpp"

#include <cmath>

namespace sig {

HalfPlane::HalfPlane(const Eigen::Vector2d& point, const Eigen::Vector2d& normal) : point_(point) {
  const double length = normal.norm();
  SIG_VERIFY(std::isfinite(length) && length > 0,
             "half plane: the normal (" << normal.x() << ", " << normal.y()
                                        << ") has zero length; give the outward normal of the "
                                           "obstacle, e.g. (0, 1) for the foundation x2 <= 0");
  SIG_VERIFY(point.allFinite(), "half plane: the point is not finite");
  n_ = normal / length;
}

ObstacleDescription HalfPlane::description() const {
  return {"plane", point_, n_, 0.0};
}

Disc::Disc(const Eigen::Vector2d& centre, double radius) : centre_(centre), radius_(radius) {
  SIG_VERIFY(std::isfinite(radius) && radius > 0,
             "disc obstacle: radius " << radius << " must be > 0");
  SIG_VERIFY(centre.allFinite(), "disc obstacle: the centre is not finite");
}

double Disc::signed_distance(const Eigen::Vector2d& x) const {
  return (x - centre_).norm() - radius_;
}

Eigen::Vector2d Disc::normal(const Eigen::Vector2d& x) const {
  const Eigen::Vector2d radial = x - centre_;
  const double length = radial.norm();
  SIG_VERIFY(length > 0, "disc obstacle: the normal is undefined at the centre ("
                             << centre_.x() << ", " << centre_.y() << ")");
  return radial / length;
}

ObstacleDescription Disc::description() const {
  return {"disc", centre_, Eigen::Vector2d::Zero(), radius_};
}

std::unique_ptr<Obstacle> make_obstacle(const ObstacleDescription& description) {
  if (description.kind == "plane")
    return std::make_unique<HalfPlane>(description.point, description.normal);
  if (description.kind == "disc")
    return std::make_unique<Disc>(description.point, description.radius);
  SIG_VERIFY(false, "obstacle kind '" << description.kind << "' is unknown; known: plane, disc");
  return nullptr; // not reached
}

} // namespace sig
