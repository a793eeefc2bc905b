#pragma once
// The static problem of sig-solve: a linear elastic bulk, with or without node-to-rigid contact.
// Without contact it is one factorization and one solve. With contact the bulk is condensed onto
// the Gamma3 dofs (one sparse factorization, solver/schur.hpp) and the chosen contact method
// iterates on the small dense problem, in nodal (tangent, normal) frames.
#include "assembly/system.hpp"
#include "contact/contact_elements.hpp"
#include "solver/contact_solver.hpp"

#include <map>
#include <string>

namespace sig {

struct StaticSolution {
  Eigen::VectorXd u;          ///< full displacement (2 dofs per node)
  Eigen::VectorXd multiplier; ///< per contact element (empty without contact)
  std::vector<char> active;
  bool converged = true;
  std::string failure;
  std::vector<IterationRecord> history;
  int unknowns = 0;                      ///< dofs of the Newton vector, as the thesis counts them
  std::map<std::string, double> seconds; ///< factorize, schur, solve
};

StaticSolution solve_linear_elasticity(const LinearSystem& system, const std::string& backend);

StaticSolution solve_static_contact(const LinearSystem& system, const ContactElements& contact,
                                    const ContactSolverParameters& parameters,
                                    const std::string& backend);

} // namespace sig
