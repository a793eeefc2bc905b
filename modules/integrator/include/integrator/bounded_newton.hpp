#pragma once
// The semi-smooth Newton method of the penalty-type strategies (specific penalty, IPM) on the
// condensed step of dynamic_contact.hpp: find x (p normal displacements) and mu such that
//     A (x - x_free) + phi(x) + mu = 0,
//     on `bounded` nodes:  x_i <= upper_i, mu_i >= 0, mu_i (x_i - upper_i) = 0;  else mu_i = 0,
// with phi a nodal, non-decreasing force law (phi_i depends on x_i only) and A symmetric
// positive definite: the optimality system of a strictly convex problem, so the Newton
// matrices A + diag(phi') are positive definite. Each iteration linearizes phi at the iterate,
// imposes x_i = upper_i on the active set and solves the rest (PDAS's step (iii) with the
// Newton step of the law); the active set is updated as in PDAS step (ii): an active node stays
// while its multiplier is >= 0, an inactive bounded node enters when it crosses its bound. The
// iteration stops when the active set is unchanged and the residual of the free rows is below
// tolerance times the forces of the step.
#include <Eigen/Core>

#include <functional>
#include <string>
#include <vector>

namespace sig {

/// phi(x) and its generalized derivative, node by node.
using NodalForceLaw =
    std::function<void(const Eigen::VectorXd& x, Eigen::VectorXd& force, Eigen::VectorXd& slope)>;

struct BoundedNewtonResult {
  Eigen::VectorXd x;
  Eigen::VectorXd lambda;     ///< phi(x) + mu: the nodal contact forces
  std::vector<char> on_bound; ///< the final active set
  bool converged = false;
  std::string failure;
  int iterations = 0; ///< linear solves
};

/// Starts from x_start with the active set {bounded, x_start >= upper}. `bounded` empty = no
/// bound anywhere.
BoundedNewtonResult bounded_newton(const Eigen::MatrixXd& A, const Eigen::VectorXd& x_free,
                                   const NodalForceLaw& law, const std::vector<char>& bounded,
                                   const Eigen::VectorXd& upper, const Eigen::VectorXd& x_start,
                                   int max_iterations, double tolerance);

} // namespace sig
