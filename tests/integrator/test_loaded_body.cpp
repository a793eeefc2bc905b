// A rectangle clamped on its left side (Dirichlet elimination) under a time-dependent load on
// its right side: the discrete energy changes exactly by the work of the load the scheme applies
// (E_n - E_0 = W_n), and Newmark and midpoint agree for a load affine in time but not for a
// curved one (their only difference is f(t_{n+1/2}) against (f_n + f_{n+1}) / 2).
#include "assembly/dirichlet.hpp"
#include "integrator/elastodynamic_march.hpp"
#include "integrator/elastodynamics.hpp"
#include "integrator/midpoint.hpp"
#include "integrator/newmark.hpp"
#include "stages/march_inputs.hpp"
#include "test_bodies.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace sig {
namespace {

constexpr double k = 0.01;
constexpr int steps = 400;

struct ClampedBody {
  Mesh mesh = test::perturbed_rectangle(3.0, 1.0, 12, 4);
  LinearSystem system = clamped_system();
  ReducedSystem reduced = reduce(system);

  LinearSystem clamped_system() const {
    LinearSystem s = test::free_body_system(mesh, test::unit_material());
    for (int i : mesh.nodes_with_ref(1)) { // left side
      s.dirichlet_dofs.push_back(2 * i);
      s.dirichlet_dofs.push_back(2 * i + 1);
    }
    std::sort(s.dirichlet_dofs.begin(), s.dirichlet_dofs.end());
    s.dirichlet_values = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(s.dirichlet_dofs.size()));
    return s;
  }
  // A downward and outward force on the right side nodes, on the free dofs.
  Eigen::VectorXd right_side_force() const {
    Eigen::VectorXd g = Eigen::VectorXd::Zero(system.num_dofs());
    for (int i : mesh.nodes_with_ref(4))
      g.segment<2>(2 * i) << 0.02, -0.05;
    return reduced.restrict(g);
  }
  Elastodynamics problem(LoadHistory load) const {
    Elastodynamics p = reduced_elastodynamics(reduced, system.M);
    p.load = std::move(load);
    return p;
  }
  DynamicState rest() const {
    return {0.0, Eigen::VectorXd::Zero(reduced.num_free()),
            Eigen::VectorXd::Zero(reduced.num_free())};
  }
};

class LoadedBody : public ::testing::TestWithParam<const char*> {};

TEST_P(LoadedBody, EnergyChangesByTheWorkOfTheLoad) {
  const ClampedBody body;
  const Eigen::VectorXd g = body.right_side_force();
  const auto scheme = make_time_scheme(
      GetParam(), body.problem([g](double t) -> Eigen::VectorXd { return std::sin(3 * t) * g; }),
      k);
  const MarchHistory h = march(*scheme, body.rest(), steps);
  double scale = 0.0, imbalance = 0.0;
  for (const StepRecord& step : h.steps) {
    const EnergyRecord& r = step.energy;
    scale = std::max(scale, r.total);
    imbalance = std::max(imbalance, std::abs(r.total - r.external_work - h.steps[0].energy.total));
  }
  EXPECT_GT(scale, 1e-4); // the load does work
  EXPECT_LT(imbalance, 1e-10 * scale) << GetParam();
  // The clamped side stays in place: the expanded state has zero there.
  const Eigen::VectorXd u = body.reduced.expand(h.final_state().u);
  for (int d : body.system.dirichlet_dofs)
    EXPECT_EQ(u(d), 0.0);
}

INSTANTIATE_TEST_SUITE_P(Schemes, LoadedBody, ::testing::Values("midpoint", "newmark"));

double max_state_difference(const ClampedBody& body, const LoadHistory& load) {
  const ImplicitMidpoint midpoint(body.problem(load), k);
  const NewmarkAverageAcceleration newmark(body.problem(load), k);
  DynamicState a = body.rest(), b = body.rest();
  double scale = 0.0, diff = 0.0;
  for (int n = 0; n < steps; ++n) {
    a = midpoint.advance(a);
    b = newmark.advance(b);
    scale = std::max(scale, a.u.lpNorm<Eigen::Infinity>());
    diff = std::max(diff, (a.u - b.u).lpNorm<Eigen::Infinity>());
  }
  return diff / scale;
}

TEST(NewmarkAgainstMidpoint, SameForAffineLoadDifferentForCurvedLoad) {
  const ClampedBody body;
  const Eigen::VectorXd g = body.right_side_force();
  EXPECT_LT(
      max_state_difference(body, [g](double t) -> Eigen::VectorXd { return (1 + 2 * t) * g; }),
      1e-11);
  // sin(10 t): the two load samplings differ by k^2 |f''| / 8 per step.
  EXPECT_GT(
      max_state_difference(body, [g](double t) -> Eigen::VectorXd { return std::sin(10 * t) * g; }),
      1e-5);
}

} // namespace
} // namespace sig
