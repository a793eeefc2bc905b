// The dynamic backward Euler in velocity of ch. 6 (integrator/backward_euler_scheme.hpp) on the
// linear-bulk march, against what is known exactly:
//  - a free body under a uniform body force moves rigidly with w_n = n k g and
//    u_n = k^2 g n (n + 1) / 2 (the scheme's first-order lag behind g t^2 / 2);
//  - without load the energy obeys the scheme's identity step by step (ALGORITHMS.md 3.6 check 3):
//    E_n - E_{n-1} = -|w_n - w_{n-1}|_M^2 / 2 - |u_n - u_{n-1}|_K^2 / 2 - k |w_n|_C^2, so it never
//    grows; with a compliance (and friction) E + the compliance's potential never grows either;
//  - with a vanishing density every step is the static contact solve of its load (the moving
//    load at x0 + c t): the displacement laws turned into laws of the velocity (cn k, g / k, the
//    normal origin) are the laws of the displacement.
#include "assembly/dirichlet.hpp"
#include "assembly/system.hpp"
#include "contact/contact_elements.hpp"
#include "contact/contact_kernel.hpp"
#include "core/datafile.hpp"
#include "deck_case.hpp"
#include "integrator/backward_euler_scheme.hpp"
#include "integrator/elastodynamics.hpp"
#include "integrator/energy.hpp"
#include "material/mili.hpp"
#include "mesh/generators.hpp"
#include "stages/march_inputs.hpp"
#include "stages/static_solve.hpp"

#include <gtest/gtest.h>

#include <optional>

namespace sig {
namespace {

using Case = test::DeckCase;

Case build(Mesh mesh, const std::string& deck) {
  return test::deck_case(std::move(mesh), deck, "be.dat");
}

ContactSolverParameters newton() {
  return test::pdas_newton(1e-10);
}

/// The energies after each step 0 .. steps: E = 1/2 w.M w + 1/2 u.K u, and the compliance's
/// potential, computed here from the states (and checked against the march's records); the
/// states too.
struct Marched {
  std::vector<double> energy, potential;
  std::vector<Eigen::VectorXd> u, w; ///< free dofs
  MarchHistory history;
  Eigen::VectorXd u_full; ///< at the end
};

Marched march(const Case& c, double k, int steps, const Eigen::VectorXd& v0_full = {}) {
  const ReducedSystem reduced = reduce(c.system);
  const Eigen::VectorXd w0 = v0_full.size() ? reduced.restrict(v0_full) : Eigen::VectorXd();
  std::optional<VelocityContact> contact;
  if (c.contact) contact = velocity_contact(*c.contact, reduced);
  DynamicBackwardEuler scheme(viscoelastic_problem(c.system, reduced, c.system.M), k, {}, w0,
                              c.contact ? c.contact->gap : Eigen::VectorXd(),
                              contact ? contact->setting : ContactSetting{});
  if (contact) contact->setting = scheme.velocity_setting();
  LinearContactMarch m(scheme, contact ? &*contact : nullptr, scheme.velocity_parameters(newton()),
                       "cholmod");
  Marched r;
  const auto record = [&] {
    r.energy.push_back(scheme.kinetic_energy() + scheme.elastic_energy());
    double stored = 0;
    if (contact)
      for (int p = 0; p < contact->size(); ++p) {
        const Eigen::VectorXd up = scheme.displacement().segment(contact->first_dof[p], 2);
        stored +=
            c.contact->weight[p] *
            compliance_energy(c.contact->law[p], -contact->normal[p].dot(up) - c.contact->gap[p]);
      }
    r.potential.push_back(stored);
    r.u.push_back(scheme.displacement());
    r.w.push_back(scheme.velocity());
  };
  record();
  r.history =
      sig::march(m, steps, steps, [&](const StepRecord&, const DynamicState&) { record(); });
  r.u_full = reduced.expand(scheme.displacement());
  // The march's own energy records: E = kinetic + elastic, the potential apart.
  EXPECT_TRUE(r.history.records.energy);
  for (std::size_t n = 0; n < r.energy.size(); ++n) {
    const EnergyRecord& e = r.history.steps[n].energy;
    EXPECT_NEAR(e.total, r.energy[n], 1e-14 * r.energy[0]) << "step " << n;
    EXPECT_EQ(e.total, e.kinetic + e.elastic);
    EXPECT_NEAR(e.interface, r.potential[n], 1e-14 * r.energy[0]) << "step " << n;
  }
  return r;
}

TEST(BackwardEuler, FreeBodyUnderUniformForceMovesRigidly) {
  const Case c = build(rectangle(2, 1, 4, 2), "MATERIAL E=100 nu=0.3 rho=2\nBODYFORCE f=0,-3\n");
  const double k = 0.1, g = -1.5; // f / rho
  const int steps = 7;
  const Marched r = march(c, k, steps);
  ASSERT_TRUE(r.history.converged);
  for (int n = 0; n <= steps; ++n)
    for (int i = 0; i < c.mesh.num_nodes(); ++i) {
      EXPECT_NEAR(r.w[n][2 * i + 1], n * k * g, 1e-12) << "step " << n;
      EXPECT_NEAR(r.u[n][2 * i + 1], k * k * g * n * (n + 1) / 2, 1e-12) << "step " << n;
      EXPECT_NEAR(r.u[n][2 * i], 0.0, 1e-12);
    }
}

// The identity of the header, step by step, without viscosity and with a Kelvin-Voigt one.
TEST(BackwardEuler, EnergyIdentityWithoutLoad) {
  for (const char* material :
       {"MATERIAL E=100 nu=0.3 rho=1e-3\n",
        "MATERIAL law=kelvin-voigt E=100 nu=0.3 eta1=0.05 eta2=0.1 rho=1e-3\n"}) {
    const Case c =
        build(rectangle(2, 0.2, 16, 4), std::string(material) + "DIRICHLET ref=1 ux=0 uy=0\n");
    Eigen::VectorXd v0 = Eigen::VectorXd::Zero(c.system.num_dofs());
    for (int i = 0; i < c.mesh.num_nodes(); ++i) // a bending velocity
      v0[2 * i + 1] = -c.mesh.nodes[i].x() * c.mesh.nodes[i].x();
    const double k = 1e-3;
    const Marched r = march(c, k, 40, v0);
    ASSERT_TRUE(r.history.converged);
    const ReducedSystem reduced = reduce(c.system);
    const Eigen::SparseMatrix<double> M = reduced.restrict_matrix(c.system.M);
    const Eigen::SparseMatrix<double> C =
        c.system.V.size() ? reduced.restrict_matrix(c.system.V) : Eigen::SparseMatrix<double>();
    for (std::size_t n = 1; n < r.energy.size(); ++n) {
      const Eigen::VectorXd dw = r.w[n] - r.w[n - 1], du = r.u[n] - r.u[n - 1];
      double loss = 0.5 * dw.dot(M * dw) + 0.5 * du.dot(reduced.K * du);
      if (C.size()) loss += k * r.w[n].dot(C * r.w[n]);
      EXPECT_NEAR(r.energy[n] - r.energy[n - 1], -loss, 1e-10 * r.energy[0]) << material << n;
      EXPECT_LT(r.energy[n], r.energy[n - 1]) << material << n;
    }
  }
}

// A strip dropped on the compliant foundation: E + the compliance's potential never grows,
// frictionless and with Coulomb friction of the slip rate.
TEST(BackwardEuler, NeverGainsEnergyOnACompliance) {
  const std::string deck = "MATERIAL E=100 nu=0.3 rho=1e-6\n"
                           "CONTACT ref=3 obstacle=plane point=0,0 normal=0,1 law=compliance "
                           "cn=10 c3=1e8\n";
  for (const std::string friction : {"", "FRICTION ref=3 law=coulomb mu=0.3\n"}) {
    const Case c = build(rectangle(2, 0.1, 16, 4), deck + friction);
    Eigen::VectorXd v0 = Eigen::VectorXd::Zero(c.system.num_dofs());
    for (int i = 0; i < c.mesh.num_nodes(); ++i) { // falling, spinning a little
      v0[2 * i] = 0.5 * (c.mesh.nodes[i].y() - 0.05);
      v0[2 * i + 1] = -1.0 + 0.2 * c.mesh.nodes[i].x();
    }
    const Marched r = march(c, 1e-4, 60, v0);
    ASSERT_TRUE(r.history.converged) << r.history.failure;
    double most = 0;
    for (std::size_t n = 1; n < r.energy.size(); ++n) {
      const double before = r.energy[n - 1] + r.potential[n - 1];
      const double after = r.energy[n] + r.potential[n];
      EXPECT_LE(after, before * (1 + 1e-12)) << friction << "step " << n;
      most = std::max(most, r.potential[n]);
    }
    EXPECT_GT(most, 0.1 * r.energy[0]) << "the foundation must have been reached";
  }
}

// With a vanishing density a step is the static compliance solve with the load of its time: the
// moving load at x0 + c t_n, on springs with a wall (compliance-unilateral) and without.
TEST(BackwardEuler, VanishingInertiaIsTheStaticSolveOfEachStep) {
  for (const char* law :
       {"law=compliance cn=10 c3=1e8", "law=compliance-unilateral cn=10 g=0.05"}) {
    const std::string deck = std::string("MATERIAL E=100 nu=0.3 rho=1e-14\n"
                                         "DIRICHLET ref=1 ux=0 uy=0\n"
                                         "CONTACT ref=3 obstacle=plane point=0,0 normal=0,1 ") +
                             law + " exclude=1\n";
    const Mesh mesh = rectangle(2, 0.1, 32, 4, {3, 1, 2, 1});
    const Case moving = build(mesh, deck + "MOVINGLOAD ref=2 F=10 psi=50 c=2 x0=0.3\n");
    const double k = 0.1;
    for (int n : {1, 3, 5}) {
      const Marched r = march(moving, k, n);
      ASSERT_TRUE(r.history.converged) << r.history.failure;
      const Case fixed = build(mesh, deck + "MOVINGLOAD ref=2 F=10 psi=50 c=0 x0=" +
                                         std::to_string(0.3 + 2 * k * n) + "\n");
      const StaticSolution s =
          solve_static_contact(fixed.system, *fixed.contact, newton(), "cholmod");
      ASSERT_TRUE(s.converged) << s.failure;
      EXPECT_LT((s.u - r.u_full).norm(), 1e-7 * s.u.norm()) << law << " step " << n;
      EXPECT_EQ(s.normal_status, r.history.steps.back().contact.normal_status) << law;
    }
  }
}

} // namespace
} // namespace sig
