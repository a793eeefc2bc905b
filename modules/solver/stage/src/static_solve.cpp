#include "solver/static_solve.hpp"

#include "assembly/dirichlet.hpp"
#include "assembly/strain.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "solver/condensed_contact.hpp"
#include "solver/linear_solver.hpp"
#include "solver/nodal_frames.hpp"
#include "solver/schur.hpp"

#include <algorithm>
#include <array>
#include <memory>

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
  for (int p = 0; p < contact.size(); ++p)
    dofs.push_back(reduced.contact_node_dofs(contact.node[p]));
  return dofs;
}

/// Position of `dof` in the sorted `interface`.
int position_in(const std::vector<int>& interface, int dof) {
  return static_cast<int>(std::lower_bound(interface.begin(), interface.end(), dof) -
                          interface.begin());
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
  const int m = contact.size();
  const bool friction = contact.has_friction();
  StaticSolution s;

  // 1. Nodal frames at the contact nodes, so each normal displacement and slip is one unknown;
  //    applied in place, K keeps its pattern.
  Stopwatch clock;
  std::vector<int> first_dofs(m);
  for (int p = 0; p < m; ++p) {
    SIG_VERIFY(dofs[p][1] == dofs[p][0] + 1,
               "contact node " << contact.node[p] + 1 << ": its dofs are not consecutive");
    first_dofs[p] = dofs[p][0];
  }
  Eigen::SparseMatrix<double>& K = reduced.K; // rotated in place: the reduced stiffness is ours
  K.makeCompressed();
  const FrameRotation frames(K, std::move(first_dofs));
  frames.rotate(K, contact.normal);
  Eigen::VectorXd f = reduced.f;
  frames.to_frames(f, contact.normal);

  // 2. Condense the bulk onto the normal unknowns (and the slips with friction): one sparse
  //    factorization of the rest, the body with Gamma3 held, positive definite even when K is
  //    not. Frictionless contact acts on the m normal unknowns only.
  std::vector<int> interface;
  for (int p = 0; p < m; ++p) {
    interface.push_back(dofs[p][1]);
    if (friction) interface.push_back(dofs[p][0]);
  }
  std::sort(interface.begin(), interface.end());
  SIG_VERIFY(std::adjacent_find(interface.begin(), interface.end()) == interface.end(),
             "a node appears in two contact elements");
  // With the contact components held, the rest of the body must be fixed: a rigid motion along
  // no contact direction (a tangential load on a frictionless body without Dirichlet condition)
  // leaves no equilibrium to find, whatever the method.
  const std::string unheld =
      "a rigid motion of the body is held neither by its Dirichlet conditions nor by the "
      "directions of its contact laws (a tangential load on a frictionless body without "
      "Dirichlet condition?): there is no equilibrium to find";
  std::unique_ptr<SchurComplement> condensation;
  try {
    condensation = std::make_unique<SchurComplement>(K, interface, backend);
  } catch (const Error& e) {
    SIG_VERIFY(false, "the body with its contact nodes held cannot be factorized ("
                          << e.what() << "); a singular or indefinite matrix here means that "
                          << unheld);
  }
  SchurComplement& schur = *condensation;
  s.seconds["frames"] = clock.seconds() - schur.seconds_factorize() - schur.seconds_schur();
  s.seconds["factorize"] = schur.seconds_factorize();
  s.seconds["schur"] = schur.seconds_schur();

  // 3. The contact method iterates on the small dense problem.
  Stopwatch solve_clock;
  CondensedProblem problem;
  problem.S = schur.matrix();
  problem.f = schur.condense(f);
  problem.gap = contact.gap;
  for (int p = 0; p < m; ++p) {
    problem.normal_dof.push_back(position_in(interface, dofs[p][1]));
    if (friction) problem.tangential_dof.push_back(position_in(interface, dofs[p][0]));
  }
  problem.regularization = kRelativeRegularization * problem.S.diagonal().cwiseAbs().maxCoeff();
  Eigen::VectorXd w_start;
  if (start.size() > 0) {
    SIG_VERIFY(start.size() == system.num_dofs(),
               "start displacement of size " << start.size() << " for " << system.num_dofs());
    Eigen::VectorXd w = reduced.restrict(start);
    frames.to_frames(w, contact.normal);
    w_start.resize(static_cast<Eigen::Index>(interface.size()));
    for (std::size_t k = 0; k < interface.size(); ++k)
      w_start[static_cast<Eigen::Index>(k)] = w[interface[k]];
  }
  // The reduced displacement (in frames) of condensed unknowns w, one interior solve, kept for
  // the last w: the convexification loop's last norm of V and the result share it.
  Eigen::VectorXd expanded_w, expanded_u;
  const auto expand = [&](const Eigen::VectorXd& w) -> const Eigen::VectorXd& {
    if (expanded_w.size() != w.size() || expanded_w != w) {
      expanded_u = schur.expand(f, w);
      expanded_w = w;
    }
    return expanded_u;
  };
  // The whole body's displacement (frames undone, Dirichlet values in), for the norm of V.
  const auto whole_body = [&](const Eigen::VectorXd& w) {
    Eigen::VectorXd u = expand(w);
    frames.from_frames(u, contact.normal);
    return reduced.expand(u);
  };
  CondensedConvexification convexification{loop.options, whole_body, {}};
  if (loop.mesh != nullptr)
    convexification.norm = [&](const Eigen::VectorXd& u) { return strain_norm(*loop.mesh, u); };
  const CondensedSolution condensed = solve_condensed_contact(
      std::move(problem), {contact.law, contact.weight}, parameters, w_start, convexification);
  const ContactNewtonResult& c = condensed.contact;
  if (!c.converged) log_warning(parameters.method + " did not converge: " + c.failure);
  if (condensed.convexification && !condensed.convexification->converged)
    log_warning("the convexification loop did not converge: " + condensed.convexification->failure);

  // 4. Back to the whole body, and its equilibrium checked there: an unheld rigid motion that
  //    the factorization did not see as singular (its pivot a round-off) leaves a meaningless
  //    drift.
  Eigen::VectorXd u = expand(condensed.w);
  Eigen::VectorXd r = K * u - f;
  for (int p = 0; p < m; ++p) {
    r[dofs[p][1]] += c.normal_force[p];
    r[dofs[p][0]] += c.tangential_force[p];
  }
  const double imbalance = r.norm() / std::max(f.norm(), 1e-300);
  frames.from_frames(u, contact.normal);
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
                 << imbalance << "): " << unheld);
  // As the thesis counts them: every displacement dof, plus the Lagrange nodes for ALM.
  s.unknowns = system.num_dofs() + condensed.multiplier_unknowns;
  return s;
}

} // namespace sig
