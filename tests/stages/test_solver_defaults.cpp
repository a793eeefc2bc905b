// Each SOLVER parameter declared once (issue 24): r, gamma, c and search have their defaults in
// the card schema (core/src/cards.cpp) and ContactSolverParameters takes them from there (and
// ContactNewtonOptions from it), so a deck without a SOLVER card solves with what a
// default-constructed struct holds. The defaults of maxit and eps depend on the stage and stay out
// of the schema (the card fingerprint would record them for a march too): their help texts name
// the two structs' values, which must agree with them.
#include "core/datafile.hpp"
#include "integrator/contact_strategy.hpp"
#include "solver/contact_method.hpp"
#include "solver/contact_newton.hpp"
#include "solver/solver_card.hpp"
#include "stages/augmentation_scale.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace sig {
namespace {

const FieldSpec& solver_field(const std::string& name) {
  const CardSpec* spec = find_card_spec("SOLVER");
  EXPECT_NE(spec, nullptr);
  for (const FieldSpec& field : spec->fields)
    if (field.name == name) return field;
  ADD_FAILURE() << "no SOLVER " << name << "= in the schema";
  return spec->fields.front();
}

TEST(SolverDefaults, ADeckWithoutSolverCardTakesTheSchemasDefaults) {
  const ContactSolverParameters defaults;
  const ContactSolverParameters read =
      read_solver_card(
          Datafile::parse("CONTACT ref=3 obstacle=plane point=0,0 normal=0,1\n", "no_solver.dat"))
          .parameters;
  EXPECT_EQ(read.method, defaults.method);
  EXPECT_EQ(read.r, defaults.r);
  EXPECT_EQ(read.gamma, defaults.gamma);
  EXPECT_EQ(read.c, defaults.c);
  EXPECT_EQ(read.eps, defaults.eps);
  EXPECT_EQ(read.max_iterations, defaults.max_iterations);
  EXPECT_EQ(read.search, defaults.search);
  // The values themselves: the schema's, and the ones the thesis runs used.
  for (const char* name : {"r", "gamma", "c"}) {
    ASSERT_NE(solver_field(name).fallback, nullptr) << name;
    EXPECT_EQ(std::stod(solver_field(name).fallback), 100.0) << name;
  }
  EXPECT_EQ(defaults.r, 100.0);
  EXPECT_EQ(defaults.gamma, 100.0);
  EXPECT_EQ(defaults.c, 100.0);
  EXPECT_EQ(defaults.eps, 1e-5);
  EXPECT_EQ(defaults.search, "auto");
  // The Newton driver given no options stops as the card's defaults say.
  const ContactNewtonOptions options, of_card = newton_options(defaults);
  EXPECT_EQ(options.eps, of_card.eps);
  EXPECT_EQ(options.max_iterations, of_card.max_iterations);
  EXPECT_EQ(options.globalize, of_card.globalize);
}

TEST(SolverDefaults, AMarchsGammaIsTheCards) {
  EXPECT_EQ(ContactStrategyParameters{}.gamma, ContactSolverParameters{}.gamma);
}

TEST(SolverDefaults, MaxitHelpNamesEachStagesDefault) {
  const FieldSpec& maxit = solver_field("maxit");
  EXPECT_EQ(maxit.fallback, nullptr) << "maxit's default depends on the stage";
  const std::string help = maxit.help;
  const std::string solve =
      "sig-solve, default " + std::to_string(ContactSolverParameters{}.max_iterations);
  const std::string march =
      "sig-march, default " + std::to_string(ContactStrategyParameters{}.max_iterations);
  EXPECT_NE(help.find(solve), std::string::npos) << help << "\nlacks: " << solve;
  EXPECT_NE(help.find(march), std::string::npos) << help << "\nlacks: " << march;
}

TEST(SolverDefaults, EpsHelpNamesEachStagesDefault) {
  // A schema default would make a march's explicit eps=1e-5 look like no eps at all to the card
  // fingerprint, though the march's own default is 1e-10: a stale case.hist kept.
  const FieldSpec& eps = solver_field("eps");
  EXPECT_EQ(eps.fallback, nullptr) << "eps's default depends on the stage";
  const auto text = [](double x) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.0e", x);
    return std::string(buffer);
  };
  const std::string help = eps.help;
  const std::string solve = "sig-solve, default " + text(ContactSolverParameters{}.eps);
  const std::string march = "sig-march, default " + text(ContactStrategyParameters{}.eps);
  EXPECT_NE(help.find(solve), std::string::npos) << help << "\nlacks: " << solve;
  EXPECT_NE(help.find(march), std::string::npos) << help << "\nlacks: " << march;
}

} // namespace
} // namespace sig

namespace sig {
namespace {

/// Two contact nodes (0 and 1) of normal (0, 1) and weight 0.5 on K = diag(k): their natural
/// scale is k / 0.5.
struct TwoNodes {
  ContactElements contact;
  Eigen::SparseMatrix<double> K;
  explicit TwoNodes(double k) : K(4, 4) {
    contact.node = {0, 1};
    contact.normal = {Eigen::Vector2d(0, 1), Eigen::Vector2d(0, 1)};
    contact.weight = Eigen::VectorXd::Constant(2, 0.5);
    for (int i = 0; i < 4; ++i)
      K.insert(i, i) = k;
  }
};

TEST(AugmentationScale, TheHintNamesTheCardAndTheScaleOnlyFarOffIt) {
  const TwoNodes si(1e12); // a deck in Pa and m: natural scale 2e12
  EXPECT_DOUBLE_EQ(*natural_contact_scale(si.K, si.contact), 2e12);
  const Datafile defaults = Datafile::parse("SOLVER method=pdas\n", "si.dat");
  const std::string hint = augmentation_scale_hint(defaults, "pdas", si.K, si.contact, false);
  EXPECT_NE(hint.find("si.dat:1: SOLVER gamma=100 (the default) is 5.0e-11 times"),
            std::string::npos)
      << hint;
  EXPECT_NE(hint.find("try gamma=2e+12"), std::string::npos) << hint;
  // Within 1e-4 .. 1e6 of the scale, no hint; far above it only a static solve hints (a
  // march's step matrix is stiffer than K).
  const Datafile near = Datafile::parse("SOLVER method=alm r=1e9\n", "near.dat");
  EXPECT_EQ(augmentation_scale_hint(near, "alm", si.K, si.contact, false), "");
  const TwoNodes soft(1e-6);
  EXPECT_NE(augmentation_scale_hint(defaults, "pdas", soft.K, soft.contact, false), "");
  EXPECT_EQ(augmentation_scale_hint(defaults, "pdas", soft.K, soft.contact, true), "");
  // The projection's parameter c is a length per pressure: 1 / c is compared.
  const Datafile projection = Datafile::parse("SOLVER method=projection c=5e-13\n", "c.dat");
  EXPECT_EQ(augmentation_scale_hint(projection, "projection", si.K, si.contact, false), "");
  // penalty's r is the foundation (the model), never hinted at.
  EXPECT_EQ(augmentation_scale_hint(defaults, "penalty", si.K, si.contact, false), "");
}

} // namespace
} // namespace sig
