// The dynamic contact strategies (integrator/contact_strategy.hpp) on a small elastic block
// thrown at a rigid plane: the discrete energy identity with the work of the contact forces for
// every strategy, the invariants that define each one (specific penalty: E + (r/2) sum w pen^2
// conserved, (3.53); two-step: no energy loss, Signorini's loss larger; ipm: penetration <= g;
// signorini: no penetration) and a failed Newton reported as a result.
#include "assembly/dirichlet.hpp"
#include "contact/contact_elements.hpp"
#include "core/error.hpp"
#include "integrator/contact_strategy.hpp"
#include "integrator/elastodynamic_march.hpp"
#include "integrator/elastodynamics.hpp"
#include "stages/march_inputs.hpp"
#include "test_bodies.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace sig {
namespace {

constexpr double kGap = 0.05;        // initial distance of the block to the plane
constexpr double kSpeed = 1.0;       // thrown downwards; impact at t = 0.05
constexpr double kStiffness = 100.0; // r, per unit area (the block: E = 1, rho = 1)
constexpr double kAllowed = 0.002;   // ipm's g

/// A 1 x 1 block of unit density and stiffness, 8 x 8 cells, lifted by kGap above the plane
/// x2 = 0, its bottom side (ref 3) the contact boundary.
struct ThrownBlock {
  Mesh mesh = lifted();
  LinearSystem system = test::free_body_system(mesh, test::unit_material());
  ReducedSystem reduced = reduce(system);
  ContactElements elements;

  explicit ThrownBlock(double extra_gap = 0.0) {
    ContactLaw law;
    law.depth = extra_gap;
    elements = build_contact_elements(mesh, 3, HalfPlane({0, 0}, {0, 1}), law);
  }
  static Mesh lifted() {
    Mesh m = test::perturbed_rectangle(1.0, 1.0, 8, 8);
    for (Point& x : m.nodes)
      x.y() += kGap;
    return m;
  }
  Elastodynamics problem(MassChoice mass) const {
    return reduced_elastodynamics(reduced, mass_matrix(system, mass, mesh, elements.node));
  }
  DynamicState thrown() const {
    Eigen::VectorXd v = Eigen::VectorXd::Zero(system.num_dofs());
    for (int i = 0; i < mesh.num_nodes(); ++i)
      v(2 * i + 1) = -kSpeed;
    return {0.0, Eigen::VectorXd::Zero(reduced.num_free()), reduced.restrict(v)};
  }
  ContactBoundary boundary() const { return contact_boundary(elements, mesh, reduced); }
};

struct BlockRun {
  MarchHistory history;
  ContactBoundary boundary;
};

BlockRun run(const std::string& strategy, int steps, double k = 0.01,
             MassChoice mass = MassChoice::consistent, const std::string& scheme = "midpoint",
             int max_iterations = 50, Persistency persistency = Persistency::midpoint) {
  const ThrownBlock block(strategy == "ipm" ? kAllowed : 0.0);
  const auto time_scheme = make_time_scheme(scheme, block.problem(mass), k);
  ContactStrategyParameters p;
  p.r = kStiffness;
  p.max_iterations = max_iterations;
  p.persistency = persistency;
  BlockRun r{{}, block.boundary()};
  r.history = march_with_contact(*time_scheme, r.boundary, *make_contact_strategy(strategy, p),
                                 block.thrown(), steps, 10);
  return r;
}

double initial_energy() {
  return 0.5 * kSpeed * kSpeed;
} // 1/2 rho |block| v^2

class EveryStrategy
    : public ::testing::TestWithParam<std::tuple<const char*, const char*, MassChoice>> {};

// E_{n+1} - E_n = f_bar . du + contact work of the step (no load here), checked with the force
// columns of the record: fails if the forces enter the step with the wrong factor or sign.
TEST_P(EveryStrategy, EnergyChangesByTheWorkOfTheContactForces) {
  const auto [strategy, scheme, mass] = GetParam();
  const BlockRun r = run(strategy, 150, 0.01, mass, scheme);
  ASSERT_TRUE(r.history.converged) << r.history.failure;
  ASSERT_EQ(r.history.steps.size(), 151u);
  const double e0 = r.history.steps[0].energy.total;
  EXPECT_NEAR(e0, initial_energy(), 1e-12);
  int contact_steps = 0;
  for (const StepRecord& step : r.history.steps) {
    const EnergyRecord& e = step.energy;
    EXPECT_NEAR(e.total - e.contact_work, e0, 1e-11 * e0) << strategy << " step " << step.step;
    contact_steps += e.active_nodes > 0 ? 1 : 0;
    // One force per contact node at every step, never pulling the body to the plane.
    ASSERT_EQ(step.contact.normal_force.size(), r.boundary.size());
    EXPECT_GE(step.contact.normal_force.minCoeff(), 0.0) << strategy;
  }
  EXPECT_GT(contact_steps, 5) << strategy; // the block did hit the plane
}

INSTANTIATE_TEST_SUITE_P(
    Strategies, EveryStrategy,
    ::testing::Values(std::make_tuple("signorini", "midpoint", MassChoice::consistent),
                      std::make_tuple("compliance", "midpoint", MassChoice::consistent),
                      std::make_tuple("specific-penalty", "midpoint", MassChoice::consistent),
                      std::make_tuple("two-step", "midpoint", MassChoice::consistent),
                      std::make_tuple("ipm", "midpoint", MassChoice::consistent),
                      std::make_tuple("signorini", "newmark", MassChoice::lumped),
                      std::make_tuple("ipm", "newmark", MassChoice::emm),
                      std::make_tuple("two-step", "midpoint", MassChoice::emm)));

// (3.53): the specific penalty's work is the change of (r / 2) sum w [pen]_+^2, so that energy
// plus the foundation's is constant to round-off through the whole impact.
TEST(SpecificPenalty, ConservesEnergyPlusPenaltyEnergy) {
  const BlockRun r = run("specific-penalty", 300);
  ASSERT_TRUE(r.history.converged) << r.history.failure;
  const double e0 = r.history.steps[0].energy.total;
  // The penetrations of every step are needed, not only at the kept states: march again with an
  // observer.
  const ThrownBlock block;
  const auto scheme = make_time_scheme("midpoint", block.problem(MassChoice::consistent), 0.01);
  ContactStrategyParameters p;
  p.r = kStiffness;
  const ContactBoundary boundary = block.boundary();
  double worst = 0, deepest = 0;
  const auto check = [&](const StepRecord& step, const DynamicState& state) {
    const EnergyRecord& e = step.energy;
    const Eigen::VectorXd pen = boundary.penetration(boundary.B * state.u);
    const double foundation = 0.5 * kStiffness * boundary.setting.weight.dot(pen.cwiseProduct(pen));
    worst = std::max(worst, std::abs(e.total + foundation - e0));
    deepest = std::max(deepest, pen.maxCoeff());
  };
  const MarchHistory h =
      march_with_contact(*scheme, boundary, *make_contact_strategy("specific-penalty", p),
                         block.thrown(), 300, 0, check);
  ASSERT_TRUE(h.converged);
  EXPECT_GT(deepest, 1e-3); // the foundation did store energy
  EXPECT_LT(worst, 1e-11 * e0);
}

double energy_after(const BlockRun& r) {
  return r.history.steps.back().energy.total;
}

double deepest(const BlockRun& r) {
  double pen = 0;
  for (const StepRecord& step : r.history.steps)
    pen = std::max(pen, step.energy.max_penetration);
  return pen;
}

// [13] with persistency on the increment: step (b) makes every contact force workless, no loss
// across the impact, while Signorini at t_n loses the normal kinetic energy of the nodes that
// hit; a node (a) left free is free in (b) and may sink. With persistency on the midpoint
// velocity (C15) a node arriving at speed v sinks a further k v / 2 or so, and the arrival costs
// energy, less than Signorini's.
TEST(TwoStep, IncrementKeepsTheEnergyMidpointPenetratesSignoriniLosesMore) {
  const BlockRun increment =
      run("two-step", 300, 0.01, MassChoice::consistent, "midpoint", 50, Persistency::increment);
  const BlockRun midpoint = run("two-step", 300);
  const BlockRun sig = run("signorini", 300);
  ASSERT_TRUE(increment.history.converged && midpoint.history.converged && sig.history.converged);
  const double e0 = initial_energy();
  for (const BlockRun* r : {&increment, &midpoint, &sig}) // the block has left the plane
    EXPECT_EQ(r->history.steps.back().energy.active_nodes, 0);
  const double loss_increment = (e0 - energy_after(increment)) / e0;
  const double loss_midpoint = (e0 - energy_after(midpoint)) / e0;
  const double loss_sig = (e0 - energy_after(sig)) / e0;
  EXPECT_LT(std::abs(loss_increment), 0.01);
  EXPECT_GT(loss_sig, 0.02);
  EXPECT_GT(loss_sig, 5 * std::abs(loss_increment));
  EXPECT_GT(loss_midpoint, 0.0);
  EXPECT_LT(loss_midpoint, loss_sig);
  const double half_step = 0.5 * 0.01 * kSpeed; // k v / 2
  EXPECT_LT(deepest(increment), 2 * half_step);
  EXPECT_GT(deepest(midpoint), deepest(increment) + 0.3 * half_step);
  EXPECT_LT(deepest(midpoint), 4 * half_step);
}

TEST(Signorini, NoPenetrationAtAnyStep) {
  const BlockRun r = run("signorini", 300);
  ASSERT_TRUE(r.history.converged) << r.history.failure;
  int contact_steps = 0;
  for (const StepRecord& step : r.history.steps) {
    EXPECT_LE(step.energy.max_penetration, 1e-12 * 1.0) << "step " << step.step; // block's size
    contact_steps += step.energy.active_nodes > 0 ? 1 : 0;
  }
  EXPECT_GT(contact_steps, 5);
}

// (8.31): penetration bounded by g at every step; with the Equivalent Mass Matrix the energy
// across the impact within 0.5 %.
TEST(ImprovedPenalty, PenetrationBoundedByGAndEnergyKeptWithEmm) {
  for (const MassChoice mass : {MassChoice::consistent, MassChoice::emm}) {
    const BlockRun r = run("ipm", 300, 0.01, mass);
    ASSERT_TRUE(r.history.converged) << r.history.failure;
    double deepest = 0;
    for (const StepRecord& step : r.history.steps) {
      EXPECT_LE(step.energy.max_penetration, kAllowed * (1 + 1e-12)) << "step " << step.step;
      deepest = std::max(deepest, step.energy.max_penetration);
    }
    EXPECT_GT(deepest, 0.5 * kAllowed); // the bound was reached, not idle
    if (mass == MassChoice::emm) {
      EXPECT_EQ(r.history.steps.back().energy.active_nodes, 0);
      EXPECT_LT(std::abs(energy_after(r) - initial_energy()), 0.005 * initial_energy());
    }
  }
}

// A Newton that cannot converge (one iteration allowed on the impact) stops the march at that
// step: a result with the steps done, never an exception or a non-finite number.
TEST(ContactMarch, NewtonFailureStopsTheMarchAndSaysWhere) {
  for (const char* strategy : {"signorini", "specific-penalty", "two-step", "ipm"}) {
    MarchHistory h;
    ASSERT_NO_THROW(h = run(strategy, 100, 0.01, MassChoice::consistent, "midpoint", 1).history);
    EXPECT_FALSE(h.converged) << strategy;
    EXPECT_NE(h.failure.find("step "), std::string::npos) << h.failure;
    // The impact starts at t = kGap / kSpeed = 0.05: steps before it are done.
    ASSERT_GE(h.steps_done(), 5u) << strategy;
    EXPECT_LT(h.steps_done(), 101u) << strategy;
    // The failed step is the last record, after the steps done.
    const StepRecord& failed = h.steps.back();
    EXPECT_FALSE(failed.converged);
    EXPECT_EQ(failed.step, static_cast<int>(h.steps_done()));
    EXPECT_NE(h.failure.find("step " + std::to_string(failed.step)), std::string::npos)
        << h.failure;
    for (const StepRecord& step : h.steps)
      EXPECT_TRUE(std::isfinite(step.energy.total) && std::isfinite(step.energy.contact_work));
    EXPECT_TRUE(h.final_state().u.allFinite() && h.final_state().v.allFinite());
    EXPECT_EQ(h.output_step.back(), failed.step - 1); // the last state done is kept
  }
}

// The traits a card reader asks of a strategy are those of the strategy the factory makes: r is
// required exactly where the traits say so, and the strategy made carries the name asked for.
TEST(ContactStrategyFactory, TraitsMatchTheStrategiesMade) {
  for (const char* name : {"signorini", "compliance", "specific-penalty", "two-step", "ipm"}) {
    ContactStrategyParameters p;
    const bool needs_r = contact_strategy_traits(name).needs_r;
    if (needs_r)
      EXPECT_THROW(make_contact_strategy(name, p), Error) << name;
    else
      EXPECT_EQ(make_contact_strategy(name, p)->name(), name);
    p.r = 1e3;
    EXPECT_EQ(make_contact_strategy(name, p)->name(), name);
  }
  EXPECT_THROW(contact_strategy_traits("penalty"), Error);
  EXPECT_THROW(make_contact_strategy("penalty", ContactStrategyParameters{}), Error);
}

} // namespace
} // namespace sig
