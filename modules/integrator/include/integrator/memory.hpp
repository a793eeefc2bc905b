#pragma once
// The memory term of (5.1) integrated by the trapezoidal rule (5.60)-(5.61) on a uniform time
// grid t_j = j k:
//
//   C_n w = k sum'_{j=0..n} K(t_n - t_j) eps(w_j)     (first and last terms halved), C_0 = 0.
//
// w_n is the unknown of step n (the velocity of the quasistatic march), so the last term, (k/2)
// K(0) eps(w_n), belongs to the step matrix and the rest is a history known before the step. For
// an exponential term K(t) = exp(-beta t) KK that history is KK eps(P_n) with
//
//   P_n = (1/2) exp(-beta t_n) w_0 + sum_{j=1..n-1} exp(-beta (t_n - t_j)) w_j,
//
// and P obeys P_1 = (1/2) exp(-beta k) w_0, P_{n+1} = exp(-beta k) (P_n + w_n): a step costs O(1)
// in the length of the history (ALGORITHMS.md 2.2), where the direct sum for a general kernel costs
// O(n). The values w_j may be any vectors on which KK eps(.) is linear: nodal velocities (then
// KK eps(.) is the memory's stiffness matrix), strains at quadrature points, scalars.
#include <Eigen/Core>

#include <functional>
#include <vector>

namespace sig {

/// The recursion of P for one exponential term.
class ExponentialMemory {
public:
  /// P_1 for beta > 0, k > 0 and the first value w_0 (the march's choice: 0, ALGORITHMS.md C8).
  ExponentialMemory(double beta, double k, const Eigen::VectorXd& w0);

  /// P_n: the history before step n's value is known.
  const Eigen::VectorXd& history() const { return history_; }
  /// Step n's value w_n is known: P becomes P_{n+1}.
  void advance(const Eigen::VectorXd& w_n);
  double beta() const { return beta_; }
  /// exp(-beta k), the factor of one step.
  double decay() const { return decay_; }

private:
  double beta_;
  double decay_;
  Eigen::VectorXd history_;
};

/// The direct trapezoidal sum k sum'_{j=0..n} kernel(t_n - t_j) w_j of (5.61) for values
/// w = w_0 .. w_n (n >= 1; n = 0 gives 0 as the thesis defines C_0), with a scalar kernel.
Eigen::VectorXd trapezoidal_memory(const std::function<double(double)>& kernel, double k,
                                   const std::vector<Eigen::VectorXd>& w);

} // namespace sig
