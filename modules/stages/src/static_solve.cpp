#include "stages/static_solve.hpp"

#include "assembly/dirichlet.hpp"
#include "assembly/strain.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "solver/condensed_contact.hpp"
#include "solver/contact_condensation.hpp"
#include "solver/linear_solver.hpp"
#include "stages/newton_outcome.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>

namespace sig {

namespace {

/// The reduced index of the first of the d dofs of each contact node, in element order.
std::vector<int> contact_first_dofs(const ReducedSystem& reduced, const ContactElements& contact) {
  std::vector<int> first;
  for (int p = 0; p < contact.size(); ++p)
    first.push_back(reduced.contact_node_first_dof(contact.node[p], contact.dim));
  return first;
}

} // namespace

std::vector<int> hold_on_contact_nodes(const LinearSystem& system, ContactElements& contact) {
  std::vector<int> held;
  for (int p = 0; p < contact.size(); ++p) {
    ContactLaw& law = contact.law[p];
    const int d = contact.dim;
    for (int component = 0; component < d; ++component) {
      const int dof = d * contact.node[p] + component;
      const auto at =
          std::lower_bound(system.dirichlet_dofs.begin(), system.dirichlet_dofs.end(), dof);
      if (at == system.dirichlet_dofs.end() || *at != dof) continue;
      const double value = system.dirichlet_values[at - system.dirichlet_dofs.begin()];
      // The held axis e_c in the node's frame: u_n = -n . u, q_n = u_n - d, q_t = t . u.
      const double along_n = contact.normal[p][component], along_t = contact.tangent[p][component];
      constexpr double kAligned = 1 - 1e-12;
      if (std::abs(along_n) >= kAligned) {
        law.held_normal = true;
        law.normal = NormalLaw::signorini;
        law.depth = -along_n * value - contact.gap[p];
        log_warning("contact node " + std::to_string(p + 1) + " (mesh node " +
                    std::to_string(contact.node[p] + 1) +
                    ") has its normal component held by a DIRICHLET card: it is out of the "
                    "contact set, its normal force the condition's reaction");
      } else if (d == 2 && std::abs(along_t) >= kAligned) {
        // In 3D a held axis of the tangent plane is one direction of a two-component slip, which
        // the law's scalar held slip cannot say (contact_kernel.hpp refuses it).
        law.held_tangential = true;
        law.held_slip = along_t * value;
      } else {
        std::ostringstream n;
        n << contact.normal[p].transpose().format(Eigen::IOFormat(
            Eigen::StreamPrecision, Eigen::DontAlignCols, ", ", ", ", "", "", "(", ")"));
        SIG_VERIFY(false, "contact node "
                              << p + 1 << " (mesh node " << contact.node[p] + 1
                              << "): a DIRICHLET card holds u" << component + 1 << ", which is "
                              << (d == 2 ? "neither the obstacle's normal "
                                         : "not along the obstacle's normal ")
                              << n.str()
                              << (d == 2 ? " nor its tangent there; hold only the normal or the "
                                           "tangential component"
                                         : " there; hold only the normal component")
                              << " of a contact node, or take the node out of the contact zone "
                                 "(CONTACT exclude=REF)");
      }
      held.push_back(dof);
    }
    // Out of contact: no friction, unless the tangential component is held too.
    if (law.held_normal) {
      law.friction = FrictionLaw::none;
      law.cn = 0;
      law.c3 = std::numeric_limits<double>::infinity();
    }
  }
  std::sort(held.begin(), held.end());
  return held;
}

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

StaticSolution solve_static_contact(const LinearSystem& system, ContactElements contact,
                                    const ContactSolverParameters& parameters,
                                    const std::string& backend, const Eigen::VectorXd& start,
                                    const StaticConvexification& loop) {
  const std::vector<int> held = hold_on_contact_nodes(system, contact);
  SIG_VERIFY(held.empty() || parameters.method != "penalty",
             "a DIRICHLET card holds a component of a contact node, which the penalty method "
             "cannot impose (it has no multipliers): use SOLVER method=alm or pdas");
  ReducedSystem reduced = reduce(system, held);
  const std::vector<int> first_dofs = contact_first_dofs(reduced, contact);
  const bool friction = contact.has_friction();
  StaticSolution s;

  // 1. The bulk in nodal frames condensed onto the normal displacements of the contact nodes
  //    (and their slips with friction): one sparse factorization.
  ContactCondensation condensation(std::move(reduced.K), first_dofs, contact.frames(), friction,
                                   backend);
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
  record_newton_outcome(s, c);
  if (condensed.convexification) {
    s.convexification = condensed.convexification;
    s.converged = s.convexification->converged;
    s.reason = s.convexification->reason;
    s.failure = s.convexification->failure;
    s.history = s.convexification->inner_history;
  }
  if (c.converged && imbalance > std::max(1e3 * parameters.eps, 1e-6)) {
    // Displacements beyond 1e10 times the contact boundary's length (or its largest gap) resolve
    // the gaps to worse than 1e-6 of that length (round-off 1e-16 of the displacement): loads
    // that large against the stiffness, not a free motion, break the equilibrium.
    const double extent = contact.dim == 3 ? std::sqrt(contact.weight.sum())
                                           : contact.weight.sum() / contact.thickness;
    const double length = std::max(contact.gap.maxCoeff(), extent);
    const double reach = s.u.cwiseAbs().maxCoeff();
    SIG_VERIFY(reach <= 1e10 * length,
               "the contact solve cannot hold its conditions: the displacement reaches "
                   << reach << ", " << reach / length << " times the contact boundary's length "
                   << length
                   << ", so the loads are that large against the stiffness (TRACTION f=, PRESSURE "
                      "p=, BODYFORCE f= against MATERIAL E=) and the gaps are lost in the "
                      "round-off of such displacements (relative residual "
                   << imbalance << ")");
    SIG_VERIFY(false, "the converged contact solve leaves the body out of equilibrium (relative "
                      "residual "
                          << imbalance << "): " << kUnheldRigidMotion);
  }
  // As the thesis counts them: every displacement dof, plus the Lagrange nodes for ALM.
  s.unknowns = system.num_dofs() + condensed.multiplier_unknowns;
  return s;
}

} // namespace sig
