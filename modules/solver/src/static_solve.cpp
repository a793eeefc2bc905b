#include "solver/static_solve.hpp"

#include "assembly/dirichlet.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "solver/linear_solver.hpp"
#include "solver/nodal_frames.hpp"
#include "solver/schur.hpp"

#include <algorithm>
#include <array>

namespace sig {

namespace {

// Weight of the vanishing proximal term, relative to the largest stiffness entry: enough to pin
// the rigid modes a single contact node leaves free (Hertz's first iterate, thesis Fig 7.8). Its
// trace in the converged state is this weight times ||u(k+1) - u(k)||, which test (iv) has made
// small: far below round-off of the equilibrium residual.
constexpr double kRelativeRegularization = 1e-10;

/// The reduced dofs (u1, u2) of each contact node, in element order.
std::vector<std::array<int, 2>> contact_dofs(const ReducedSystem& reduced,
                                             const ContactElements& contact) {
  std::vector<std::array<int, 2>> dofs;
  for (int p = 0; p < contact.size(); ++p) {
    std::array<int, 2> d{};
    for (int component = 0; component < 2; ++component) {
      d[component] = reduced.reduced_index[2 * contact.node[p] + component];
      SIG_VERIFY(d[component] >= 0, "contact node " << contact.node[p] + 1
                                                    << " has a Dirichlet condition on component "
                                                    << component + 1
                                                    << "; Gamma3 and Gamma1 must not share nodes");
    }
    dofs.push_back(d);
  }
  return dofs;
}

} // namespace

StaticSolution solve_linear_elasticity(const LinearSystem& system, const std::string& backend) {
  const ReducedSystem reduced = reduce(system);
  StaticSolution s;
  Stopwatch clock;
  auto solver = make_linear_solver(backend, MatrixKind::spd);
  solver->analyze(reduced.K);
  solver->factorize(reduced.K);
  s.seconds["factorize"] = clock.seconds();
  Stopwatch solve_clock;
  s.u = reduced.expand(solver->solve(reduced.f));
  s.seconds["solve"] = solve_clock.seconds();
  s.unknowns = system.num_dofs();
  return s;
}

StaticSolution solve_static_contact(const LinearSystem& system, const ContactElements& contact,
                                    const ContactSolverParameters& parameters,
                                    const std::string& backend) {
  const ReducedSystem reduced = reduce(system);
  const std::vector<std::array<int, 2>> dofs = contact_dofs(reduced, contact);
  StaticSolution s;

  // 1. Nodal frames at the contact nodes, so each normal displacement is one unknown.
  Stopwatch clock;
  const Eigen::SparseMatrix<double> Q = nodal_frames(reduced.num_free(), dofs, contact.normal);
  const Eigen::SparseMatrix<double> K = Q.transpose() * reduced.K * Q;
  const Eigen::VectorXd f = Q.transpose() * reduced.f;

  // 2. Condense the bulk onto the normal unknowns: one sparse factorization of the rest (the
  //    body with Gamma3 held normally, positive definite even when K is not). Frictionless
  //    contact acts on these m unknowns only.
  std::vector<int> normal(contact.size());
  for (int p = 0; p < contact.size(); ++p)
    normal[p] = dofs[p][1];
  std::vector<int> interface = normal;
  std::sort(interface.begin(), interface.end());
  SIG_VERIFY(std::adjacent_find(interface.begin(), interface.end()) == interface.end(),
             "a node appears in two contact elements");
  SchurComplement schur(K, interface, backend);
  s.seconds["frames"] = clock.seconds() - schur.seconds_factorize() - schur.seconds_schur();
  s.seconds["factorize"] = schur.seconds_factorize();
  s.seconds["schur"] = schur.seconds_schur();

  // 3. The contact method iterates on the small dense problem, in element order.
  Stopwatch solve_clock;
  std::vector<int> position(contact.size());
  for (int p = 0; p < contact.size(); ++p)
    position[p] = static_cast<int>(std::lower_bound(interface.begin(), interface.end(), normal[p]) -
                                   interface.begin());
  const Eigen::VectorXd f_condensed = schur.condense(f);
  ContactProblem problem;
  problem.K.resize(contact.size(), contact.size());
  problem.f.resize(contact.size());
  for (int p = 0; p < contact.size(); ++p) {
    problem.f[p] = f_condensed[position[p]];
    for (int q = 0; q < contact.size(); ++q)
      problem.K(p, q) = schur.matrix()(position[p], position[q]);
    problem.normal_dof.push_back(p);
  }
  problem.gap = contact.gap;
  problem.weight = contact.weight;
  problem.regularization = kRelativeRegularization * problem.K.diagonal().cwiseAbs().maxCoeff();
  const ContactSolution c = make_contact_solver(parameters)->solve(problem);
  if (!c.converged) log_warning(parameters.method + " did not converge: " + c.failure);

  // 4. Back to the whole body.
  Eigen::VectorXd un(contact.size());
  for (int p = 0; p < contact.size(); ++p)
    un[position[p]] = c.u[p];
  s.u = reduced.expand(Q * schur.expand(f, un));
  s.seconds["solve"] = solve_clock.seconds();
  s.multiplier = c.multiplier;
  s.active = c.active;
  s.converged = c.converged;
  s.failure = c.failure;
  s.history = c.history;
  // As the thesis counts them: every displacement dof, plus the Lagrange nodes for ALM.
  s.unknowns = system.num_dofs() + (c.unknowns - problem.size());
  return s;
}

} // namespace sig
