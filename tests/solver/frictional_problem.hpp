// The random frictional test problem of the contact Newton's unit tests in 2D and 3D: m contact
// nodes with d unknowns each (the d - 1 slips, then the normal displacement), a dense SPD S
// coupling all of them, a load whose components the test chooses, gaps from 0 (touching) to out
// of reach; and the two friction laws the tests take.
#pragma once

#include "solver/condensed_contact.hpp"

#include <Eigen/Dense>

#include <random>

namespace sig::test {

struct Frictional {
  CondensedProblem problem;
  ContactSetting setting;
};

/// `load(c, u)` is the load's component c of a node (0 .. d - 2 tangential, d - 1 normal) from a
/// uniform draw u in [-1, 1]; the draws follow the dofs' order, so a seed fixes the problem.
template <class Load>
Frictional random_frictional_problem(int d, int m, unsigned seed, const ContactLaw& law,
                                     Load load) {
  Frictional fr;
  CondensedProblem& p = fr.problem;
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const int n = d * m;
  Eigen::MatrixXd A(n, n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      A(i, j) = uniform(random);
  p.S = 0.2 * A * A.transpose() + 2.0 * Eigen::MatrixXd::Identity(n, n);
  p.f.resize(n);
  p.gap.resize(m);
  for (int q = 0; q < m; ++q) {
    for (int c = 0; c + 1 < d; ++c)
      p.tangential_dof.push_back(d * q + c);
    p.normal_dof.push_back(d * q + d - 1);
    for (int c = 0; c < d; ++c)
      p.f[d * q + c] = load(c, uniform(random));
    p.gap[q] = q % 4 == 3 ? 5.0 : 0.05 * (q % 4);
  }
  fr.setting.weight = Eigen::VectorXd::LinSpaced(m, 0.6, 1.4);
  fr.setting.law.assign(m, law);
  return fr;
}

inline ContactLaw coulomb(double mu) {
  ContactLaw law;
  law.friction = FrictionLaw::coulomb;
  law.mu = mu;
  return law;
}

inline ContactLaw tresca(double threshold) {
  ContactLaw law;
  law.friction = FrictionLaw::tresca;
  law.threshold = threshold;
  return law;
}

} // namespace sig::test
