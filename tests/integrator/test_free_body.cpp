// A free elastic rectangle thrown with a deforming velocity field, no load, no contact: the
// midpoint rule keeps the discrete energy (8.33) and the linear and angular momenta of the body
// to round-off over 1000 steps, with every mass choice; Newmark's average acceleration scheme
// reproduces the midpoint states (the two are the same scheme for a linear problem without
// load).
#include "assembly/dirichlet.hpp"
#include "core/error.hpp"
#include "integrator/elastodynamic_march.hpp"
#include "integrator/elastodynamics.hpp"
#include "integrator/midpoint.hpp"
#include "integrator/newmark.hpp"
#include "stages/march_inputs.hpp"
#include "test_bodies.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace sig {
namespace {

constexpr int steps = 1000;
constexpr double k = 0.02; // an implicit scheme: no stability limit on k, any step would do

struct FreeBody {
  Mesh mesh = test::perturbed_rectangle(2.0, 1.0, 10, 5);
  LinearSystem system = test::free_body_system(mesh, test::unit_material());
  ReducedSystem reduced = reduce(system);

  std::vector<int> bottom() const { return mesh.nodes_with_ref(3); }
  Elastodynamics problem(MassChoice choice) const {
    return reduced_elastodynamics(reduced, mass_matrix(system, choice, mesh, bottom()));
  }
  DynamicState initial() const {
    DynamicState s;
    s.u = Eigen::VectorXd::Zero(reduced.num_free());
    s.v = reduced.restrict(test::initial_velocity(mesh));
    return s;
  }
  // Translation e_c and the infinitesimal rotation about the origin: the kernel of K.
  Eigen::VectorXd translation(int c) const {
    Eigen::VectorXd e = Eigen::VectorXd::Zero(2 * mesh.num_nodes());
    for (int i = 0; i < mesh.num_nodes(); ++i)
      e(2 * i + c) = 1.0;
    return e;
  }
  Eigen::VectorXd rotation() const {
    Eigen::VectorXd r(2 * mesh.num_nodes());
    for (int i = 0; i < mesh.num_nodes(); ++i)
      r.segment<2>(2 * i) << -mesh.nodes[i].y(), mesh.nodes[i].x();
    return r;
  }
};

class MidpointFreeBody : public ::testing::TestWithParam<MassChoice> {};

TEST_P(MidpointFreeBody, ConservesEnergyAndMomentaOverThousandSteps) {
  const FreeBody body;
  const Elastodynamics problem = body.problem(GetParam());
  const ImplicitMidpoint scheme(problem, k);
  const MarchHistory history = march(scheme, body.initial(), steps);
  ASSERT_EQ(history.steps.size(), steps + 1u);

  const double E0 = history.steps.front().energy.total;
  double drift = 0.0, min_elastic = 1e300, max_elastic = 0.0;
  for (const StepRecord& step : history.steps) {
    const EnergyRecord& r = step.energy;
    EXPECT_EQ(r.external_work, 0.0);
    EXPECT_DOUBLE_EQ(r.total, r.kinetic + r.elastic);
    drift = std::max(drift, std::abs(r.total - E0) / E0);
    min_elastic = std::min(min_elastic, r.elastic);
    max_elastic = std::max(max_elastic, r.elastic);
  }
  EXPECT_LT(drift, 1e-10) << to_string(GetParam());
  // The body really vibrates: energy moves between the kinetic and the elastic parts.
  EXPECT_EQ(min_elastic, 0.0);
  EXPECT_GT(max_elastic, 1e-3 * E0);
  EXPECT_NEAR(history.steps.back().time, steps * k, 1e-9);

  // K annihilates the rigid modes, so M (v_{n+1} - v_n) is orthogonal to them: the momenta
  // p = e.M v and the angular momentum about the origin are conserved by the scheme.
  const Eigen::VectorXd v0 = body.initial().v, v1 = history.final_state().v;
  for (const Eigen::VectorXd& mode : {body.translation(0), body.translation(1), body.rotation()}) {
    const Eigen::VectorXd m = body.reduced.restrict(mode);
    const double p0 = m.dot(problem.M * v0), p1 = m.dot(problem.M * v1);
    EXPECT_NEAR(p1, p0, 1e-11 * (1 + std::abs(p0)));
  }
}

INSTANTIATE_TEST_SUITE_P(Masses, MidpointFreeBody,
                         ::testing::Values(MassChoice::consistent, MassChoice::lumped,
                                           MassChoice::emm),
                         [](const auto& info) { return to_string(info.param); });

class NewmarkFreeBody : public ::testing::TestWithParam<MassChoice> {};

TEST_P(NewmarkFreeBody, MatchesMidpointStatesAndEnergy) {
  const FreeBody body;
  const Elastodynamics problem = body.problem(GetParam());
  const ImplicitMidpoint midpoint(problem, k);
  const NewmarkAverageAcceleration newmark(problem, k, "umfpack");
  DynamicState a = body.initial(), b = body.initial();
  // Velocities are compared in the kinetic-energy norm: under EMM the normal velocity of a
  // contact node has no mass and follows v_{n+1} = (2 / k)(u_{n+1} - u_n) - v_n alone, a
  // neutral recurrence that keeps (and sums) the rounding of either scheme without effect on
  // the dynamics.
  auto kinetic_norm = [&problem](const Eigen::VectorXd& v) {
    return std::sqrt(v.dot(problem.M * v));
  };
  double u_scale = 0.0, v_scale = 0.0, du = 0.0, dv = 0.0, dv_max = 0.0;
  for (int n = 0; n < steps; ++n) {
    a = midpoint.advance(a);
    b = newmark.advance(b);
    u_scale = std::max(u_scale, a.u.lpNorm<Eigen::Infinity>());
    v_scale = std::max(v_scale, kinetic_norm(a.v));
    du = std::max(du, (a.u - b.u).lpNorm<Eigen::Infinity>());
    dv = std::max(dv, kinetic_norm(a.v - b.v));
    dv_max =
        std::max(dv_max, (a.v - b.v).lpNorm<Eigen::Infinity>() / a.v.lpNorm<Eigen::Infinity>());
  }
  EXPECT_LT(du, 1e-10 * u_scale) << to_string(GetParam());
  EXPECT_LT(dv, 1e-10 * v_scale) << to_string(GetParam());
  if (GetParam() != MassChoice::emm) {
    EXPECT_LT(dv_max, 1e-10);
  }
  EXPECT_EQ(a.time, b.time);
  const double E0 = energy_of(problem, body.initial()).total;
  EXPECT_NEAR(energy_of(problem, b).total, E0, 1e-10 * E0);
}

INSTANTIATE_TEST_SUITE_P(Masses, NewmarkFreeBody,
                         ::testing::Values(MassChoice::consistent, MassChoice::emm),
                         [](const auto& info) { return to_string(info.param); });

// Every output_every-th step is kept, and the last one even off that grid; the observer sees
// every step once, in order, with its state.
TEST(MarchHistory, KeepsTheOutputStepsAndTheLast) {
  const FreeBody body;
  const ImplicitMidpoint scheme(body.problem(MassChoice::lumped), k);
  int calls = 0;
  const MarchHistory h = march(scheme, body.initial(), 10, 4,
                               [&calls](const StepRecord& r, const DynamicState& state) {
                                 EXPECT_EQ(r.step, ++calls);
                                 EXPECT_EQ(state.time, r.time);
                               });
  EXPECT_EQ(calls, 10);
  EXPECT_EQ(h.output_step, (std::vector<int>{0, 4, 8, 10}));
  ASSERT_EQ(h.outputs.size(), 4u);
  EXPECT_NEAR(h.outputs[1].time, 4 * k, 1e-15);
  EXPECT_NEAR(h.outputs[2].time, 8 * k, 1e-15);
  EXPECT_NEAR(h.final_state().time, 10 * k, 1e-15);
  EXPECT_EQ(march(scheme, body.initial(), 3).outputs.size(), 2u); // initial and final
}

TEST(TimeScheme, RejectsBadInput) {
  const FreeBody body;
  EXPECT_THROW(make_time_scheme("euler", body.problem(MassChoice::lumped), k), Error);
  EXPECT_THROW(ImplicitMidpoint(body.problem(MassChoice::lumped), 0.0), Error);
  EXPECT_THROW(mass_choice_from_string("diagonal"), Error);
  EXPECT_EQ(mass_choice_from_string("emm"), MassChoice::emm);
  const auto scheme = make_time_scheme("newmark", body.problem(MassChoice::lumped), k);
  EXPECT_EQ(scheme->name(), "newmark");
  DynamicState bad;
  bad.u = Eigen::VectorXd::Zero(3);
  bad.v = Eigen::VectorXd::Zero(3);
  EXPECT_THROW(scheme->advance(bad), Error);
  // Without density there is no mass to integrate with.
  const LinearSystem massless =
      test::free_body_system(body.mesh, test::unit_material(1.0, 0.3, 0.0));
  LinearSystem empty = massless;
  empty.M = Eigen::SparseMatrix<double>(0, 0);
  EXPECT_THROW(mass_matrix(empty, MassChoice::consistent, body.mesh), Error);
}

// Every scheme the TIME card names has its traits; the factory makes exactly those of
// elastodynamics (the marches in velocity build their own), midpoint alone in large deformation.
TEST(TimeScheme, EveryCardSchemeHasTraitsAndTheFactoryMakesElastodynamicsOnes) {
  const FreeBody body;
  std::istringstream names(time_scheme_names);
  int count = 0;
  for (std::string name; std::getline(names, name, '|'); ++count) {
    const TimeSchemeTraits traits = time_scheme_traits(name);
    if (traits.march == MarchKind::elastodynamics)
      EXPECT_EQ(make_time_scheme(name, body.problem(MassChoice::lumped), k)->name(), name);
    else
      EXPECT_THROW(make_time_scheme(name, body.problem(MassChoice::lumped), k), Error) << name;
    EXPECT_EQ(traits.large_deformation, name == "midpoint") << name;
  }
  EXPECT_EQ(count, 4);
  EXPECT_THROW(time_scheme_traits("euler"), Error);
}

} // namespace
} // namespace sig
