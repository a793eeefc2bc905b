// The oedometer patch test of scene 4's contact law (ALGORITHMS.md 1.6, check 2), through the
// static solve stage (stages/static_solve.hpp): a unit square on the foundation x2 <= 0, rollers
// on both sides (u1 = 0), a uniform pressure q on its top, normal compliance c with its wall at
// g on the bottom, nonmonotone friction bounded by the compliance pressure (4.6). The state is
// uniform and P1 holds it exactly: every bottom node CN with penetration q / c if q / c < g, else
// every node CU at g with the wall's multiplier w (q - c g); the top settles by that penetration
// plus q l / (lambda + 2 mu). The rollers hold the bottom corners too, contact nodes whose
// tangential component the solve holds in their frames (stuck at zero slip, issue 23).
#include "assembly/system.hpp"
#include "contact/contact_elements.hpp"
#include "contact/obstacle.hpp"
#include "core/datafile.hpp"
#include "core/error.hpp"
#include "material/mili.hpp"
#include "mesh/generators.hpp"
#include "scene4_law.hpp"
#include "stages/static_solve.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace sig {
namespace {

constexpr double kE = 200, kNu = 0.3, kCn = 10, kG = 0.05;
constexpr double kLambda = kE * kNu / ((1 + kNu) * (1 - 2 * kNu)), kMu = kE / (2 * (1 + kNu));

struct Oedometer {
  Mesh mesh = square(1.0, 8);
  LinearSystem system;
  ContactElements contact;
};

Oedometer oedometer(double q) {
  Oedometer o;
  const Datafile deck =
      Datafile::parse("MATERIAL law=hooke E=" + std::to_string(kE) +
                          " nu=0.3 plane=strain\nPRESSURE ref=2 p=" + std::to_string(q) + "\n",
                      "oedometer.dat");
  const MaterialTable table = material_table_from_cards(deck, o.mesh);
  o.system = assemble_system(o.mesh, table, deck);
  // Rollers: u1 = 0 on the sides (refs 1 and 4), the bottom corners, contact nodes, included.
  for (int ref : {1, 4})
    for (int node : o.mesh.nodes_with_ref(ref))
      o.system.dirichlet_dofs.push_back(2 * node);
  std::sort(o.system.dirichlet_dofs.begin(), o.system.dirichlet_dofs.end());
  o.system.dirichlet_dofs.erase(
      std::unique(o.system.dirichlet_dofs.begin(), o.system.dirichlet_dofs.end()),
      o.system.dirichlet_dofs.end());
  o.system.dirichlet_values = Eigen::VectorXd::Zero(o.system.dirichlet_dofs.size());
  o.contact = build_contact_elements(o.mesh, 3, HalfPlane({0, 0}, {0, 1}),
                                     test::compliance_nonmonotone(kCn, kG, 2, 0.02, 1));
  return o;
}

TEST(Oedometer, UniformCompressionIsExact) {
  for (const char* method : {"alm", "pdas"})
    for (double q : {0.3, 2.0}) { // q / c = 0.03 < g: CN; 0.2 > g: CU
      const Oedometer o = oedometer(q);
      ContactSolverParameters parameters;
      parameters.method = method;
      parameters.r = parameters.gamma = 100;
      parameters.eps = 1e-12;
      StaticConvexification loop;
      loop.mesh = &o.mesh;
      const StaticSolution s =
          solve_static_contact(o.system, o.contact, parameters, "cholmod", {}, loop);
      const std::string where = std::string(method) + " q " + std::to_string(q);
      ASSERT_TRUE(s.converged) << where << ": " << s.failure;
      ASSERT_TRUE(s.convexification.has_value());
      EXPECT_EQ(s.convexification->outer_iterations(), 2) << where; // nothing slips: mu stays a
      const bool wall = q / kCn >= kG;
      const double d = wall ? kG : q / kCn;
      for (int p = 0; p < o.contact.size(); ++p) {
        const int node = o.contact.node[p];
        const double w = o.contact.weight[p];
        EXPECT_EQ(s.normal_status[p], wall ? NormalStatus::unilateral : NormalStatus::compliance)
            << where << " element " << p;
        EXPECT_EQ(s.friction_status[p], FrictionStatus::stick) << where << " element " << p;
        EXPECT_NEAR(s.u[2 * node + 1], -d, 1e-12) << where << " element " << p;
        EXPECT_NEAR(s.multiplier[p], w * q, 1e-11) << where << " element " << p;
      }
      for (int node = 0; node < o.mesh.num_nodes(); ++node) {
        const double y = o.mesh.nodes[node].y();
        EXPECT_NEAR(s.u[2 * node], 0.0, 1e-12) << where << " node " << node;
        EXPECT_NEAR(s.u[2 * node + 1], -d - q * y / (kLambda + 2 * kMu), 1e-12)
            << where << " node " << node;
      }
    }
}

} // namespace
} // namespace sig

namespace sig {
namespace {

ContactElements one_node(const Eigen::Vector2d& normal) {
  ContactElements c;
  c.node = {3};
  c.normal = {normal};
  c.tangent = {contact_tangent(normal)};
  c.gap = Eigen::VectorXd::Constant(1, 0.1);
  c.weight = Eigen::VectorXd::Ones(1);
  c.law = {ContactLaw{}};
  c.law[0].friction = FrictionLaw::coulomb;
  c.law[0].mu = 0.3;
  return c;
}

LinearSystem holding(int dof, double value) {
  LinearSystem s;
  s.f = Eigen::VectorXd::Zero(10);
  s.dirichlet_dofs = {dof};
  s.dirichlet_values = Eigen::VectorXd::Constant(1, value);
  return s;
}

TEST(HeldContactNodes, EachHeldComponentInTheNodesFrame) {
  // Normal (0, -1): u_n = -n . u = u2, q_n = u2 - 0.1; t = (-1, 0), q_t = -u1.
  ContactElements c = one_node({0, -1});
  EXPECT_EQ(hold_on_contact_nodes(holding(6, 0.25), c), std::vector<int>{6}); // u1 of node 3
  EXPECT_TRUE(c.law[0].held_tangent[0]);
  EXPECT_FALSE(c.law[0].held_normal);
  EXPECT_DOUBLE_EQ(c.law[0].held_slip[0], -0.25);
  EXPECT_EQ(c.law[0].friction, FrictionLaw::coulomb);
  c = one_node({0, -1});
  EXPECT_EQ(hold_on_contact_nodes(holding(7, 0.25), c), std::vector<int>{7}); // u2
  EXPECT_TRUE(c.law[0].held_normal);
  EXPECT_DOUBLE_EQ(c.law[0].depth, 0.25 - 0.1);
  EXPECT_EQ(c.law[0].friction, FrictionLaw::none); // out of contact
  EXPECT_FALSE(law_problem(c.law[0]).has_value());
  // Not a contact node's dof: untouched.
  c = one_node({0, -1});
  EXPECT_TRUE(hold_on_contact_nodes(holding(4, 1.0), c).empty());
  EXPECT_EQ(c.law[0], one_node({0, -1}).law[0]);
}

TEST(HeldContactNodes, AnObliqueHeldComponentIsRefusedNamingTheNode) {
  ContactElements c = one_node({0.6, 0.8});
  try {
    hold_on_contact_nodes(holding(6, 0.0), c);
    FAIL() << "an oblique held component was accepted";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("contact node 1 (mesh node 4)"), std::string::npos) << what;
    EXPECT_NE(what.find("neither the obstacle's normal"), std::string::npos) << what;
  }
}

} // namespace
} // namespace sig
