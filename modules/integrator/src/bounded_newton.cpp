#include "integrator/bounded_newton.hpp"

#include "core/error.hpp"

#include <Eigen/Cholesky>
#include <cmath>

namespace sig {

namespace {

/// Below this relative Newton step the iterate no longer moves but by rounding: the residual
/// cannot decrease further and the active set is final.
constexpr double kRoundoffStep = 1e-14;

struct Residual {
  Eigen::VectorXd mu; ///< -R on the active nodes, 0 elsewhere
  double free_norm = 0;
  double scale = 0;
};

/// R = A (x - x_free) + phi(x): its free rows are the equations to solve, its active rows define
/// the multipliers mu = -R.
Residual residual(const Eigen::MatrixXd& A, const Eigen::VectorXd& x_free, const Eigen::VectorXd& x,
                  const Eigen::VectorXd& phi, const std::vector<char>& active) {
  const Eigen::VectorXd inertia = A * (x - x_free);
  const Eigen::VectorXd R = inertia + phi;
  Residual r;
  r.mu = Eigen::VectorXd::Zero(x.size());
  double sum = 0;
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    if (active[i])
      r.mu[i] = -R[i];
    else
      sum += R[i] * R[i];
  }
  r.free_norm = std::sqrt(sum);
  r.scale = inertia.norm() + phi.norm() + r.mu.norm();
  return r;
}

} // namespace

BoundedNewtonResult bounded_newton(const Eigen::MatrixXd& A, const Eigen::VectorXd& x_free,
                                   const NodalForceLaw& law, const std::vector<char>& bounded_in,
                                   const Eigen::VectorXd& upper, const Eigen::VectorXd& x_start,
                                   int max_iterations, double tolerance) {
  const auto p = x_free.size();
  SIG_VERIFY(A.rows() == p && A.cols() == p && x_start.size() == p,
             "bounded_newton: sizes disagree");
  const std::vector<char> bounded = bounded_in.empty() ? std::vector<char>(p, 0) : bounded_in;
  SIG_VERIFY(static_cast<Eigen::Index>(bounded.size()) == p &&
                 (bounded_in.empty() || upper.size() == p),
             "bounded_newton: one bound flag and value per node");

  BoundedNewtonResult s;
  Eigen::VectorXd x = x_start;
  std::vector<char> active(p, 0);
  for (Eigen::Index i = 0; i < p; ++i)
    if (bounded[i] && x[i] >= upper[i]) {
      active[i] = 1;
      x[i] = upper[i];
    }
  Eigen::VectorXd phi(p), slope(p);
  law(x, phi, slope);
  Residual r = residual(A, x_free, x, phi, active);
  bool done = r.free_norm <= tolerance * r.scale;
  for (Eigen::Index i = 0; i < p && done; ++i)
    done = !active[i] || r.mu[i] >= 0;

  while (!done && s.iterations < max_iterations) {
    ++s.iterations;
    // (A + diag(phi')) y = A x_free - phi + phi' x - mu, with y = upper on the active nodes.
    Eigen::MatrixXd M = A;
    M.diagonal() += slope;
    Eigen::VectorXd rhs = A * x_free - phi + slope.cwiseProduct(x);
    std::vector<Eigen::Index> free;
    Eigen::VectorXd y = Eigen::VectorXd::Zero(p);
    for (Eigen::Index i = 0; i < p; ++i) {
      if (active[i])
        y[i] = upper[i];
      else
        free.push_back(i);
    }
    const Eigen::VectorXd imposed = M * y;
    const auto nf = static_cast<Eigen::Index>(free.size());
    if (nf > 0) {
      Eigen::MatrixXd Mff(nf, nf);
      Eigen::VectorXd b(nf);
      for (Eigen::Index j = 0; j < nf; ++j) {
        for (Eigen::Index i = 0; i < nf; ++i)
          Mff(i, j) = M(free[i], free[j]);
        b[j] = rhs[free[j]] - imposed[free[j]];
      }
      const Eigen::LLT<Eigen::MatrixXd> cholesky(Mff);
      if (cholesky.info() != Eigen::Success) {
        s.failure = "the Newton matrix is not positive definite";
        break;
      }
      const Eigen::VectorXd yf = cholesky.solve(b);
      for (Eigen::Index j = 0; j < nf; ++j)
        y[free[j]] = yf[j];
    }
    const Eigen::VectorXd mu_linear = rhs - M * y; // meaningful on the active rows
    if (!y.allFinite()) {
      s.failure = "the Newton iterate is not finite";
      break;
    }
    const double step = (y - x).norm();
    x = y;

    // PDAS step (ii): keep an active node while it pushes, activate a node beyond its bound.
    std::vector<char> next(p, 0);
    for (Eigen::Index i = 0; i < p; ++i)
      next[i] = bounded[i] && (active[i] ? mu_linear[i] >= 0 : x[i] > upper[i]);
    law(x, phi, slope);
    r = residual(A, x_free, x, phi, active);
    const bool stagnant = step <= kRoundoffStep * x.norm();
    done = next == active && (r.free_norm <= tolerance * r.scale || stagnant);
    active = next;
  }
  s.converged = done;
  if (!done && s.failure.empty())
    s.failure = "no convergence in " + std::to_string(max_iterations) + " Newton iterations";
  s.x = x;
  s.lambda = phi + r.mu;
  s.on_bound = active;
  if (s.converged && !s.lambda.allFinite()) {
    s.converged = false;
    s.failure = "the contact forces are not finite";
  }
  return s;
}

} // namespace sig
