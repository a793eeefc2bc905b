// Semi-smooth Newton with load stepping for hyperelastic contact (finite_strain_contact.hpp).
#include "solver/finite_strain_contact.hpp"

#include "assembly/dirichlet.hpp"
#include "assembly/nonlinear.hpp"
#include "contact/complementarity.hpp"
#include "core/error.hpp"
#include "mesh/mesh.hpp"
#include "solver/linear_solver.hpp"
#include "solver/methods.hpp"
#include "solver/newton_matrix.hpp"
#include "solver/nodal_frames.hpp"

#include <algorithm>
#include <cmath>

namespace sig {

namespace {

/// Halvings of the Newton step before the line search gives up on a decrease.
constexpr int kMaxHalvings = 12;
/// Relative step of the central differences of the obstacle normal (error O(h^2) ~ 1e-12,
/// round-off ~ 1e-16 / h ~ 1e-10 of the curvature).
constexpr double kNormalDifferenceStep = 1e-6;

enum class Method { alm, penalty, pdas, projection };

Method method_of(const std::string& name) {
  if (name == "alm") return Method::alm;
  if (name == "penalty") return Method::penalty;
  if (name == "pdas") return Method::pdas;
  if (name == "projection") return Method::projection;
  SIG_VERIFY(false, "unknown contact method '" << name << "'; known: alm penalty pdas projection");
  return Method::pdas;
}

/// Everything the loop needs about the current iterate (u, lambda).
struct Iterate {
  Eigen::VectorXd u, lambda;
  HyperelasticState bulk;
  Eigen::VectorXd phi;                 ///< penetration per contact node (u_n - g)
  std::vector<Eigen::Vector2d> normal; ///< obstacle normal at the current position
  bool has_tangent = false;            ///< bulk.tangent belongs to u (not a force-only trial)
};

/// The geometry and data of one solve, fixed over the Newton loops.
class Setting {
public:
  Setting(const FiniteStrainProblem& problem, const FiniteStrainOptions& options)
      : problem_(problem), options_(options), method_(method_of(options.contact.method)),
        pattern_(*problem.mesh) {
    const int m = contacts();
    offset_.resize(m);
    for (int p = 0; p < m; ++p) {
      const int node = problem.contact->node[p];
      offset_[p] =
          problem.contact->gap[p] - problem.obstacle->signed_distance(problem.mesh->nodes[node]);
    }
  }

  int dofs() const { return 2 * problem_.mesh->num_nodes(); }
  int contacts() const { return problem_.contact ? problem_.contact->size() : 0; }
  int node(int p) const { return problem_.contact->node[p]; }
  double weight(int p) const { return problem_.contact->weight[p]; }
  /// The nodal weights (empty without contact).
  Eigen::VectorXd weights() const {
    return problem_.contact ? problem_.contact->weight : Eigen::VectorXd();
  }
  Method method() const { return method_; }
  const ContactSolverParameters& parameters() const { return options_.contact; }
  const SparsityPattern& pattern() const { return pattern_; }
  Eigen::VectorXd load(double s) const {
    return problem_.load.size() ? Eigen::VectorXd(s * problem_.load)
                                : Eigen::VectorXd(Eigen::VectorXd::Zero(dofs()));
  }

  /// Fill the bulk and contact parts of `x` at x.u, the tangent only `with_tangent` (a
  /// line-search trial needs the residual; the tangent waits until a trial is accepted); false
  /// when the body is outside the law's domain (an inverted triangle).
  bool evaluate(Iterate& x, bool with_tangent) const {
    // The assembly refuses an inverted triangle or a law without admissible state there.
    try {
      if (with_tangent)
        assemble_hyperelastic(*problem_.mesh, *problem_.materials, pattern_, x.u, x.bulk);
      else
        assemble_hyperelastic_force(*problem_.mesh, *problem_.materials, x.u, x.bulk);
    } catch (const Error&) {
      return false;
    }
    x.has_tangent = with_tangent;
    const int m = contacts();
    x.phi.resize(m);
    x.normal.resize(m);
    for (int p = 0; p < m; ++p) {
      const Eigen::Vector2d position = problem_.mesh->nodes[node(p)] + x.u.segment<2>(2 * node(p));
      x.phi[p] = -(problem_.obstacle->signed_distance(position) + offset_[p]);
      x.normal[p] = problem_.obstacle->normal(position);
    }
    if (method_ == Method::penalty)
      for (int p = 0; p < m; ++p)
        x.lambda[p] = weight(p) * penalty_force(x.phi[p], 0.0, parameters().r);
    return true;
  }

  /// The tangent at x.u after a force-only evaluation (the accepted trial of a line search);
  /// true if it had to be assembled.
  bool complete_tangent(Iterate& x) const {
    if (x.has_tangent) return false;
    assemble_hyperelastic(*problem_.mesh, *problem_.materials, pattern_, x.u, x.bulk);
    x.has_tangent = true;
    return true;
  }

  /// The complementarity row of node p, times w to read as a force.
  double complementarity(const Iterate& x, int p) const {
    const double pressure = x.lambda[p] / weight(p);
    const ContactSolverParameters& c = parameters();
    switch (method_) {
    case Method::pdas:
      return weight(p) * alart_curnier_normal(pressure, x.phi[p], 0.0, c.gamma);
    case Method::alm:
      return weight(p) * alart_curnier_normal(pressure, x.phi[p], 0.0, c.r);
    case Method::projection:
      return weight(p) * projection_residual(pressure, x.phi[p], 0.0, c.c) / c.c;
    case Method::penalty:
      return 0.0; // lambda is a function of u
    }
    return 0.0;
  }

  /// ||(R, C)||: equilibrium on the free dofs and the complementarity rows.
  double residual_norm(const Iterate& x, double s, const std::vector<char>& dirichlet) const {
    Eigen::VectorXd r = x.bulk.internal_force - load(s);
    double complementarity_sum = 0;
    for (int p = 0; p < contacts(); ++p) {
      r.segment<2>(2 * node(p)) -= x.lambda[p] * x.normal[p];
      complementarity_sum += std::pow(complementarity(x, p), 2);
    }
    for (int i = 0; i < dofs(); ++i)
      if (dirichlet[i]) r[i] = 0;
    return std::sqrt(r.squaredNorm() + complementarity_sum);
  }

  double force_scale(const Iterate& x, double s) const {
    return std::max({load(s).norm(), x.bulk.internal_force.norm(), 1e-300});
  }

  /// Step (ii) of each method at the iterate x; `previous` is the last active set (empty at
  /// the start).
  std::vector<char> active_set(const Iterate& x, const std::vector<char>& previous) const {
    const ContactSolverParameters& c = parameters();
    std::vector<char> active(contacts());
    for (int p = 0; p < contacts(); ++p) {
      const double pressure = x.lambda[p] / weight(p);
      switch (method_) {
      case Method::pdas:
        active[p] = pdas_is_active(pressure, x.phi[p], 0.0, c.gamma);
        break;
      case Method::alm:
        active[p] = d_positive_part(pressure + c.r * x.phi[p]) > 0;
        break;
      case Method::projection: {
        // The Robin force of a node left inactive relaxes (7.19); its contact pressure is 0.
        const bool was_inactive = !previous.empty() && !previous[p];
        active[p] = projection_is_active(was_inactive ? 0.0 : pressure, x.phi[p], 0.0, c.c);
        break;
      }
      case Method::penalty:
        active[p] = d_penalty_force(x.phi[p], 0.0, c.r) > 0;
        break;
      }
    }
    return active;
  }

  /// d(-lambda_p n(x_p))/du_p, added to the bulk tangent on the block of node p: -lambda_p
  /// dn/dx, the curvature of the obstacle (zero for a plane). The obstacle interface gives n(x)
  /// only, so dn/dx is a central difference.
  Eigen::Matrix2d curvature_block(const Iterate& x, int p) const {
    const Eigen::Vector2d position = problem_.mesh->nodes[node(p)] + x.u.segment<2>(2 * node(p));
    const double h = kNormalDifferenceStep * (1.0 + position.norm());
    Eigen::Matrix2d block;
    for (int j = 0; j < 2; ++j) {
      const Eigen::Vector2d e = h * Eigen::Vector2d::Unit(j);
      block.col(j) =
          -x.lambda[p] *
          (problem_.obstacle->normal(position + e) - problem_.obstacle->normal(position - e)) /
          (2 * h);
    }
    return block;
  }

private:
  const FiniteStrainProblem& problem_;
  const FiniteStrainOptions& options_;
  Method method_;
  SparsityPattern pattern_;
  std::vector<double> offset_; ///< g_p - d(X_p): the extra gap of the CONTACT card
};

/// The Newton direction (du, lambda at the full step) of one iteration (header comment).
struct NewtonStep {
  Eigen::VectorXd du;
  Eigen::VectorXd lambda;
};

NewtonStep newton_step(const Setting& setting, const Iterate& x, const std::vector<char>& active,
                       const std::vector<int>& dirichlet_dofs,
                       const Eigen::VectorXd& dirichlet_increment, double s, NewtonMatrix& J,
                       LinearSolver& solver) {
  const int m = setting.contacts();
  const ContactSolverParameters& c = setting.parameters();
  J.set_tangent(x.bulk.tangent);
  for (int p = 0; p < m; ++p)
    if (x.lambda[p] != 0.0) J.add_node_block(p, setting.curvature_block(x, p));
  J.rotate(x.normal);
  // r0 = Q^T (f_int - s f_ext).
  Eigen::VectorXd r0 = x.bulk.internal_force - setting.load(s);
  for (int p = 0; p < m; ++p) {
    const Eigen::Vector2d r = r0.segment<2>(2 * setting.node(p));
    r0.segment<2>(2 * setting.node(p)) = nodal_frame(x.normal[p]).transpose() * r;
  }

  // Imposed increments: the Dirichlet dofs (never contact nodes) and, for the active-set
  // methods, du_n = -phi on the active nodes, so that the linearized penetration vanishes.
  std::vector<std::pair<int, double>> imposed;
  for (std::size_t k = 0; k < dirichlet_dofs.size(); ++k)
    imposed.emplace_back(dirichlet_dofs[k], dirichlet_increment[static_cast<Eigen::Index>(k)]);
  for (int p = 0; p < m; ++p) {
    const int normal_dof = 2 * setting.node(p) + 1;
    const double w = setting.weight(p);
    switch (setting.method()) {
    case Method::penalty:
      if (active[p]) {
        J.diagonal(normal_dof) += w * c.r;
        r0[normal_dof] += x.lambda[p];
      }
      break;
    case Method::projection:
      if (!active[p]) J.diagonal(normal_dof) += w / c.c;
      [[fallthrough]];
    case Method::pdas:
    case Method::alm:
      if (active[p]) imposed.emplace_back(normal_dof, -x.phi[p]);
      break;
    }
  }
  std::sort(imposed.begin(), imposed.end());
  const Eigen::VectorXd dw = J.solve(r0, imposed, solver);

  // Multipliers: the reaction of an imposed normal (r0 + A dw + lambda = 0 on its row), the
  // Robin force w / c du_n on the inactive nodes of the projection, 0 elsewhere.
  NewtonStep step;
  step.lambda = Eigen::VectorXd::Zero(m);
  if (setting.method() != Method::penalty) {
    for (int p = 0; p < m; ++p) {
      const int normal_dof = 2 * setting.node(p) + 1;
      if (active[p])
        step.lambda[p] = -(r0[normal_dof] + J.normal_row_times(p, dw));
      else if (setting.method() == Method::projection)
        step.lambda[p] = setting.weight(p) * dw[normal_dof] / c.c;
    }
  }
  // du = Q dw.
  step.du = dw;
  for (int p = 0; p < m; ++p) {
    const int a = 2 * setting.node(p);
    step.du.segment<2>(a) = nodal_frame(x.normal[p]) * dw.segment<2>(a);
  }
  return step;
}

/// Line search (header): alpha = 1, 1/2, ... until the trial is admissible and lowers the
/// residual ||R(x)|| = residual_before, else the largest admissible alpha (at once without
/// seek_decrease); 0 if every length folds the mesh. Each trial counts one bulk evaluation. The
/// first trial is assembled with its tangent (it is accepted in most iterations), the later ones
/// without; the accepted one gets its tangent in load_step. The accepted trial's residual norm
/// is returned in accepted_residual; `trial` is scratch space whose storage is reused from one
/// iteration to the next.
double line_search(const Setting& setting, const Iterate& x, const NewtonStep& step, double s,
                   const std::vector<char>& dirichlet, double residual_before, Iterate& accepted,
                   Iterate& trial, bool seek_decrease, double& accepted_residual,
                   int& evaluations) {
  double accepted_alpha = 0;
  double alpha = 1;
  for (int h = 0; h <= kMaxHalvings; ++h, alpha /= 2) {
    trial.u = x.u + alpha * step.du;
    trial.lambda = x.lambda + alpha * (step.lambda - x.lambda);
    ++evaluations;
    if (!setting.evaluate(trial, h == 0)) continue;
    const double trial_residual = setting.residual_norm(trial, s, dirichlet);
    const bool decreases = trial_residual < residual_before;
    if (accepted_alpha == 0 || decreases) {
      std::swap(accepted, trial);
      accepted_alpha = alpha;
      accepted_residual = trial_residual;
    }
    if (decreases || (!seek_decrease && accepted_alpha > 0)) break;
  }
  return accepted_alpha;
}

/// One load step s: Newton iterations from x (updated in place) until test (iv) holds.
LoadStepResult load_step(const Setting& setting, const FiniteStrainProblem& problem, double s,
                         const std::vector<char>& dirichlet, NewtonMatrix& J, LinearSolver& solver,
                         Iterate& x, std::vector<char>& previous_active) {
  const ContactSolverParameters& c = setting.parameters();
  LoadStepResult result;
  result.load_factor = s;
  const Eigen::VectorXd target = s * problem.dirichlet_values;

  double residual_norm = setting.residual_norm(x, s, dirichlet);
  Iterate accepted, trial; // line-search storage, reused by every iteration
  for (int iteration = 0; iteration < c.max_iterations; ++iteration) {
    // (ii) active set, (iii) the linearized problem with it, then the line search.
    const std::vector<char> active = setting.active_set(x, previous_active);
    Eigen::VectorXd dirichlet_increment(target.size());
    for (Eigen::Index d = 0; d < target.size(); ++d)
      dirichlet_increment[d] = target[d] - x.u[problem.dirichlet_dofs[d]];
    NewtonStep step;
    try {
      result.bulk_evaluations += setting.complete_tangent(x) ? 1 : 0;
      step = newton_step(setting, x, active, problem.dirichlet_dofs, dirichlet_increment, s, J,
                         solver);
    } catch (const Error& e) {
      result.failure = std::string("the generalized Jacobian could not be factorized: ") + e.what();
      break;
    }
    // The first iteration of a load step starts from the previous load's converged state, whose
    // residual is already below the tolerance (the new Dirichlet values are not in R): the
    // trials, each carrying part of the new Dirichlet increment, do not lower it, and the search
    // would end on the largest admissible alpha after 12 wasted bulk assemblies. Take it at once.
    const bool seek_decrease = iteration > 0 || residual_norm > c.eps * setting.force_scale(x, s);
    const double alpha = line_search(setting, x, step, s, dirichlet, residual_norm, accepted, trial,
                                     seek_decrease, residual_norm, result.bulk_evaluations);
    if (alpha == 0) {
      result.failure =
          "every step length down to 2^-" + std::to_string(kMaxHalvings) + " inverts a triangle";
      break;
    }

    const Increment increment =
        increment_between(stack(accepted.u, accepted.lambda, setting.weights()),
                          stack(x.u, x.lambda, setting.weights()));
    std::swap(x, accepted);
    const double residual = residual_norm / setting.force_scale(x, s);
    double mismatch = 0;
    for (Eigen::Index d = 0; d < target.size(); ++d)
      mismatch = std::max(mismatch, std::abs(target[d] - x.u[problem.dirichlet_dofs[d]]));
    result.history.push_back({count_active(active), residual, increment.relative, increment.norm});
    result.step_length.push_back(alpha);

    // (iv) the iterate no longer moves, R vanishes, the Dirichlet values are reached and
    // (except for alm) A(k+1) = A(k).
    const bool settled = setting.method() == Method::alm || active == previous_active;
    previous_active = active;
    const double reached =
        c.eps * std::max(target.lpNorm<Eigen::Infinity>(), x.u.lpNorm<Eigen::Infinity>());
    if (increment.relative <= c.eps && residual <= c.eps && settled && mismatch <= reached) {
      result.converged = true;
      break;
    }
  }
  if (!result.converged && result.failure.empty())
    result.failure = "no convergence within the iteration limit";
  result.u = x.u;
  result.multiplier = x.lambda;
  // The set the last iteration used (at convergence, the set the state satisfies).
  result.active = previous_active.empty() ? setting.active_set(x, {}) : previous_active;
  return result;
}

} // namespace

bool FiniteStrainSolution::converged() const {
  return !steps.empty() &&
         std::all_of(steps.begin(), steps.end(), [](const auto& s) { return s.converged; });
}

int FiniteStrainSolution::total_iterations() const {
  int n = 0;
  for (const LoadStepResult& s : steps)
    n += s.iterations();
  return n;
}

FiniteStrainSolution solve_finite_strain_contact(const FiniteStrainProblem& problem,
                                                 const FiniteStrainOptions& options) {
  SIG_VERIFY(problem.mesh && problem.materials, "finite-strain contact needs a mesh and materials");
  const int ndof = 2 * problem.mesh->num_nodes();
  const bool has_contact = problem.contact && problem.contact->size() > 0;
  SIG_VERIFY(!has_contact || problem.obstacle, "contact elements without an obstacle");
  SIG_VERIFY(problem.load.size() == 0 || problem.load.size() == ndof,
             "load has " << problem.load.size() << " values for " << ndof << " dofs");
  SIG_VERIFY(static_cast<Eigen::Index>(problem.dirichlet_dofs.size()) ==
                 problem.dirichlet_values.size(),
             problem.dirichlet_dofs.size()
                 << " Dirichlet dofs but " << problem.dirichlet_values.size() << " values");
  SIG_VERIFY(options.load_steps >= 1, "load_steps must be >= 1, not " << options.load_steps);
  std::vector<char> dirichlet(ndof, 0);
  for (std::size_t k = 0; k < problem.dirichlet_dofs.size(); ++k) {
    const int dof = problem.dirichlet_dofs[k];
    SIG_VERIFY(dof >= 0 && dof < ndof && (k == 0 || dof > problem.dirichlet_dofs[k - 1]),
               "Dirichlet dofs must be sorted, unique and < " << ndof);
    dirichlet[dof] = 1;
  }
  FiniteStrainProblem checked = problem;
  if (!has_contact) checked.contact = nullptr;
  const Setting setting(checked, options);
  for (int p = 0; p < setting.contacts(); ++p)
    for (int a = 0; a < 2; ++a)
      SIG_VERIFY(!dirichlet[2 * setting.node(p) + a],
                 "contact node " << setting.node(p) + 1 << " has a Dirichlet condition");

  const int m = setting.contacts();
  auto solver = make_linear_solver(
      options.backend, options.backend == "cholmod" ? MatrixKind::spd : MatrixKind::symmetric);
  FiniteStrainSolution solution;
  solution.unknowns = ndof + (setting.method() == Method::alm ? m : 0);

  Iterate x;
  x.u = Eigen::VectorXd::Zero(ndof);
  x.lambda = Eigen::VectorXd::Zero(m);
  SIG_VERIFY(setting.evaluate(x, true), "the reference configuration has an inverted triangle");
  std::vector<int> contact_nodes(m);
  for (int p = 0; p < m; ++p)
    contact_nodes[p] = setting.node(p);
  NewtonMatrix J(setting.pattern(), dirichlet, contact_nodes);
  std::vector<char> previous_active;
  for (int k = 1; k <= options.load_steps; ++k) {
    const double s = static_cast<double>(k) / options.load_steps;
    solution.steps.push_back(
        load_step(setting, checked, s, dirichlet, J, *solver, x, previous_active));
    if (!solution.steps.back().converged) break; // later steps start from a wrong state
  }
  return solution;
}

} // namespace sig
