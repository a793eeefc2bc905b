#include "material/algorithmic_stress.hpp"

#include "core/error.hpp"

#include <Eigen/LU>

namespace sig {

namespace {

/// Below this |dC| / |C_m| the step is rigid for Gonzalez's stress (header).
constexpr double kRigidStep = 1e-6;

/// A 2 x 2 tensor as a vector in the Voigt order 2 I + J.
Eigen::Vector4d voigt(const Eigen::Matrix2d& M) {
  return {M(0, 0), M(0, 1), M(1, 0), M(1, 1)};
}

/// (delta_IK delta_JL + delta_IL delta_JK) / 2, the identity on symmetric tensors.
Eigen::Matrix4d symmetric_identity() {
  Eigen::Matrix4d I = Eigen::Matrix4d::Zero();
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      I(2 * i + j, 2 * i + j) += 0.5;
      I(2 * i + j, 2 * j + i) += 0.5;
    }
  return I;
}

StepResponse gonzalez(const HyperelasticLaw& law, const Eigen::Matrix2d& F_prev, double energy_prev,
                      const Eigen::Matrix2d& F, bool with_tangent) {
  const Eigen::Matrix2d C_prev = F_prev.transpose() * F_prev, C = F.transpose() * F;
  const Eigen::Matrix2d C_mid = 0.5 * (C + C_prev), dC = C - C_prev;
  const MaterialPoint2d mid = law.in_plane(C_mid), now = law.in_plane(C);
  const Eigen::Vector4d dc = voigt(dC);
  const double norm2 = dc.squaredNorm();
  const bool rigid = norm2 <= kRigidStep * kRigidStep * C_mid.squaredNorm();

  Eigen::Matrix2d Sigma = mid.S;
  double beta = 0;
  if (!rigid) {
    beta = now.energy - energy_prev - 0.5 * (mid.S.array() * dC.array()).sum();
    Sigma += (2.0 * beta / norm2) * dC;
  }
  const Eigen::Matrix2d F_mid = 0.5 * (F + F_prev);
  StepResponse out;
  out.energy = now.energy;
  out.stress = F_mid * Sigma;
  if (!with_tangent) return out;

  // D = dSigma / dC_n (header), then A(2 i + J, 2 k + L) = delta_ik Sigma_JL / 2
  // + 2 F_mid,iI D(2 I + J, 2 K + L) F_kK, D being symmetric in K, L.
  Eigen::Matrix4d D = 0.25 * mid.CC;
  if (!rigid) {
    const Eigen::Vector4d b = 0.5 * voigt(now.S - mid.S) - 0.125 * (mid.CC * dc);
    D +=
        (2.0 / norm2) * dc * b.transpose() +
        2.0 * beta * (symmetric_identity() / norm2 - (2.0 / (norm2 * norm2)) * dc * dc.transpose());
  }
  Eigen::Matrix4d T; // T(2 i + J, c) = F_mid,iI D(2 I + J, c)
  for (int i = 0; i < 2; ++i)
    for (int J = 0; J < 2; ++J)
      T.row(2 * i + J) = F_mid(i, 0) * D.row(J) + F_mid(i, 1) * D.row(2 + J);
  for (int k = 0; k < 2; ++k)
    for (int L = 0; L < 2; ++L)
      out.tangent.col(2 * k + L) = 2.0 * (T.col(L) * F(k, 0) + T.col(2 + L) * F(k, 1));
  for (int i = 0; i < 2; ++i)
    out.tangent.block<2, 2>(2 * i, 2 * i) += 0.5 * Sigma;
  return out;
}

StepResponse midpoint(const HyperelasticLaw& law, const Eigen::Matrix2d& F_prev,
                      const Eigen::Matrix2d& F, bool with_tangent) {
  const HyperelasticResponse mid = law.response(0.5 * (F + F_prev));
  StepResponse out;
  out.stress = mid.stress;
  if (with_tangent) out.tangent = 0.5 * mid.tangent; // dF_m = dF_n / 2
  out.energy = step_energy(law, F);
  return out;
}

} // namespace

double step_energy(const HyperelasticLaw& law, const Eigen::Matrix2d& F) {
  return law.in_plane(F.transpose() * F).energy;
}

std::string to_string(AlgorithmicStress stress) {
  return stress == AlgorithmicStress::gonzalez ? "gonzalez" : "midpoint";
}

AlgorithmicStress algorithmic_stress_named(const std::string& name) {
  for (AlgorithmicStress s : {AlgorithmicStress::gonzalez, AlgorithmicStress::midpoint})
    if (to_string(s) == name) return s;
  SIG_VERIFY(false,
             "algorithmic stress '" << name << "' is unknown; known: " << algorithmic_stress_names);
  return AlgorithmicStress::gonzalez;
}

StepResponse step_response(const HyperelasticLaw& law, AlgorithmicStress kind,
                           const Eigen::Matrix2d& F_prev, double energy_prev,
                           const Eigen::Matrix2d& F, bool with_tangent) {
  SIG_VERIFY(F.determinant() > 0.0 && F_prev.determinant() > 0.0,
             "time step: det F = " << F.determinant() << " at the end, " << F_prev.determinant()
                                   << " at the start (inverted element)");
  return kind == AlgorithmicStress::gonzalez ? gonzalez(law, F_prev, energy_prev, F, with_tangent)
                                             : midpoint(law, F_prev, F, with_tangent);
}

} // namespace sig
