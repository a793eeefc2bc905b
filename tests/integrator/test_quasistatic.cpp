// The quasistatic march in velocity of ch. 5 (integrator/linear_contact_march.hpp,
// integrator/kelvin_voigt_scheme.hpp) against what can be known exactly (ALGORITHMS.md 2.6):
//  - the oedometric Kelvin-Voigt column, whose P1 / backward-Euler solution is a uniform strain
//    given by a scalar recursion: strain, settlements, the RNI -> CUV switch, the wall pressure,
//    with and without a memory term (the recursion to round-off, O(k^2) to the continuous);
//  - scaling the load and the bound g by s scales the velocities by s and keeps the statuses;
//  - without viscosity and memory a step is the static compliance solve of its increment;
//  - Coulomb in velocity on one node (the bound on the damper's pressure only), and the normal
//    origin of the scheme interface;
//  - a step whose Newton fails stops the march with a report, and one factorization serves it.
#include "assembly/dirichlet.hpp"
#include "assembly/system.hpp"
#include "contact/contact_elements.hpp"
#include "core/datafile.hpp"
#include "core/error.hpp"
#include "deck_case.hpp"
#include "integrator/kelvin_voigt_scheme.hpp"
#include "integrator/linear_contact_march.hpp"
#include "material/mili.hpp"
#include "mesh/generators.hpp"
#include "stages/march_inputs.hpp"
#include "stages/static_solve.hpp"

#include <Eigen/SparseCholesky>
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <sstream>

namespace sig {
namespace {

constexpr double kE = 100, kNu = 0.3, kEta1 = 0.25, kEta2 = 0.5;
// The oedometric moduli of the column: M_B = lambda + 2 mu (plane strain), M_A = eta1 + eta2.
const double kMB = kE * (1 - kNu) / ((1 + kNu) * (1 - 2 * kNu));
constexpr double kMA = kEta1 + kEta2;

using Case = test::DeckCase;

Case build(Mesh mesh, const std::string& deck) {
  return test::deck_case(std::move(mesh), deck, "qs.dat");
}

ContactSolverParameters newton(double eps = 1e-11) {
  return test::pdas_newton(eps);
}

struct Marched {
  MarchHistory history;
  Eigen::VectorXd u; ///< full dofs at the end
  int dense_factorizations = 0;
};

Marched march(const Case& c, double k, int steps, const ContactSolverParameters& p = newton()) {
  const ReducedSystem reduced = reduce(c.system);
  std::optional<VelocityContact> contact;
  if (c.contact) contact = velocity_contact(*c.contact, reduced);
  QuasistaticKelvinVoigt scheme(viscoelastic_problem(c.system, reduced), k);
  LinearContactMarch m(scheme, contact ? &*contact : nullptr, p, "cholmod");
  Marched r;
  r.history = sig::march(m, steps, steps);
  r.u = reduced.expand(scheme.displacement());
  r.dense_factorizations = m.dense_factorizations();
  return r;
}

// The column [0, 1]^2 on the foundation, rollers on its sides (u1 = 0), the top pushed down by
// q0 t. The sides' lowest edges carry reference 5, so that the bottom corners are contact nodes
// free of Dirichlet conditions; a Tresca bound far above any tangential force holds them
// sideways (stick: tangential velocity 0) as the rollers would. The exact field then has u1 = 0
// and a uniform strain e = eps22, which P1 elements represent exactly.
Case column(double q0, double cn, double g, const std::string& memory = "") {
  Mesh mesh = rectangle(1, 1, 4, 4, {3, 4, 2, 1}, CellPattern::union_jack);
  for (Facet& e : mesh.facets)
    if ((e.ref == 1 || e.ref == 4) &&
        std::min(mesh.nodes[e.node[0]].y(), mesh.nodes[e.node[1]].y()) == 0.0)
      e.ref = 5;
  std::ostringstream deck;
  deck.precision(17);
  deck << "MATERIAL law=kelvin-voigt E=" << kE << " nu=" << kNu << " eta1=" << kEta1
       << " eta2=" << kEta2 << "\n"
       << memory << "DIRICHLET ref=1 ux=0\nDIRICHLET ref=4 ux=0\n"
       << "TRACTION ref=2 f=0," << -q0 << " ramp=1\n"
       << "CONTACT ref=3 obstacle=plane point=0,0 normal=0,1 law=damped-unilateral cn=" << cn
       << " g=" << g << "\nFRICTION ref=3 law=tresca threshold=1e6\n";
  return build(std::move(mesh), deck.str());
}

/// e_n of the discrete column: (5.63) in one dimension with the memory modulus M_K, rate beta
/// (M_K = 0: none), w_0 = 0.
std::vector<double> column_strain(double q0, double k, int steps, double MK = 0, double beta = 1) {
  std::vector<double> e{0.0};
  double P = 0; // the history of (5.61)
  for (int n = 1; n <= steps; ++n) {
    const double w = (-q0 * n * k - kMB * e.back() - MK * k * P) / (kMA + k * kMB + 0.5 * k * MK);
    e.push_back(e.back() + k * w);
    P = std::exp(-beta * k) * (P + w);
  }
  return e;
}

/// Bottom and top settlements (downwards) of the column's displacement u (full dofs).
std::pair<double, double> settlements(const Mesh& mesh, const Eigen::VectorXd& u) {
  double bottom = 0, top = 0;
  int nb = 0, nt = 0;
  for (int i = 0; i < mesh.num_nodes(); ++i) {
    if (mesh.nodes[i].y() == 0.0) bottom -= u[2 * i + 1], ++nb;
    if (mesh.nodes[i].y() == 1.0) top -= u[2 * i + 1], ++nt;
  }
  return {bottom / nb, top / nt};
}

// The uniform strain of every triangle, checked uniform, and u1 = 0 everywhere.
double uniform_strain(const Mesh& mesh, const Eigen::VectorXd& u) {
  for (int i = 0; i < mesh.num_nodes(); ++i)
    EXPECT_NEAR(u[2 * i], 0.0, 1e-12) << "node " << i;
  const auto [bottom, top] = settlements(mesh, u);
  for (int i = 0; i < mesh.num_nodes(); ++i)
    EXPECT_NEAR(-u[2 * i + 1], bottom + (top - bottom) * mesh.nodes[i].y(), 1e-12) << "node " << i;
  return -(top - bottom);
}

// ALGORITHMS.md 2.6 check 1: q0 = 10, c = 10, g = 0.01, k = 1/64: CUV from the first step,
// e(1) = -0.07387184 (backward Euler exact for a ramp), settlements 0.01 and 0.08387184, wall
// pressure q - c g = 9.9 GPa.
TEST(OedometricColumn, StrainSettlementsAndWallPressure) {
  const double k = 1.0 / 64;
  const Case c = column(10, 10, 0.01);
  const Marched r = march(c, k, 64);
  ASSERT_TRUE(r.history.converged) << r.history.failure;
  const std::vector<double> e = column_strain(10, k, 64);
  EXPECT_NEAR(uniform_strain(c.mesh, r.u), e.back(), 1e-12);
  EXPECT_NEAR(e.back(), -0.07387184, 5e-9);
  const auto [bottom, top] = settlements(c.mesh, r.u);
  EXPECT_NEAR(bottom, 0.01, 1e-12);
  EXPECT_NEAR(top, 0.08387184, 5e-9);
  const StepRecord& last = r.history.steps.back();
  for (int p = 0; p < c.contact->size(); ++p) {
    EXPECT_EQ(last.contact.normal_status[p], NormalStatus::unilateral) << "node " << p;
    EXPECT_NEAR(last.contact.normal_velocity[p], 0.01, 1e-12);
    EXPECT_NEAR(last.contact.tangential_velocity[p], 0.0, 1e-12);
    const double pressure = last.contact.normal_force[p] / c.contact->weight[p];
    EXPECT_NEAR(pressure, 10.0, 1e-9);            // the whole normal pressure: q(1)
    EXPECT_NEAR(pressure - 10 * 0.01, 9.9, 1e-9); // the wall's share: q - c g
  }
  EXPECT_EQ(r.dense_factorizations, 1); // one condensed factorization for the whole march
}

// With g = 0.05 the bottom is RNI (v = q(t) / c) while q / c < g, CUV (v = g) after: the switch
// at t* = g c / q0 = 0.05, between steps 3 and 4 of k = 1/64.
TEST(OedometricColumn, RniToCuvSwitch) {
  const double k = 1.0 / 64;
  const Case c = column(10, 10, 0.05);
  const Marched r = march(c, k, 8);
  ASSERT_TRUE(r.history.converged) << r.history.failure;
  for (std::size_t n = 1; n < r.history.steps.size(); ++n) {
    const StepRecord& s = r.history.steps[n];
    const bool rni = s.step <= 3;
    for (int p = 0; p < c.contact->size(); ++p) {
      EXPECT_EQ(s.contact.normal_status[p],
                rni ? NormalStatus::compliance : NormalStatus::unilateral)
          << "step " << s.step << " node " << p;
      EXPECT_NEAR(s.contact.normal_velocity[p], rni ? 10 * s.time / 10 : 0.05, 1e-12);
    }
  }
  EXPECT_NEAR(uniform_strain(c.mesh, r.u), column_strain(10, k, 8).back(), 1e-13);
}

// ALGORITHMS.md 2.6 check 2: a memory term KK = (M_K / M_B) B, M_K = 20, beta = 10. The march
// is the discrete recursion (5.61) to round-off (-0.07273285, -0.07276616, -0.07276824 at N = 16,
// 64, 256) and tends to the continuous e(1) = -0.07276838 as k^2.
TEST(OedometricColumn, MemoryTermIsTheTrapezoidalRecursion) {
  const double MK = 20, beta = 10;
  std::ostringstream memory;
  memory.precision(17);
  memory << "MEMORY E=" << kE * MK / kMB << " nu=" << kNu << " beta=" << beta << "\n";
  const Case c = column(10, 10, 0.01, memory.str());
  const double continuous = -0.07276838;
  const std::vector<std::pair<int, double>> table = {
      {16, -0.07273285}, {64, -0.07276616}, {256, -0.07276824}};
  double previous_error = 0;
  for (const auto& [N, printed] : table) {
    const Marched r = march(c, 1.0 / N, N);
    ASSERT_TRUE(r.history.converged) << r.history.failure;
    const double e = uniform_strain(c.mesh, r.u);
    EXPECT_NEAR(e, column_strain(10, 1.0 / N, N, MK, beta).back(), 1e-13) << "N " << N;
    EXPECT_NEAR(e, printed, 5e-9) << "N " << N;
    const double error = std::abs(e - continuous);
    if (previous_error > 0) {
      EXPECT_NEAR(previous_error / error, 16.0, 1.5) << "N " << N;
    }
    previous_error = error;
  }
  // Without the term the strain is another one: the memory acts.
  EXPECT_GT(std::abs(column_strain(10, 1.0 / 64, 64).back() - table[1].second), 1e-3);
}

// The strip of scene 5 on a coarse union-jack mesh: clamped ends, ramped load, damped response
// with a velocity bound, Coulomb on the damper's pressure.
Case strip(double q0, double g, double mu = 0.2) {
  std::ostringstream deck;
  deck.precision(17);
  deck << "MATERIAL law=kelvin-voigt E=100 nu=0.3 eta1=0.25 eta2=0.5\n"
       << "DIRICHLET ref=1 ux=0 uy=0\nDIRICHLET ref=4 ux=0 uy=0\n"
       << "TRACTION ref=2 f=0," << -q0 << " ramp=1\n"
       << "CONTACT ref=3 obstacle=plane point=0,0 normal=0,1 law=damped-unilateral cn=10 g=" << g
       << " exclude=1,4\n";
  if (mu > 0) deck << "FRICTION ref=3 law=coulomb mu=" << mu << " bound=compliance\n";
  return build(rectangle(5, 1, 16, 4, {3, 4, 2, 1}, CellPattern::union_jack), deck.str());
}

// ALGORITHMS.md 2.6 check 3: the problem is positively homogeneous in (load, g, velocity), so
// (s f, s g) gives s times the velocities and the same statuses at every step.
TEST(QuasistaticMarch, ScalingLoadAndBoundScalesTheVelocities) {
  const double s = 10, k = 1.0 / 16;
  const Marched a = march(strip(1, 0.05), k, 16), b = march(strip(s, s * 0.05), k, 16);
  ASSERT_TRUE(a.history.converged && b.history.converged);
  int rni = 0, cuv = 0, stick = 0, slip = 0;
  for (std::size_t n = 1; n < a.history.steps.size(); ++n) {
    const ContactRecord &x = a.history.steps[n].contact, &y = b.history.steps[n].contact;
    EXPECT_EQ(x.normal_status, y.normal_status) << "step " << n;
    EXPECT_EQ(x.friction_status, y.friction_status) << "step " << n;
    EXPECT_LT((s * x.normal_velocity - y.normal_velocity).norm(), 1e-9 * y.normal_velocity.norm());
    EXPECT_LT((s * x.tangential_velocity - y.tangential_velocity).norm(),
              1e-9 * y.normal_velocity.norm());
    for (std::size_t p = 0; p < x.normal_status.size(); ++p) {
      rni += x.normal_status[p] == NormalStatus::compliance;
      cuv += x.normal_status[p] == NormalStatus::unilateral;
      stick += x.friction_status[p] == FrictionStatus::stick;
      slip += x.friction_status[p] == FrictionStatus::slip_forward ||
              x.friction_status[p] == FrictionStatus::slip_backward;
    }
  }
  EXPECT_LT((s * a.u - b.u).norm(), 1e-9 * b.u.norm());
  // The run goes through every status, so the comparison says something.
  EXPECT_GT(rni, 0);
  EXPECT_GT(cuv, 0);
  EXPECT_GT(stick, 0);
  EXPECT_GT(slip, 0);
}

// Without viscosity and memory, k K_B w_n = f(t_n) - K_B u_{n-1} - contact: the static solve of
// u_n with the compliance cn / k on the increment u_n - u_{n-1} (the gap d = u_{n-1}'s normal
// displacement) and its wall at g k. Both solvers agree step by step, statuses included; without
// contact each step is K_B u_n = f(t_n).
TEST(QuasistaticMarch, NoViscosityIsAStaticSolvePerStep) {
  const double k = 1.0 / 8, cn = 10, g = 0.05;
  const std::string deck = "MATERIAL law=kelvin-voigt E=100 nu=0.3\n"
                           "DIRICHLET ref=1 ux=0 uy=0\nDIRICHLET ref=4 ux=0 uy=0\n"
                           "TRACTION ref=2 f=0,-1 ramp=1\n";
  const Mesh mesh = rectangle(5, 1, 16, 4, {3, 4, 2, 1}, CellPattern::union_jack);
  const Case free = build(mesh, deck);
  const Marched without = march(free, k, 8);
  const ReducedSystem reduced = reduce(free.system);
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> K(reduced.K);
  EXPECT_LT((reduced.expand(K.solve(reduced.load_at(1.0))) - without.u).norm(),
            1e-10 * without.u.norm());

  const Case c = build(mesh, deck + "CONTACT ref=3 obstacle=plane point=0,0 normal=0,1 "
                                    "law=damped-unilateral cn=10 g=0.05 exclude=1,4\n");
  ContactElements increments = *c.contact;
  for (ContactLaw& law : increments.law) {
    law.normal = NormalLaw::compliance_unilateral;
    law.cn = cn / k;
    law.depth = g * k;
  }
  Eigen::VectorXd u = Eigen::VectorXd::Zero(c.system.num_dofs());
  int cuv = 0;
  for (int n = 1; n <= 8; ++n) {
    const Marched r = march(c, k, n);
    ASSERT_TRUE(r.history.converged) << r.history.failure;
    for (int p = 0; p < increments.size(); ++p)
      increments.gap[p] = -increments.normal[p].dot(u.segment<2>(2 * increments.node[p]));
    LinearSystem at = c.system;
    at.f = c.system.load_at(n * k);
    at.time_loads = {};
    const StaticSolution s = solve_static_contact(at, increments, newton(), "cholmod");
    ASSERT_TRUE(s.converged) << s.failure;
    EXPECT_LT((s.u - r.u).norm(), 1e-8 * r.u.norm()) << "step " << n;
    EXPECT_EQ(s.normal_status, r.history.steps.back().contact.normal_status) << "step " << n;
    for (NormalStatus status : s.normal_status)
      cuv += status == NormalStatus::unilateral;
    u = s.u;
  }
  EXPECT_GT(cuv, 0); // the wall was reached
}

// A scheme of three dofs: one contact node (dofs 0, 1: tangential, normal frame for the normal
// (0, 1)) on a weak bulk, and a loose dof, with a constant right side: the node's laws alone
// decide its velocity.
class OneNode final : public VelocityScheme {
public:
  OneNode(double fx, double fn, double origin = 0) : origin_(origin) {
    // The node's 2 x 2 block stored full, as an assembled stiffness has it.
    S_.resize(3, 3);
    S_.insert(0, 0) = kBulk;
    S_.insert(1, 0) = 0;
    S_.insert(0, 1) = 0;
    S_.insert(1, 1) = kBulk;
    S_.insert(2, 2) = 1;
    S_.makeCompressed();
    b_ = Eigen::Vector3d(fx, -fn, 0); // fn pushes the node towards the obstacle (-x2)
    u_ = Eigen::VectorXd::Zero(3);
  }
  static constexpr double kBulk = 1e-3;
  std::string name() const override { return "one node"; }
  double time_step() const override { return 1; }
  const Eigen::SparseMatrix<double>& step_matrix() const override { return S_; }
  Eigen::VectorXd right_side(int) const override { return b_; }
  void accept(int, const Eigen::VectorXd& w) override { u_ += w; }
  const Eigen::VectorXd& displacement() const override { return u_; }
  Eigen::VectorXd normal_origin(int, const VelocityContact&) const override {
    return Eigen::VectorXd::Constant(1, origin_);
  }

private:
  Eigen::SparseMatrix<double> S_;
  Eigen::VectorXd b_, u_;
  double origin_;
};

struct NodeOutcome {
  double v_n, v_t, N, T;
  NormalStatus normal;
  FrictionStatus friction;
};

NodeOutcome one_node(double fx, double fn, FrictionBound bound, double origin = 0) {
  OneNode scheme(fx, fn, origin);
  VelocityContact contact;
  contact.first_dof = {0};
  contact.normal = {Eigen::Vector2d(0, 1)};
  ContactLaw law;
  law.normal = NormalLaw::damped_unilateral;
  law.cn = 10;
  law.depth = 0.01;
  law.friction = FrictionLaw::coulomb;
  law.mu = 0.2;
  law.bound = bound;
  contact.setting = {{law}, Eigen::VectorXd::Constant(1, 0.5)};
  LinearContactMarch m(scheme, &contact, newton(1e-12), "cholmod");
  const StepRecord s = m.step(1);
  EXPECT_TRUE(s.converged) << s.failure;
  const ContactRecord& c = s.contact;
  return {c.normal_velocity[0],  c.tangential_velocity[0], c.normal_force[0],
          c.tangential_force[0], c.normal_status[0],       c.friction_status[0]};
}

// ALGORITHMS.md 2.6 check 4: Coulomb in velocity on one node of weight w = 0.5, c = 10,
// g = 0.01, mu = 0.2. The node sticks iff |F_x| <= mu c min(v, g) w, the damper's force: on the
// wall (CUV) the bound is Tresca's mu c g w whatever the wall's reaction (bound=compliance, (5.6)),
// where bound=normal would take mu N.
TEST(QuasistaticMarch, CoulombInVelocityOnOneNode) {
  const double c = 10, g = 0.01, w = 0.5, mu = 0.2, weak = OneNode::kBulk;
  // RNI: F_n = (c w + weak) v with v = 0.006 (the weak bulk's share S v included); the bound
  // mu c v w = 0.006.
  const double fn = (c * w + weak) * 0.006;
  NodeOutcome o = one_node(0.005, fn, FrictionBound::compliance);
  EXPECT_EQ(o.normal, NormalStatus::compliance);
  EXPECT_NEAR(o.v_n, 0.006, 1e-12);
  EXPECT_EQ(o.friction, FrictionStatus::stick);
  EXPECT_NEAR(o.v_t, 0.0, 1e-12);
  EXPECT_NEAR(o.T, 0.005, 1e-9);
  o = one_node(0.007, fn, FrictionBound::compliance);
  EXPECT_EQ(o.friction, FrictionStatus::slip_forward);
  EXPECT_NEAR(o.T, mu * c * o.v_n * w, 1e-9);
  EXPECT_NEAR(o.v_t, (0.007 - o.T) / weak, 1e-6);
  // CUV: F_n = 1 >> c g w = 0.05; bound mu c g w = 0.01 on the wall.
  o = one_node(0.009, 1.0, FrictionBound::compliance);
  EXPECT_EQ(o.normal, NormalStatus::unilateral);
  EXPECT_NEAR(o.v_n, g, 1e-12);
  EXPECT_EQ(o.friction, FrictionStatus::stick);
  o = one_node(-0.011, 1.0, FrictionBound::compliance);
  EXPECT_EQ(o.friction, FrictionStatus::slip_backward);
  EXPECT_NEAR(o.T, -mu * c * g * w, 1e-9);
  EXPECT_NEAR(o.v_t, (-0.011 - o.T) / weak, 1e-6);
  // The classical bound mu N counts the wall's reaction: the same load sticks.
  o = one_node(-0.011, 1.0, FrictionBound::normal);
  EXPECT_EQ(o.friction, FrictionStatus::stick);
  EXPECT_NEAR(o.N, 1.0 - weak * g, 1e-12);
  // The scheme's normal origin o shifts the law, N = c [v - o]+ w: weak v + c w (v - o) = F_n.
  o = one_node(0.0, fn, FrictionBound::compliance, 0.002);
  EXPECT_NEAR(o.v_n, (fn + c * w * 0.002) / (c * w + weak), 1e-12);
}

// A step whose Newton fails stops the march: the history says which and why, the scheme keeps
// its last accepted state, nothing is thrown.
TEST(QuasistaticMarch, AFailedStepStopsTheMarch) {
  ContactSolverParameters p = newton();
  p.max_iterations = 1;
  const Marched r = march(strip(1, 0.05), 1.0 / 16, 16, p);
  EXPECT_FALSE(r.history.converged);
  EXPECT_NE(r.history.failure.find("did not converge"), std::string::npos) << r.history.failure;
  EXPECT_FALSE(r.history.steps.back().converged);
  EXPECT_EQ(r.history.output_step.back(), r.history.steps.back().step - 1);
}

} // namespace
} // namespace sig
