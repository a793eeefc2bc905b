#include "solver/static_solve.hpp"

#include "assembly/dirichlet.hpp"
#include "assembly/strain.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "solver/condensed_contact.hpp"
#include "solver/contact_condensation.hpp"
#include "solver/linear_solver.hpp"

#include <algorithm>
#include <array>
#include <memory>

namespace sig {

namespace {

/// The reduced dofs (u1, u2) of each contact node, in element order.
std::vector<std::array<int, 2>> contact_dofs(const ReducedSystem& reduced,
                                             const ContactElements& contact) {
  std::vector<std::array<int, 2>> dofs;
  for (int p = 0; p < contact.size(); ++p)
    dofs.push_back(reduced.contact_node_dofs(contact.node[p]));
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
                                    const std::string& backend, const Eigen::VectorXd& start,
                                    const StaticConvexification& loop) {
  ReducedSystem reduced = reduce(system);
  const std::vector<std::array<int, 2>> dofs = contact_dofs(reduced, contact);
  const bool friction = contact.has_friction();
  StaticSolution s;

  // 1. The bulk in nodal frames condensed onto the normal displacements of the contact nodes
  //    (and their slips with friction): one sparse factorization.
  ContactCondensation condensation(std::move(reduced.K), dofs, contact.normal, friction, backend);
  s.seconds["frames"] = condensation.seconds_frames();
  s.seconds["factorize"] = condensation.seconds_factorize();
  s.seconds["schur"] = condensation.seconds_schur();

  // 2. The contact method iterates on the small dense problem.
  Stopwatch solve_clock;
  CondensedProblem problem = condensation.problem(reduced.f);
  problem.gap = contact.gap;
  Eigen::VectorXd w_start;
  if (start.size() > 0) {
    SIG_VERIFY(start.size() == system.num_dofs(),
               "start displacement of size " << start.size() << " for " << system.num_dofs());
    w_start = condensation.restrict(reduced.restrict(start));
  }
  // The free dofs (frames undone) of condensed unknowns w, one interior solve, kept for the last
  // w: the convexification loop's last norm of V and the result share it.
  Eigen::VectorXd expanded_w, expanded_u;
  const auto expand = [&](const Eigen::VectorXd& w) -> const Eigen::VectorXd& {
    if (expanded_w.size() != w.size() || expanded_w != w) {
      expanded_u = condensation.expand(w);
      expanded_w = w;
    }
    return expanded_u;
  };
  // The whole body's displacement (Dirichlet values in), for the norm of V.
  const auto whole_body = [&](const Eigen::VectorXd& w) { return reduced.expand(expand(w)); };
  CondensedConvexification convexification{loop.options, whole_body, {}, {}};
  if (loop.mesh != nullptr)
    convexification.norm = [&](const Eigen::VectorXd& u) { return strain_norm(*loop.mesh, u); };
  const CondensedSolution condensed = solve_condensed_contact(
      std::move(problem), {contact.law, contact.weight}, parameters, w_start, convexification);
  const ContactNewtonResult& c = condensed.contact;
  if (!c.converged) log_warning(parameters.method + " did not converge: " + c.failure);
  if (condensed.convexification && !condensed.convexification->converged)
    log_warning("the convexification loop did not converge: " + condensed.convexification->failure);

  // 3. Back to the whole body, and its equilibrium checked there: an unheld rigid motion that
  //    the factorization did not see as singular (its pivot a round-off) leaves a meaningless
  //    drift.
  const Eigen::VectorXd u = expand(condensed.w);
  const double imbalance = condensation.relative_residual(u, c.normal_force, c.tangential_force);
  s.u = reduced.expand(u);
  s.seconds["solve"] = solve_clock.seconds();
  s.multiplier = c.normal_force;
  s.tangential = c.tangential_force;
  s.normal_status = c.normal_status;
  s.friction_status = c.friction_status;
  s.converged = c.converged;
  s.failure = c.failure;
  s.history = c.history;
  if (condensed.convexification) {
    s.convexification = condensed.convexification;
    s.converged = s.convexification->converged;
    s.failure = s.convexification->failure;
    s.history = s.convexification->inner_history;
  }
  SIG_VERIFY(!c.converged || imbalance <= std::max(1e3 * parameters.eps, 1e-6),
             "the converged contact solve leaves the body out of equilibrium (relative residual "
                 << imbalance << "): " << kUnheldRigidMotion);
  // As the thesis counts them: every displacement dof, plus the Lagrange nodes for ALM.
  s.unknowns = system.num_dofs() + condensed.multiplier_unknowns;
  return s;
}

} // namespace sig
