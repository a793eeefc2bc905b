#pragma once
// The loads that change in time. The TAE's load vector f is the load at t = 0 (what a static
// deck solves with); a march applies f(t) = f + change(t), change(0) = 0.
//
//   TRACTION, PRESSURE, BODYFORCE ... ramp=t1   a load growing linearly, t / t1 times its value
//       (assembly/loads.hpp): change(t) = t rate, rate the sum of the ramped loads over t1.
//
//   MOVINGLOAD ref=R F= psi= c= [x0=0]   the thesis's moving mass (6.91): the traction
//       (0, -F exp(-psi (x1 - x0 - c t)^2)) on the edges of reference R, a Gaussian of x1 whose
//       centre x0 + c t moves at speed c (vertical whatever the edge's direction, as (6.91)).
//
// The Gaussian is integrated against the P1 basis of each edge by a composite 3-point Gauss
// rule (ALGORITHMS.md C11) whose pieces span at most 1 / (2 sqrt(psi)) in x1: a single 3-point
// rule on a coarse edge (1 m at h = 1/2 against a Gaussian of standard deviation 0.1 m) misses
// the load by up to 77 % (tests/assembly/test_time_loads.cpp), the composite one by 2e-8. The
// points do not depend on t: they are laid out once, and the nodal forces at any t cost one
// exponential per point.
#include <Eigen/Core>

#include <vector>

namespace sig {

/// One quadrature point of a moving load on an edge [a, b]: the load's magnitude there times
/// weight_a (weight_b) is the vertical nodal force it puts on node a (b), downwards.
struct MovingLoadPoint {
  int node_a = 0, node_b = 0;        ///< 0-based mesh nodes
  double x1 = 0;                     ///< abscissa of the point
  double weight_a = 0, weight_b = 0; ///< Gauss weight x length x thickness x P1 basis of a, b
};

struct MovingLoad {
  double F = 0;   ///< peak traction
  double psi = 0; ///< > 0, per unit length squared (m^-2)
  double c = 0;   ///< speed of the centre
  double x0 = 0;  ///< centre at t = 0
  std::vector<MovingLoadPoint> points;

  /// F exp(-psi (x1 - x0 - c t)^2).
  double magnitude(double x1, double t) const;
  /// f += the nodal forces at time t (f of size 2 x nodes).
  void add(double t, Eigen::VectorXd& f) const;
  /// Lay out the quadrature points of the straight edge [xa, xb] (nodes a, b) of thickness
  /// `thickness`; psi must be set.
  void add_edge(int a, int b, const Eigen::Vector2d& xa, const Eigen::Vector2d& xb,
                double thickness);
};

struct TimeLoads {
  std::vector<MovingLoad> moving;
  /// The ramped loads per unit time (assembly/loads.hpp, ramp=): t rate at time t; empty: none.
  Eigen::VectorXd rate;

  bool empty() const { return moving.empty() && rate.size() == 0; }
  /// f(t) - f(0), of size `dofs`.
  Eigen::VectorXd change(double t, int dofs) const;
};

} // namespace sig
