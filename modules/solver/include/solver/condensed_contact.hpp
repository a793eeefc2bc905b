#pragma once
// A contact problem on a condensed linear bulk (condensed_bulk.hpp), solved by one of the four
// methods with the one Newton driver: what the static solve and the dynamic steps share.
#include "solver/condensed_bulk.hpp"
#include "solver/contact_method.hpp"
#include "solver/contact_newton.hpp"

namespace sig {

struct CondensedSolution {
  ContactNewtonResult contact;
  Eigen::VectorXd w;           ///< the condensed displacement at the end
  int multiplier_unknowns = 0; ///< unknowns the method adds (alm: its Lagrange nodes')
};

/// From w = start (empty: 0) and zero multipliers. The default normal spring of a node is the
/// method's inactive stiffness where its law has a wall. sig::Error for inconsistent input.
CondensedSolution solve_condensed_contact(CondensedProblem problem, const ContactSetting& setting,
                                          const ContactSolverParameters& parameters,
                                          const Eigen::VectorXd& start = {});

} // namespace sig
