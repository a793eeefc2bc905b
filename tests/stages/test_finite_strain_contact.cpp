// Hyperelastic contact in large deformation (stages/finite_strain_contact.hpp): the methods agree
// with each other and satisfy Signorini and global equilibrium on a pressed block, reduce to the
// small-strain solver for small loads, and Newton converges quadratically without contact.
#include "assembly/nonlinear.hpp"
#include "assembly/system.hpp"
#include "core/error.hpp"
#include "material/ciarlet_geymonat.hpp"
#include "material/mili.hpp"
#include "mesh/generators.hpp"
#include "stages/finite_strain_contact.hpp"
#include "stages/small_strain_start.hpp"
#include "stages/static_solve.hpp"

#include <Eigen/SVD>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <utility>

namespace {

using sig::FiniteStrainOptions;
using sig::FiniteStrainProblem;

/// The thesis's Ciarlet-Geymonat ring material (c1 = 0.5, c2 = 0.005, a = 0.35), plane strain.
sig::MaterialTable hyperelastic_material(const sig::Mesh& mesh) {
  const auto law = std::make_shared<const sig::CiarletGeymonat>(0.5, 0.005, 0.35);
  sig::MaterialTable table;
  for (int subdomain : mesh.subdomains()) {
    sig::SubdomainMaterial material;
    material.subdomain = subdomain;
    material.hooke = law->linearized();
    material.hyperelastic = law;
    table.entries.push_back(material);
  }
  return table;
}

/// A block [0, 1] x [0, 0.5] with a parabolic bottom x2 = 0.4 (x1 - 1/2)^2 touching the
/// foundation x2 <= 0 at its middle node, its top (ref 2) moved down by `press` and held
/// horizontally: the contact zone spreads over the bottom as the press grows. (A thick block:
/// unlike a thin ring on one contact node, its symmetric state has no sway instability.)
sig::Mesh rounded_block(int nx, int ny) {
  sig::Mesh mesh = sig::rectangle(1.0, 0.5, nx, ny);
  for (sig::Point& x : mesh.nodes)
    x.y() += 0.4 * (x.x() - 0.5) * (x.x() - 0.5) * (1.0 - x.y() / 0.5);
  return mesh;
}

struct PressedBlock {
  sig::Mesh mesh;
  sig::MaterialTable table;
  std::shared_ptr<const sig::Obstacle> foundation;
  sig::ContactElements contact;
  std::vector<int> dirichlet_dofs;
  Eigen::VectorXd dirichlet_values;

  PressedBlock(int nx, int ny, double press,
               std::shared_ptr<const sig::Obstacle> obstacle =
                   std::make_shared<const sig::HalfPlane>(Eigen::Vector2d(0.0, 0.0),
                                                          Eigen::Vector2d(0.0, 1.0)))
      : mesh(rounded_block(nx, ny)), table(hyperelastic_material(mesh)),
        foundation(std::move(obstacle)),
        contact(sig::build_contact_elements(mesh, 3, *foundation)) {
    const std::vector<int> top = mesh.nodes_with_ref(2);
    dirichlet_values.resize(2 * static_cast<Eigen::Index>(top.size()));
    for (std::size_t k = 0; k < top.size(); ++k) {
      dirichlet_dofs.push_back(2 * top[k]);
      dirichlet_dofs.push_back(2 * top[k] + 1);
      dirichlet_values[2 * static_cast<Eigen::Index>(k)] = 0.0;
      dirichlet_values[2 * static_cast<Eigen::Index>(k) + 1] = -press;
    }
  }

  FiniteStrainProblem problem() const {
    FiniteStrainProblem p;
    p.mesh = &mesh;
    p.materials = &table;
    p.dirichlet_dofs = dirichlet_dofs;
    p.dirichlet_values = dirichlet_values;
    p.contact = &contact;
    p.obstacle = foundation.get();
    return p;
  }
};

/// A ring r_in <= |x - (0, R)| <= R on the foundation x2 <= 0 (sig::ring, N nodes around), the
/// outer nodes with x2 >= 0.99 (2R) (AB, ref 1) moved by (0, -press), Gamma3 the outer edges
/// below x2 = R (1 + sqrt(2) / 2).
struct PressedRing {
  sig::Mesh mesh;
  sig::MaterialTable table;
  sig::HalfPlane foundation{Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(0.0, 1.0)};
  sig::ContactElements contact;
  FiniteStrainProblem problem;

  PressedRing(double r_in, double R, int N, double press)
      : mesh(sig::ring({0.0, R}, r_in, R, N)), table(hyperelastic_material(mesh)),
        contact(sig::build_contact_elements(mesh, 3, foundation)) {
    problem.mesh = &mesh;
    problem.materials = &table;
    problem.contact = &contact;
    problem.obstacle = &foundation;
    const std::vector<int> top = mesh.nodes_with_ref(1);
    problem.dirichlet_values = Eigen::VectorXd::Zero(2 * static_cast<Eigen::Index>(top.size()));
    for (std::size_t k = 0; k < top.size(); ++k) {
      problem.dirichlet_dofs.push_back(2 * top[k]);
      problem.dirichlet_dofs.push_back(2 * top[k] + 1);
      problem.dirichlet_values[2 * static_cast<Eigen::Index>(k) + 1] = -press;
    }
  }
  PressedRing(const PressedRing&) = delete; // problem points into the members
};

/// Contact elements whose normal status is not free.
int in_contact(const std::vector<sig::NormalStatus>& status) {
  return static_cast<int>(std::count_if(status.begin(), status.end(), [](sig::NormalStatus s) {
    return s != sig::NormalStatus::free;
  }));
}

FiniteStrainOptions options_for(const std::string& method, int steps, double eps) {
  FiniteStrainOptions o;
  o.contact.method = method;
  o.contact.eps = eps;
  o.contact.max_iterations = 100;
  o.load_steps = steps;
  return o;
}

/// Iterations k -> k + 1 in the asymptotic range (relative residual below 1e-2, next one above
/// round-off, same active set) where Newton's quadratic rate r(k+1) <= 10 r(k)^2 holds; -1 if
/// one such iteration breaks it.
int quadratic_steps(const std::vector<sig::IterationRecord>& history) {
  int n = 0;
  for (std::size_t k = 0; k + 1 < history.size(); ++k) {
    const double now = history[k].residual;
    const double next = history[k + 1].residual;
    if (now > 1e-2 || next < 1e-13 || history[k].active != history[k + 1].active) continue;
    if (next > 10 * now * now) return -1;
    ++n;
  }
  return n;
}

/// Signorini at the current positions and equilibrium between the contact forces and the
/// reactions of Gamma1.
void expect_signorini_and_balance(const PressedBlock& body, const sig::LoadStepResult& s,
                                  double tol) {
  const sig::ContactElements& c = body.contact;
  Eigen::Vector2d contact_force = Eigen::Vector2d::Zero();
  for (int p = 0; p < c.size(); ++p) {
    const Eigen::Vector2d x = body.mesh.nodes[c.node[p]] + s.u.segment<2>(2 * c.node[p]);
    const double gap = body.foundation->signed_distance(x);
    const double pressure = s.multiplier[p] / c.weight[p];
    EXPECT_GE(gap, -tol) << "penetration at element " << p;
    EXPECT_GE(pressure, -tol) << "tension at element " << p;
    EXPECT_NEAR(pressure * gap, 0.0, tol) << "element " << p;
    contact_force += s.multiplier[p] * body.foundation->normal(x);
  }
  // The internal forces of a body balance (translation invariance of W), so the force the
  // support applies on Gamma1, f_int there, is the total contact force pushing down.
  sig::HyperelasticState state;
  sig::assemble_hyperelastic(body.mesh, body.table, sig::SparsityPattern(body.mesh), s.u, state);
  Eigen::Vector2d reaction = Eigen::Vector2d::Zero();
  for (int dof : body.dirichlet_dofs)
    reaction[dof % 2] += state.internal_force[dof];
  EXPECT_GT(contact_force.y(), 0.0);
  EXPECT_NEAR(-reaction.x(), contact_force.x(), 1e-6 * contact_force.norm());
  EXPECT_NEAR(-reaction.y(), contact_force.y(), 1e-6 * contact_force.norm());
}

TEST(FiniteStrainContact, MethodsAgreeOnAPressedBlock) {
  const PressedBlock body(16, 8, 0.1);
  const FiniteStrainProblem problem = body.problem();
  const sig::FiniteStrainSolution pdas =
      sig::solve_finite_strain_contact(problem, options_for("pdas", 4, 1e-10));
  ASSERT_TRUE(pdas.converged()) << pdas.steps.back().failure;
  const sig::LoadStepResult& reference = pdas.steps.back();
  ASSERT_GE(in_contact(reference.normal_status), 3) << "the test needs a contact zone";
  ASSERT_LT(in_contact(reference.normal_status), body.contact.size()) << "and a free boundary";
  expect_signorini_and_balance(body, reference, 1e-8);
  for (const sig::LoadStepResult& step : pdas.steps)
    EXPECT_LE(step.iterations(), 8) << "a Newton method needs few iterations per load step";

  for (const char* method : {"alm", "projection"}) {
    const sig::FiniteStrainSolution s =
        sig::solve_finite_strain_contact(problem, options_for(method, 4, 1e-10));
    ASSERT_TRUE(s.converged()) << method << ": " << s.steps.back().failure;
    const sig::LoadStepResult& last = s.steps.back();
    EXPECT_EQ(last.normal_status, reference.normal_status) << method;
    EXPECT_LE((last.multiplier - reference.multiplier).lpNorm<Eigen::Infinity>(),
              1e-6 * reference.multiplier.lpNorm<Eigen::Infinity>())
        << method;
    EXPECT_LE((last.u - reference.u).lpNorm<Eigen::Infinity>(),
              1e-6 * reference.u.lpNorm<Eigen::Infinity>())
        << method;
    expect_signorini_and_balance(body, last, 1e-8);
  }
  EXPECT_EQ(sig::solve_finite_strain_contact(problem, options_for("alm", 4, 1e-10)).unknowns,
            pdas.unknowns + body.contact.size());
}

TEST(FiniteStrainContact, EveryBackendReachesTheSameState) {
  const PressedBlock body(16, 8, 0.1);
  FiniteStrainOptions o = options_for("pdas", 4, 1e-10);
  const sig::FiniteStrainSolution reference = sig::solve_finite_strain_contact(body.problem(), o);
  ASSERT_TRUE(reference.converged());
  for (const char* backend : {"cholmod", "mumps"}) {
    o.backend = backend;
    const sig::FiniteStrainSolution s = sig::solve_finite_strain_contact(body.problem(), o);
    ASSERT_TRUE(s.converged()) << backend << ": " << s.steps.back().failure;
    EXPECT_LE((s.steps.back().u - reference.steps.back().u).lpNorm<Eigen::Infinity>(), 1e-9)
        << backend;
  }
}

TEST(FiniteStrainContact, PenaltyPenetratesByPressureOverR) {
  const PressedBlock body(16, 8, 0.1);
  FiniteStrainOptions o = options_for("penalty", 4, 1e-10);
  o.contact.r = 1e4;
  const sig::FiniteStrainSolution s = sig::solve_finite_strain_contact(body.problem(), o);
  ASSERT_TRUE(s.converged()) << s.steps.back().failure;
  const sig::FiniteStrainSolution pdas =
      sig::solve_finite_strain_contact(body.problem(), options_for("pdas", 4, 1e-10));
  ASSERT_TRUE(pdas.converged());
  const sig::LoadStepResult& last = s.steps.back();
  for (int p = 0; p < body.contact.size(); ++p) {
    const int node = body.contact.node[p];
    const double gap =
        body.foundation->signed_distance(body.mesh.nodes[node] + last.u.segment<2>(2 * node));
    const double pressure = last.multiplier[p] / body.contact.weight[p];
    EXPECT_NEAR(pressure, o.contact.r * std::max(-gap, 0.0), 1e-9) << "element " << p;
  }
  // The Winkler foundation tends to the rigid one as r grows: here within a few per cent.
  const double scale = pdas.steps.back().multiplier.lpNorm<Eigen::Infinity>();
  EXPECT_LE((last.multiplier - pdas.steps.back().multiplier).lpNorm<Eigen::Infinity>(),
            0.05 * scale);
}

TEST(FiniteStrainContact, SmallLoadsMatchTheSmallStrainSolver) {
  double previous_error = 0;
  for (double press : {5e-4, 1e-3}) {
    const PressedBlock body(16, 8, press);
    const sig::FiniteStrainSolution s =
        sig::solve_finite_strain_contact(body.problem(), options_for("pdas", 1, 1e-12));
    ASSERT_TRUE(s.converged()) << s.steps.back().failure;

    // The small-strain problem with the linearized law (the table's Hooke part).
    sig::LinearSystem system;
    system.K = sig::assemble_stiffness(body.mesh, body.table, sig::SparsityPattern(body.mesh));
    system.f = Eigen::VectorXd::Zero(2 * body.mesh.num_nodes());
    system.M_lumped = system.f;
    system.dirichlet_dofs = body.dirichlet_dofs;
    system.dirichlet_values = body.dirichlet_values;
    sig::ContactSolverParameters parameters;
    parameters.method = "pdas";
    parameters.eps = 1e-9;
    const sig::StaticSolution linear =
        sig::solve_static_contact(system, body.contact, parameters, "umfpack");
    ASSERT_TRUE(linear.converged) << linear.failure;
    EXPECT_EQ(s.steps.back().normal_status, linear.normal_status);

    // Both solve the same problem to first order: they differ by O(press^2).
    const double error = (s.steps.back().u - linear.u).norm();
    EXPECT_LT(error, 1e-3 * linear.u.norm());
    EXPECT_NEAR(s.steps.back().multiplier.sum(), linear.multiplier.sum(),
                1e-3 * linear.multiplier.sum());
    if (previous_error > 0) {
      EXPECT_GT(error / previous_error, 3.8) << "not second order in the load";
      EXPECT_LT(error / previous_error, 4.2) << "not second order in the load";
    }
    previous_error = error;
  }
}

/// A block [0, 1] x [0, 0.5] clamped on its left side (ref 1), its right side (ref 4) moved by
/// `shift`; no contact.
FiniteStrainProblem clamped_block(const sig::Mesh& mesh, const sig::MaterialTable& table,
                                  const Eigen::Vector2d& shift) {
  FiniteStrainProblem problem;
  problem.mesh = &mesh;
  problem.materials = &table;
  std::vector<std::pair<int, double>> imposed;
  for (int node : mesh.nodes_with_ref(4)) {
    imposed.emplace_back(2 * node, shift.x());
    imposed.emplace_back(2 * node + 1, shift.y());
  }
  for (int node : mesh.nodes_with_ref(1)) { // the left side wins at shared corners
    imposed.emplace_back(2 * node, 0.0);
    imposed.emplace_back(2 * node + 1, 0.0);
  }
  std::stable_sort(imposed.begin(), imposed.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::pair<int, double>> unique;
  for (const auto& entry : imposed)
    if (unique.empty() || unique.back().first != entry.first)
      unique.push_back(entry);
    else
      unique.back() = entry;
  problem.dirichlet_values.resize(static_cast<Eigen::Index>(unique.size()));
  for (std::size_t k = 0; k < unique.size(); ++k) {
    problem.dirichlet_dofs.push_back(unique[k].first);
    problem.dirichlet_values[static_cast<Eigen::Index>(k)] = unique[k].second;
  }
  return problem;
}

TEST(FiniteStrainContact, NewtonConvergesQuadraticallyWithoutContact) {
  // Large rotation and stretch, no contact.
  const sig::Mesh mesh = sig::rectangle(1.0, 0.5, 8, 4);
  const sig::MaterialTable table = hyperelastic_material(mesh);
  const FiniteStrainProblem problem = clamped_block(mesh, table, {0.3, 0.2});
  const sig::FiniteStrainSolution s =
      sig::solve_finite_strain_contact(problem, options_for("pdas", 1, 1e-12));
  ASSERT_TRUE(s.converged()) << s.steps.back().failure;
  EXPECT_GE(quadratic_steps(s.steps.back().history), 1);
}

// The Newton step from rest of a problem without contact: the linear elastic solution with its
// Dirichlet values (the tangent at rest is the linearized law).
Eigen::VectorXd first_step_from_rest(const sig::Mesh& mesh, const sig::MaterialTable& table,
                                     const FiniteStrainProblem& problem) {
  sig::LinearSystem linear;
  linear.K = sig::assemble_stiffness(mesh, table, sig::SparsityPattern(mesh));
  linear.f = Eigen::VectorXd::Zero(2 * mesh.num_nodes());
  linear.M_lumped = linear.f;
  linear.dirichlet_dofs = problem.dirichlet_dofs;
  linear.dirichlet_values = problem.dirichlet_values;
  return sig::solve_linear_elasticity(linear, "umfpack").u;
}

TEST(FiniteStrainContact, LineSearchRescuesAStepThatFoldsTheMesh) {
  // The right side moved by (-1.2, 0.8) in one load step: the first Newton step (the imposed
  // displacement with the tangent at rest) folds triangles, so the line search shortens it.
  const sig::Mesh mesh = sig::rectangle(1.0, 0.5, 8, 4);
  const sig::MaterialTable table = hyperelastic_material(mesh);
  const FiniteStrainProblem problem = clamped_block(mesh, table, {-1.2, 0.8});
  // That first step is the linear elastic solution (tangent at rest = the linearized law).
  const Eigen::VectorXd full_step = first_step_from_rest(mesh, table, problem);
  ASSERT_FALSE(std::isfinite(sig::hyperelastic_energy(mesh, table, full_step)));

  const sig::FiniteStrainSolution s =
      sig::solve_finite_strain_contact(problem, options_for("pdas", 1, 1e-10));
  ASSERT_TRUE(s.converged()) << s.steps.back().failure;
  const sig::LoadStepResult& step = s.steps.back();
  EXPECT_LT(step.step_length.front(), 1.0);
  EXPECT_EQ(step.step_length.back(), 1.0) << "full Newton steps near the solution";
  EXPECT_TRUE(std::isfinite(sig::hyperelastic_energy(mesh, table, step.u))) << "no fold";
  for (std::size_t k = 0; k < problem.dirichlet_dofs.size(); ++k)
    EXPECT_NEAR(step.u[problem.dirichlet_dofs[k]],
                problem.dirichlet_values[static_cast<Eigen::Index>(k)], 1e-12);
}

TEST(FiniteStrainContact, StepIsTrustedWhileNoStretchChangesByMoreThanAHalf) {
  // From rest the Newton step of the block whose right side moves by (-1.2, 0.8) is the linear
  // elastic solution du; the bulk trusts it up to alpha = (1/2) / max_e ||grad du||_2 (P1: one
  // gradient per triangle, the largest singular value computed here by an SVD). The contact
  // driver starts the first step's search there (the ring:
  // tests/pipeline/ring_getfem_iterations.sh).
  const sig::Mesh mesh = sig::rectangle(1.0, 0.5, 8, 4);
  const sig::MaterialTable table = hyperelastic_material(mesh);
  const FiniteStrainProblem problem = clamped_block(mesh, table, {-1.2, 0.8});
  const Eigen::VectorXd du = first_step_from_rest(mesh, table, problem);
  double largest = 0;
  for (const sig::Simplex& cell : mesh.cells) {
    Eigen::Matrix2d x, d;
    for (int j = 0; j < 2; ++j) {
      x.col(j) = mesh.nodes[cell[j + 1]] - mesh.nodes[cell[0]];
      d.col(j) = du.segment<2>(2 * cell[j + 1]) - du.segment<2>(2 * cell[0]);
    }
    largest =
        std::max(largest, Eigen::JacobiSVD<Eigen::Matrix2d>(d * x.inverse()).singularValues()[0]);
  }
  ASSERT_GT(largest, 0.5) << "the full step must be beyond the trusted change";

  sig::FiniteStrainBulk bulk(problem, "umfpack", 1e-8);
  EXPECT_EQ(bulk.trusted_length(), std::numeric_limits<double>::infinity()) << "before a solve";
  bulk.solve({}, Eigen::VectorXd());
  EXPECT_NEAR(bulk.trusted_length(), 0.5 / largest, 1e-10 / largest);
}

TEST(FiniteStrainContact, RewindMakesTheCheckpointPresentAgain) {
  // The watchdog's return (solver/contact_newton.hpp): after two accepted Newton steps beyond a
  // checkpoint, rewind() gives back the bulk that was there, its residual and its next step's
  // iterate bit for bit (the state is evaluated again from the remembered u, whose first step
  // was a half one: not a point the later steps pass through).
  const sig::Mesh mesh = sig::rectangle(1.0, 0.5, 8, 4);
  const sig::MaterialTable table = hyperelastic_material(mesh);
  const FiniteStrainProblem problem = clamped_block(mesh, table, {0.3, 0.2});
  sig::FiniteStrainBulk bulk(problem, "umfpack", 1e-8);
  ASSERT_EQ(bulk.contacts(), 0);
  const Eigen::VectorXd none;
  const auto accept = [&](double alpha) {
    bulk.solve({}, none);
    EXPECT_TRUE(bulk.move(alpha));
    bulk.keep();
    bulk.restore();
    return std::pair{bulk.equilibrium_residual(none, none), bulk.displacement_norm()};
  };
  accept(0.5);
  bulk.checkpoint();
  const auto at_checkpoint =
      std::pair{bulk.equilibrium_residual(none, none), bulk.displacement_norm()};
  const auto one_step = accept(1.0);
  const auto two_steps = accept(1.0);
  ASSERT_NE(two_steps, at_checkpoint);
  bulk.rewind();
  EXPECT_EQ(std::pair(bulk.equilibrium_residual(none, none), bulk.displacement_norm()),
            at_checkpoint);
  EXPECT_EQ(accept(1.0), one_step);
}

TEST(FiniteStrainContact, CurvedObstacleKeepsNewtonsRate) {
  // The block pressed onto a disc off its axis: normals change with the position of the nodes
  // and the contact forces have a horizontal part.
  const PressedBlock body(16, 8, 0.1,
                          std::make_shared<const sig::Disc>(Eigen::Vector2d(0.6, -2.0), 2.0));
  for (const char* method : {"pdas", "alm", "projection"}) {
    const sig::FiniteStrainSolution s =
        sig::solve_finite_strain_contact(body.problem(), options_for(method, 4, 1e-10));
    ASSERT_TRUE(s.converged()) << method << ": " << s.steps.back().failure;
    expect_signorini_and_balance(body, s.steps.back(), 1e-8);
    if (method == std::string("projection")) continue; // its Robin relaxation is linear
    // The curvature term -lambda dn/dx makes the Jacobian consistent: quadratic once the
    // active set is found.
    for (const sig::LoadStepResult& step : s.steps)
      EXPECT_GE(quadratic_steps(step.history), 0) << method << " at load " << step.load_factor;
    EXPECT_GE(quadratic_steps(s.steps.back().history), 1) << method;
  }
}

TEST(FiniteStrainContact, ProjectionStallsForSmallCOnAThinRing) {
  // A thin ring (radii 0.9 and 1) pressed onto the foundation by its top arc. The projection's
  // Robin spring s = w / c on the inactive normals makes each step proximal: its error
  // contracts by 1 / (1 + theta), theta the smallest eigenvalue of K v = theta s v on those
  // normals (K the tangent with Gamma1 and the active normals held), and a soft ring has a
  // small theta for small c: slow linear convergence, Nv within the iteration limit (thesis
  // Tables 7.4, 7.5, small c). Where K is indefinite (a thicker ring, radii 0.7 and 1, whose
  // symmetric state with a sliding bottom is a saddle) it diverges instead. PDAS, a Newton
  // method, and the projection with a large c reach the same state.
  const PressedRing ring(0.9, 1.0, 64, 0.2);
  const FiniteStrainProblem& problem = ring.problem;
  const sig::FiniteStrainSolution pdas =
      sig::solve_finite_strain_contact(problem, options_for("pdas", 2, 1e-8));
  ASSERT_TRUE(pdas.converged()) << pdas.steps.back().failure;
  FiniteStrainOptions small = options_for("projection", 2, 1e-8);
  small.contact.c = 10;
  const sig::FiniteStrainSolution diverged = sig::solve_finite_strain_contact(problem, small);
  EXPECT_FALSE(diverged.converged());
  EXPECT_FALSE(diverged.steps.back().failure.empty());
  // A slow linear rate, not a blow-up: still decreasing, by less than half in 5 iterations.
  const std::vector<sig::IterationRecord>& h = diverged.steps.back().history;
  ASSERT_EQ(h.size(), 100u);
  EXPECT_LT(h.back().residual, 1e-3 * h.front().residual);
  EXPECT_GT(h.back().residual, 0.5 * h[h.size() - 6].residual);

  FiniteStrainOptions large = options_for("projection", 2, 1e-8);
  large.contact.c = 1e6;
  const sig::FiniteStrainSolution converged = sig::solve_finite_strain_contact(problem, large);
  ASSERT_TRUE(converged.converged()) << converged.steps.back().failure;
  EXPECT_LE(
      (converged.steps.back().multiplier - pdas.steps.back().multiplier).lpNorm<Eigen::Infinity>(),
      1e-6 * pdas.steps.back().multiplier.lpNorm<Eigen::Infinity>());
}

TEST(FiniteStrainContact, PdasInOneLoadStepDoesNotDependOnGamma) {
  // Scene 7b's ring at N = 64 crushed by 14 of its 20 mm in one load step (thesis Table 7.5:
  // "the values of gamma have practically no influence"). The semi-smooth Newton imposes
  // conditions that do not depend on gamma, only the active sets do: the same active set at
  // every iteration for every gamma, and ALM, the same test with r = gamma, the same too. Before
  // the line search held the branches of the test (contact_newton.hpp), gamma weighed the
  // penetration of inactive nodes in its merit: 10, 12, 12, 11 iterations for gamma = 10, 1e2,
  // 1e4, 1e6. From rest: full steps keep every wall node's q_n = 0 and every other node's
  // lambda = 0, so the test lambda + gamma q_n never weighs one against the other.
  const PressedRing ring(9, 10, 64, 14);
  std::vector<int> reference;
  for (double gamma : {10.0, 1e2, 1e4, 1e6}) {
    FiniteStrainOptions o = options_for("pdas", 1, 1e-5);
    o.small_strain_start = false;
    o.contact.gamma = gamma;
    const sig::FiniteStrainSolution s = sig::solve_finite_strain_contact(ring.problem, o);
    ASSERT_TRUE(s.converged()) << "gamma " << gamma << ": " << s.steps.back().failure;
    const std::vector<sig::IterationRecord>& h = s.steps.back().history;
    std::vector<int> active;
    int previous = 0;
    for (const sig::IterationRecord& record : h) {
      active.push_back(record.active);
      EXPECT_EQ(record.active - previous, record.entered - record.left) << "gamma " << gamma;
      previous = record.active;
    }
    if (reference.empty()) reference = active;
    EXPECT_EQ(active, reference) << "gamma " << gamma;
  }
  FiniteStrainOptions o = options_for("alm", 1, 1e-5);
  o.small_strain_start = false;
  o.contact.r = 1e3;
  const sig::FiniteStrainSolution alm = sig::solve_finite_strain_contact(ring.problem, o);
  ASSERT_TRUE(alm.converged()) << alm.steps.back().failure;
  EXPECT_EQ(alm.steps.back().iterations(), static_cast<int>(reference.size()));
}

TEST(FiniteStrainContact, NonConvergenceIsAStatus) {
  const PressedBlock body(16, 8, 0.1);
  FiniteStrainOptions o = options_for("projection", 2, 1e-10);
  o.contact.max_iterations = 2;
  const sig::FiniteStrainSolution s = sig::solve_finite_strain_contact(body.problem(), o);
  EXPECT_FALSE(s.converged());
  ASSERT_EQ(s.steps.size(), 1u) << "later steps are not attempted";
  EXPECT_EQ(s.steps[0].iterations(), 2);
  EXPECT_FALSE(s.steps[0].failure.empty());
}

/// ||u_final - u_start|| / ||u_final|| of the ring pressed by `press` from the small-strain
/// start: the start's distance to the large-deformation solution.
double start_distance(double press) {
  const PressedRing ring(9, 10, 64, press);
  FiniteStrainOptions o = options_for("pdas", 1, 1e-10);
  sig::FiniteStrainBulk bulk(ring.problem, o.backend, o.contact.eps);
  const sig::StartRecord start =
      sig::start_from_small_strain(bulk, ring.problem, 1.0, o.contact, o.backend);
  EXPECT_TRUE(start.used && start.converged && start.note.empty()) << start.note;
  EXPECT_EQ(start.fraction, 1.0);
  EXPECT_GT(start.iterations, 0);
  const sig::FiniteStrainSolution s = sig::solve_finite_strain_contact(ring.problem, o);
  EXPECT_TRUE(s.converged()) << s.steps.back().failure;
  EXPECT_TRUE(s.start.used && s.start.fraction == 1.0);
  const Eigen::VectorXd& u = s.steps.back().u;
  return (u - bulk.displacement()).norm() / u.norm();
}

} // namespace

TEST(FiniteStrainContact, SmallStrainStartIsTheLinearizationAtRestSolved) {
  // The start solves the problem linearized at rest, contact included: it differs from the
  // large-deformation solution by terms second order in the press (geometric and material
  // nonlinearity), so the relative distance is first order: 5.0e-4 at 0.02, twice that at 0.04
  // (a start off by a first-order term would not shrink with the press).
  const double d1 = start_distance(0.02), d2 = start_distance(0.04);
  EXPECT_LT(d1, 1e-3);
  EXPECT_NEAR(d2 / d1, 2.0, 0.2) << d1 << " " << d2;
}

TEST(FiniteStrainContact, StartShortensALinearDisplacementThatFoldsTriangles) {
  // u = -2 x reflects every triangle (inverted), -x collapses them (refused), -x / 2 halves the
  // body: start_from takes theta = 1/4. A displacement no theta >= 1/64 makes admissible leaves
  // the iterate at rest.
  const PressedBlock body(8, 4, 0.1);
  const FiniteStrainProblem problem = body.problem();
  sig::FiniteStrainBulk bulk(problem, "umfpack", 1e-8);
  Eigen::VectorXd folded = Eigen::VectorXd::Zero(2 * body.mesh.num_nodes());
  for (int node = 0; node < body.mesh.num_nodes(); ++node)
    folded[2 * node] = -2.0 * body.mesh.nodes[node].x();
  EXPECT_EQ(bulk.start_from(folded), 0.25);
  EXPECT_EQ((bulk.displacement() - 0.25 * folded).norm(), 0.0);
  EXPECT_EQ(bulk.start_from(1e6 * folded), 0.0);
  EXPECT_EQ(bulk.displacement().norm(), 0.0);
}

TEST(FiniteStrainContact, ForceOnlyAssemblyMatchesTheFullOne) {
  // A line-search trial is evaluated without its tangent: its energy and internal force must
  // be those of the full assembly, and a tangent held in the state is left as it was.
  const sig::Mesh mesh = sig::rectangle(1.0, 0.5, 6, 3);
  const sig::MaterialTable table = hyperelastic_material(mesh);
  const sig::SparsityPattern pattern(mesh);
  Eigen::VectorXd u(2 * mesh.num_nodes());
  for (Eigen::Index i = 0; i < u.size(); ++i)
    u[i] = 0.05 * std::sin(1.7 * static_cast<double>(i) + 0.3);
  sig::HyperelasticState full;
  sig::assemble_hyperelastic(mesh, table, pattern, u, full);

  sig::HyperelasticState force_only;
  sig::assemble_hyperelastic(mesh, table, pattern, Eigen::VectorXd::Zero(u.size()), force_only);
  const Eigen::SparseMatrix<double> tangent_at_rest = force_only.tangent;
  sig::assemble_hyperelastic_force(mesh, table, u, force_only);
  EXPECT_NEAR(force_only.energy, full.energy, 1e-14 * std::abs(full.energy));
  EXPECT_LE((force_only.internal_force - full.internal_force).norm(),
            1e-14 * full.internal_force.norm());
  EXPECT_GT(full.internal_force.norm(), 0.0);
  EXPECT_EQ((force_only.tangent - tangent_at_rest).norm(), 0.0);

  // A folded mesh is refused as by the full assembly.
  Eigen::VectorXd folded = Eigen::VectorXd::Zero(u.size());
  for (int node = 0; node < mesh.num_nodes(); ++node)
    folded[2 * node] = -2.0 * mesh.nodes[node].x(); // x -> -x: every triangle inverted
  EXPECT_THROW(sig::assemble_hyperelastic_force(mesh, table, folded, force_only), sig::Error);
}

TEST(FiniteStrainContact, OneBulkAssemblyPerAcceptedFullStep) {
  // Without contact and with full Newton steps, each iteration assembles the bulk once (force
  // and tangent together), also at the start of each load step, where the iterate meets the
  // residual test and the line search has no decrease to look for. eps = 1e-5 (the thesis's)
  // stops before the residual is round-off, where the search may halve to chase its noise.
  const sig::Mesh mesh = sig::rectangle(1.0, 0.5, 8, 4);
  const sig::MaterialTable table = hyperelastic_material(mesh);
  for (int steps : {1, 3}) {
    const sig::FiniteStrainSolution s = sig::solve_finite_strain_contact(
        clamped_block(mesh, table, {0.05, 0.02}), options_for("pdas", steps, 1e-5));
    ASSERT_TRUE(s.converged());
    ASSERT_EQ(static_cast<int>(s.steps.size()), steps);
    for (const sig::LoadStepResult& step : s.steps) {
      for (double alpha : step.step_length)
        ASSERT_EQ(alpha, 1.0);
      EXPECT_EQ(step.bulk_evaluations, step.iterations()) << "load " << step.load_factor;
    }
  }

  // A line search that halves (the first step folds the mesh) costs one force-only assembly
  // per trial and, when alpha < 1 was taken, the tangent of the accepted trial.
  const sig::FiniteStrainSolution folded = sig::solve_finite_strain_contact(
      clamped_block(mesh, table, {-1.2, 0.8}), options_for("pdas", 1, 1e-10));
  ASSERT_TRUE(folded.converged());
  const sig::LoadStepResult& f = folded.steps.back();
  ASSERT_LT(f.step_length.front(), 1.0);
  const int halvings = static_cast<int>(std::lround(-std::log2(f.step_length.front())));
  EXPECT_GE(f.bulk_evaluations, f.iterations() + halvings + 1);
}
