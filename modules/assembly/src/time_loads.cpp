#include "assembly/time_loads.hpp"

#include "core/error.hpp"

#include <array>
#include <cmath>

namespace sig {

namespace {

// 3-point Gauss-Legendre on [0, 1]: exact for polynomials of degree 5.
constexpr std::array<double, 3> kGaussPoint = {0.1127016653792583, 0.5, 0.8872983346207417};
constexpr std::array<double, 3> kGaussWeight = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};

// Pieces of at most this many 1 / sqrt(psi) in x1: the 3-point rule then errs by less than
// 3e-6 F w on a piece of width w wherever the Gaussian's centre is, and by 2e-8 of the whole
// load on an edge of 1 m at psi = 50 (a single rule there: -49 % to +77 %).
constexpr double kPieceWidth = 0.5;

} // namespace

double MovingLoad::magnitude(double x1, double t) const {
  const double s = x1 - x0 - c * t;
  return F * std::exp(-psi * s * s);
}

void MovingLoad::add(double t, Eigen::VectorXd& f) const {
  for (const MovingLoadPoint& p : points) {
    const double g = magnitude(p.x1, t);
    f[2 * p.node_a + 1] -= g * p.weight_a;
    f[2 * p.node_b + 1] -= g * p.weight_b;
  }
}

void MovingLoad::add_edge(int a, int b, const Eigen::Vector2d& xa, const Eigen::Vector2d& xb,
                          double thickness) {
  SIG_VERIFY(psi > 0, "moving load: psi = " << psi << " must be > 0");
  const double length = (xb - xa).norm();
  const int pieces = std::max(
      1, static_cast<int>(std::ceil(std::abs(xb.x() - xa.x()) * std::sqrt(psi) / kPieceWidth)));
  for (int k = 0; k < pieces; ++k)
    for (int q = 0; q < 3; ++q) {
      const double s = (k + kGaussPoint[q]) / pieces; // position along the edge, 0 at a
      const double w = kGaussWeight[q] * length * thickness / pieces;
      points.push_back({a, b, xa.x() + s * (xb.x() - xa.x()), w * (1.0 - s), w * s});
    }
}

Eigen::VectorXd TimeLoads::change(double t, int dofs) const {
  SIG_VERIFY(rate.size() == 0 || rate.size() == dofs,
             "time loads: a rate of " << rate.size() << " values for " << dofs << " dofs");
  Eigen::VectorXd f = rate.size() > 0 ? Eigen::VectorXd(t * rate) : Eigen::VectorXd::Zero(dofs);
  for (const MovingLoad& load : moving)
    for (const MovingLoadPoint& p : load.points) {
      const double dg = load.magnitude(p.x1, t) - load.magnitude(p.x1, 0.0);
      f[2 * p.node_a + 1] -= dg * p.weight_a;
      f[2 * p.node_b + 1] -= dg * p.weight_b;
    }
  return f;
}

} // namespace sig
