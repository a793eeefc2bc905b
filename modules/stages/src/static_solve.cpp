#include "stages/static_solve.hpp"

#include "assembly/dirichlet.hpp"
#include "assembly/strain.hpp"
#include "core/datafile.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "solver/condensed_contact.hpp"
#include "solver/contact_condensation.hpp"
#include "solver/convexification.hpp"
#include "solver/linear_solver.hpp"
#include "stages/newton_outcome.hpp"
#include "stages/rank_rows.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
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

HeldAxis held_axis(const ContactFrame& frame, int component) {
  // |e_c . n| or |e_c . t_k| within round-off of 1: the axis is that one of the frame, whose
  // last column is -n.
  constexpr double kAligned = 1 - 1e-12;
  const int normal = static_cast<int>(frame.cols()) - 1;
  HeldAxis axis;
  axis.along_normal = -frame(component, normal);
  if (std::abs(axis.along_normal) >= kAligned) {
    axis.kind = HeldAxis::Kind::normal;
    return axis;
  }
  for (int k = 0; k < normal; ++k)
    if (std::abs(frame(component, k)) >= kAligned) {
      axis.kind = HeldAxis::Kind::tangent;
      axis.tangent = k;
      axis.along_tangent = frame(component, k);
      return axis;
    }
  return axis;
}

std::string oblique_hold_problem(const ContactElements& contact, int p, int component) {
  std::ostringstream what;
  what << "holds u" << component + 1 << " of contact node " << p + 1 << " (mesh node "
       << contact.node[p] + 1 << "), which is neither the obstacle's normal "
       << coordinates(contact.normal[p]) << " nor "
       << (contact.dim == 2 ? "its tangent" : "one of the node's tangents")
       << " there; hold only those components of a contact node, or take the node out of the "
          "contact zone (CONTACT exclude=REF)";
  return what.str();
}

void verify_held_contact_components(const Mesh& mesh, const Datafile& datafile,
                                    const LinearSystem& system, const ContactElements& contact,
                                    const std::string& method) {
  const int d = contact.dim;
  for (int p = 0; p < contact.size(); ++p) {
    const ContactFrame frame = contact.frame(p);
    for (int component = 0; component < d; ++component) {
      const int dof = d * contact.node[p] + component;
      if (!std::binary_search(system.dirichlet_dofs.begin(), system.dirichlet_dofs.end(), dof))
        continue;
      const std::string field = std::string("u") + "xyz"[component];
      if (held_axis(frame, component).kind == HeldAxis::Kind::oblique) {
        if (const Card* card = dirichlet_card_of(mesh, datafile, dof))
          card->fail(field, oblique_hold_problem(contact, p, component));
        SIG_VERIFY(false, datafile.path << ": a DIRICHLET condition "
                                        << oblique_hold_problem(contact, p, component));
      }
      if (const Card* card = method == "penalty" ? dirichlet_card_of(mesh, datafile, dof) : nullptr)
        card->fail(field, "holds u" + std::to_string(component + 1) + " of contact node " +
                              std::to_string(p + 1) +
                              ", which the penalty method cannot impose (it has no multipliers): "
                              "use SOLVER method=alm or pdas");
    }
  }
}

std::vector<int> hold_on_contact_nodes(const LinearSystem& system, ContactElements& contact) {
  std::vector<int> held;
  for (int p = 0; p < contact.size(); ++p) {
    ContactLaw& law = contact.law[p];
    const int d = contact.dim;
    const ContactFrame frame = contact.frame(p);
    for (int component = 0; component < d; ++component) {
      const int dof = d * contact.node[p] + component;
      const auto at =
          std::lower_bound(system.dirichlet_dofs.begin(), system.dirichlet_dofs.end(), dof);
      if (at == system.dirichlet_dofs.end() || *at != dof) continue;
      const double value = system.dirichlet_values[at - system.dirichlet_dofs.begin()];
      // The held axis e_c in the node's frame: u_n = -n . u, q_n = u_n - d, q_t = t . u.
      const HeldAxis axis = held_axis(frame, component);
      SIG_VERIFY(axis.kind != HeldAxis::Kind::oblique,
                 "a DIRICHLET card " << oblique_hold_problem(contact, p, component));
      if (axis.kind == HeldAxis::Kind::normal) {
        law.held_normal = true;
        law.normal = NormalLaw::signorini;
        law.depth = -axis.along_normal * value - contact.gap[p];
        log_warning("contact node " + std::to_string(p + 1) + " (mesh node " +
                    std::to_string(contact.node[p] + 1) +
                    ") has its normal component held by a DIRICHLET card: it is out of the "
                    "contact set, its normal force the condition's reaction");
      } else {
        law.held_tangent[axis.tangent] = true;
        law.held_slip[axis.tangent] = axis.along_tangent * value;
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
  SIG_VERIFY(!system.rank_rows, "a linear solve without contact runs in one process (no mpirun)");
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

namespace {

/// The solution on the elements `zone` of `contact` spread over all of them: the others are
/// free, without force.
void spread(StaticSolution& s, const std::vector<int>& zone, int m) {
  // c components per element (the tangential force: two in 3D with friction).
  const auto spread_vector = [&](Eigen::VectorXd& v) {
    const int c = zone.empty() ? 1 : static_cast<int>(v.size() / std::ssize(zone));
    Eigen::VectorXd all = Eigen::VectorXd::Zero(c * m);
    for (std::size_t k = 0; k < zone.size(); ++k)
      for (int j = 0; j < c; ++j)
        all[c * zone[k] + j] = v[c * static_cast<Eigen::Index>(k) + j];
    v = std::move(all);
  };
  spread_vector(s.multiplier);
  spread_vector(s.tangential);
  std::vector<NormalStatus> normal(m, NormalStatus::free);
  std::vector<FrictionStatus> friction(m, FrictionStatus::none);
  for (std::size_t k = 0; k < zone.size(); ++k) {
    normal[zone[k]] = s.normal_status[k];
    friction[zone[k]] = s.friction_status[k];
  }
  s.normal_status = std::move(normal);
  s.friction_status = std::move(friction);
  for (IterationRecord& r : s.history) {
    if (r.wall.size() != zone.size()) continue;
    std::vector<std::int8_t> wall(m, 0);
    for (std::size_t k = 0; k < zone.size(); ++k)
      wall[zone[k]] = r.wall[k];
    r.wall = std::move(wall);
  }
}

/// The largest initial gap of a node outside `zone` that the displacement u (full, d dofs per
/// node) brings beyond the obstacle surface, or -1 if none does.
double largest_gap_entered(const ContactElements& contact, const std::vector<int>& zone,
                           const Eigen::VectorXd& u) {
  const int d = contact.dim;
  // Round-off of a node resting on the surface: of the contact boundary's size.
  const double extent = contact.extent();
  double entered = -1;
  std::size_t k = 0;
  for (int i = 0; i < contact.size(); ++i) {
    if (k < zone.size() && zone[k] == i) {
      ++k;
      continue;
    }
    const double u_n = -contact.normal[i].dot(u.segment(d * contact.node[i], d));
    if (u_n - contact.gap[i] > 1e-12 * extent) entered = std::max(entered, contact.gap[i]);
  }
  return entered;
}

/// The solve of solve_static_contact on every node of `contact`.
StaticSolution solve_whole(const LinearSystem& system, ContactElements contact,
                           const ContactSolverParameters& parameters, const std::string& backend,
                           const Eigen::VectorXd& start, const StaticConvexification& loop);

} // namespace

std::vector<int> candidates(const LinearSystem& system, const ContactElements& contact,
                            double bound) {
  std::vector<int> zone;
  const int d = contact.dim;
  for (int i = 0; i < contact.size(); ++i) {
    bool held = false;
    for (int c = 0; c < d; ++c)
      held = held || std::binary_search(system.dirichlet_dofs.begin(), system.dirichlet_dofs.end(),
                                        d * contact.node[i] + c);
    if (held || contact.gap[i] <= bound) zone.push_back(i);
  }
  return zone;
}

std::string candidate_zone_problem(const ContactElements& contact) {
  for (const ContactLaw& law : contact.law) {
    if (law.normal == NormalLaw::compliance_bilateral)
      return "law=compliance-bilateral pulls the nodes that are apart from the obstacle too";
    if (law.friction == FrictionLaw::tresca)
      return "Tresca's threshold acts on every contact node, apart from the obstacle or not";
    if (law.in_velocity()) return "a law of the velocity has no initial gap to choose by";
  }
  if (needs_convexification(contact.law))
    return "the convexification loop of law=nonmonotone keeps a coefficient on every node";
  return {};
}

StaticSolution solve_static_contact(const LinearSystem& system, ContactElements contact,
                                    const ContactSolverParameters& parameters,
                                    const std::string& backend, const Eigen::VectorXd& start,
                                    const StaticConvexification& loop) {
  if (!std::isfinite(parameters.candidate_gap))
    return solve_whole(system, std::move(contact), parameters, backend, start, loop);
  const std::string problem = candidate_zone_problem(contact);
  SIG_VERIFY(problem.empty(), "SOLVER candidate_gap= condenses only the nodes near the obstacle, "
                              "but "
                                  << problem);
  // Only the candidates are condensed (SOLVER candidate_gap=): the dense Schur complement of a 3D
  // contact boundary grows as the square of its nodes. Outside the zone a node carries no force
  // while it is apart from the obstacle (candidate_zone_problem). One that the solution brings
  // through the obstacle widens the zone to twice its gap, and the solve starts again: the
  // solution is then that of every node. A zone whose solve fails (it may not hold the body)
  // widens four times.
  double bound = parameters.candidate_gap;
  // [choice] At least the 8 d nodes of least gap: fewer (two nodes of a ball) may leave a tilt
  // of the body held by nothing but the proximal term, whose solve says nothing.
  {
    std::vector<double> gaps(contact.gap.begin(), contact.gap.end());
    const auto least =
        std::min<std::size_t>(gaps.size(), 8 * static_cast<std::size_t>(contact.dim));
    std::nth_element(gaps.begin(), gaps.begin() + static_cast<std::ptrdiff_t>(least - 1),
                     gaps.end());
    bound = std::max(bound, gaps[least - 1]);
  }
  std::map<std::string, double> seconds;
  std::vector<IterationRecord> history; // every round's iterations, walls over every node
  const auto text = [](double x) {
    std::ostringstream out;
    out << x;
    return out.str();
  };
  for (int round = 1;; ++round) {
    const std::vector<int> zone = candidates(system, contact, bound);
    const bool whole = static_cast<int>(zone.size()) == contact.size();
    const std::string candidates_text = std::to_string(zone.size()) + " of " +
                                        std::to_string(contact.size()) +
                                        " contact nodes (initial gap <= " + text(bound) + ")";
    StaticSolution s;
    try {
      s = solve_whole(system, contact.subset(zone), parameters, backend, start, loop);
    } catch (const Error& e) {
      if (whole) throw;
      log_info("contact zone: the solve on " + candidates_text + " failed (" + e.what() +
               "): the zone widens and the solve restarts");
      bound *= 4;
      continue;
    }
    for (const auto& [phase, time] : s.seconds)
      seconds[phase] += time;
    spread(s, zone, contact.size());
    history.insert(history.end(), s.history.begin(), s.history.end());
    if (!whole && !s.converged) { // the zone may not hold the body: widen it
      log_info("contact zone: the solve on " + candidates_text + " did not converge (" + s.failure +
               "): the zone widens and the solve restarts");
      bound *= 4;
      continue;
    }
    const double entered = whole ? -1 : largest_gap_entered(contact, zone, s.u);
    if (entered < 0) {
      s.seconds = seconds;
      s.history = std::move(history);
      log_info("contact zone: " + candidates_text + " condensed, " + std::to_string(round) +
               (round == 1 ? " solve" : " solves") + ", " + std::to_string(s.history.size()) +
               " iterations in all");
      return s;
    }
    log_info("contact zone: a node of initial gap " + text(entered) + " outside the " +
             candidates_text + " comes to touch: the zone widens and the solve restarts");
    bound = std::max(2 * bound, 2 * entered);
  }
}

namespace {

StaticSolution solve_whole(const LinearSystem& system, ContactElements contact,
                           const ContactSolverParameters& parameters, const std::string& backend,
                           const Eigen::VectorXd& start, const StaticConvexification& loop) {
  const std::vector<int> held = hold_on_contact_nodes(system, contact);
  SIG_VERIFY(held.empty() || parameters.method != "penalty",
             "a DIRICHLET card holds a component of a contact node, which the penalty method "
             "cannot impose (it has no multipliers): use SOLVER method=alm or pdas");
  ReducedSystem reduced = reduce_on_ranks(system, held);
  const std::vector<int> first_dofs = contact_first_dofs(reduced, contact);
  const bool friction = contact.has_friction();
  StaticSolution s;

  // 1. The bulk in nodal frames condensed onto the normal displacements of the contact nodes
  //    (and their slips with friction): one sparse factorization.
  ContactCondensation condensation(std::move(reduced.K), first_dofs, contact.frames(), friction,
                                   backend, false, system.rank_rows);
  s.ordering = condensation.ordering();
  if (const MumpsStatistics* statistics = condensation.mumps_statistics()) s.mumps = *statistics;
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
    // Displacements beyond 1e10 times the contact boundary's size (or its largest gap) resolve
    // the gaps to worse than 1e-6 of that length (round-off 1e-16 of the displacement): loads
    // that large against the stiffness, not a free motion, break the equilibrium.
    const double length = std::max(contact.gap.maxCoeff(), contact.extent());
    const double reach = s.u.cwiseAbs().maxCoeff();
    SIG_VERIFY(reach <= 1e10 * length,
               "the contact solve cannot hold its conditions: the displacement reaches "
                   << reach << ", " << reach / length << " times the contact boundary's size "
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

} // namespace

} // namespace sig
