#pragma once
// Rigid obstacles as signed-distance objects (GetFEM's habit): contact geometry only asks an
// obstacle for the signed distance d(x) and the outward normal n(x) at the projection of x, so
// the contact elements and every solver stay unaware of the obstacle's shape.
//
// Sign convention (fixed for the whole code): d(x) > 0 outside the obstacle, on the side where
// the deformable body lives; n(x) is the unit normal of the obstacle pointing from the obstacle
// into the body's side. The foundation of the thesis scenes, x2 <= 0, is
// HalfPlane({0, 0}, {0, 1}).
#include <Eigen/Core>
#include <memory>
#include <string>

namespace sig {

/// What a contact DS stores about its obstacle, enough to rebuild it (make_obstacle).
struct ObstacleDescription {
  std::string kind;                                 ///< "plane" or "disc"
  Eigen::Vector2d point = Eigen::Vector2d::Zero();  ///< plane: a boundary point; disc: centre
  Eigen::Vector2d normal = Eigen::Vector2d::Zero(); ///< plane: outward unit normal; disc: 0
  double radius = 0;                                ///< disc only
};

class Obstacle {
public:
  virtual ~Obstacle() = default;
  /// d(x): distance to the obstacle boundary, > 0 on the body's side, < 0 inside.
  virtual double signed_distance(const Eigen::Vector2d& x) const = 0;
  /// n(proj(x)): outward unit normal of the obstacle at the projection of x on its boundary.
  virtual Eigen::Vector2d normal(const Eigen::Vector2d& x) const = 0;
  virtual std::string kind() const = 0;
  virtual ObstacleDescription description() const = 0;
  /// proj(x) = x - d(x) n(x): exact for obstacles whose d is the true distance (all here).
  Eigen::Vector2d projection(const Eigen::Vector2d& x) const {
    return x - signed_distance(x) * normal(x);
  }
};

/// The half plane {x : (x - p).n <= 0}; the body lives where (x - p).n > 0.
class HalfPlane final : public Obstacle {
public:
  /// `normal` is normalized; a zero-length or non-finite normal is a sig::Error.
  HalfPlane(const Eigen::Vector2d& point, const Eigen::Vector2d& normal);
  double signed_distance(const Eigen::Vector2d& x) const override { return (x - point_).dot(n_); }
  Eigen::Vector2d normal(const Eigen::Vector2d&) const override { return n_; }
  std::string kind() const override { return "plane"; }
  ObstacleDescription description() const override;

private:
  Eigen::Vector2d point_, n_;
};

/// A rigid disc {x : |x - c| <= R}; the body lives outside it. The normal is undefined at the
/// centre, where asking for it is a sig::Error.
class Disc final : public Obstacle {
public:
  Disc(const Eigen::Vector2d& centre, double radius); ///< radius > 0
  double signed_distance(const Eigen::Vector2d& x) const override;
  Eigen::Vector2d normal(const Eigen::Vector2d& x) const override;
  std::string kind() const override { return "disc"; }
  ObstacleDescription description() const override;

private:
  Eigen::Vector2d centre_;
  double radius_;
};

/// Rebuild an obstacle from its description (as read back from a CONT file).
std::unique_ptr<Obstacle> make_obstacle(const ObstacleDescription& description);

} // namespace sig
