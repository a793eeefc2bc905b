#pragma once
// The dynamic contact strategies of ch. 3.3 and 8.4, one class per file (src/*_strategy.cpp):
//   signorini          Signorini at t_{n+1}, u_n <= bound, by the static PDAS (3.20)-(3.32)
//   compliance         normal compliance -xi = r [u_n - d]_+, by the static penalty method
//   specific-penalty   the force r w p(a, b) of (3.51)/(8.32), semi-smooth Newton
//   two-step           [13], 3.3.3: (a) Signorini, (b) persistency on the nodes active in (a)
//   ipm                (8.30)-(8.31): (a) specific penalty, (b) the same bounded by the
//                      unilateral constraint u_n <= d + g
// Each solves the condensed step of integrator/dynamic_contact.hpp,
//     A (x - x_free) + lambda = 0,
// for the end-of-step normal displacements x of the p contact nodes and their nodal forces
// lambda, from x_n (at t_n) and x_free (where the step would end without contact force). A step
// that does not converge is a result (converged = false, failure says why), never an exception.
#include <Eigen/Core>

#include <memory>
#include <string>

namespace sig {

struct ContactBoundary;

/// Card field `CONTACT ... strategy=`.
inline constexpr const char* contact_strategy_names =
    "signorini|compliance|specific-penalty|two-step|ipm";

struct ContactStrategyParameters {
  /// Stiffness per unit area of the foundation (compliance, specific-penalty, ipm): nodal force
  /// r * weight * penetration; > 0 where used.
  double r = 0;
  int max_iterations = 50; ///< per Newton phase
  /// Newton stops when the residual of the end-of-step equations is below tolerance times the
  /// forces of the step (and the active set no longer changes).
  double tolerance = 1e-12;
};

/// One step's condensed problem (dynamic_contact.hpp); the references outlive the call.
struct NormalStep {
  const Eigen::MatrixXd& A;      ///< (2 B S^{-1} B^T)^{-1}
  const Eigen::VectorXd& x_now;  ///< u_n of the contact nodes at t_n
  const Eigen::VectorXd& x_free; ///< u_n at t_{n+1} without contact force
};

struct ContactStepSolution {
  Eigen::VectorXd lambda; ///< nodal contact forces over the step (>= 0 but for persistency)
  bool converged = false;
  std::string failure;
  int iterations = 0; ///< Newton (or active-set) iterations, both phases summed
};

class ContactStrategy {
public:
  virtual ~ContactStrategy() = default;
  virtual ContactStepSolution solve(const NormalStep& step,
                                    const ContactBoundary& boundary) const = 0;
  virtual std::string name() const = 0;
};

/// The strategy called `name` (contact_strategy_names); sig::Error for an unknown name or a
/// non-positive r where the strategy needs it.
std::unique_ptr<ContactStrategy> make_contact_strategy(const std::string& name,
                                                       const ContactStrategyParameters& p);

} // namespace sig
