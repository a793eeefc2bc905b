#pragma once
// A contact problem on a condensed linear bulk (condensed_bulk.hpp), solved by one of the four
// methods with the one Newton driver: what the static solve and the dynamic steps share. With a
// nonmonotone friction law the convexification loop (convexification.hpp) runs on the same
// condensed bulk: one dense factorization for every outer iteration.
#include "solver/condensed_bulk.hpp"
#include "solver/contact_method.hpp"
#include "solver/contact_newton.hpp"
#include "solver/convexification.hpp"

#include <functional>
#include <optional>

namespace sig {

struct CondensedSolution {
  ContactNewtonResult contact; ///< the (last) convex solve
  Eigen::VectorXd w;           ///< the condensed displacement at the end
  int multiplier_unknowns = 0; ///< unknowns the method adds (alm: its Lagrange nodes')
  std::optional<ConvexificationResult> convexification; ///< with a nonmonotone law
};

/// The loop's options and measures on a condensed bulk: `displacement` maps the condensed
/// unknowns w to the vector `norm` measures in the outer test (empty: w and the Euclidean norm);
/// `slip` maps w to the slip measure r per contact node (empty: |q_t|, the slip from the
/// reference; a law of the slip rate, of=slip-rate, must give it: a time step knows its rate).
struct CondensedConvexification {
  ConvexificationOptions options;
  std::function<Eigen::VectorXd(const Eigen::VectorXd& w)> displacement;
  std::function<double(const Eigen::VectorXd&)> norm;
  std::function<Eigen::VectorXd(const Eigen::VectorXd& w)> slip;
};

/// From w = start (empty: 0) and zero multipliers. The default normal spring of a node is the
/// method's inactive stiffness where its law has a wall. A nonmonotone law runs the loop with
/// `loop`. sig::Error for inconsistent input, or a law of the slip rate without `loop.slip`.
CondensedSolution solve_condensed_contact(CondensedProblem problem, const ContactSetting& setting,
                                          const ContactSolverParameters& parameters,
                                          const Eigen::VectorXd& start = {},
                                          const CondensedConvexification& loop = {});

} // namespace sig
