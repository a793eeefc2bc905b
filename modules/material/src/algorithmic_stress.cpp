#include "material/algorithmic_stress.hpp"

#include "core/error.hpp"

#include <Eigen/LU>

namespace sig {

namespace {

/// Below this |dC| / |C_m| the step is rigid for Gonzalez's stress (header).
constexpr double kRigidStep = 1e-6;

/// A d x d tensor as a vector in the Voigt order d I + J.
template <int d> Eigen::Matrix<double, d * d, 1> voigt(const Tensor<d>& M) {
  Eigen::Matrix<double, d * d, 1> v;
  for (int I = 0; I < d; ++I)
    for (int J = 0; J < d; ++J)
      v[d * I + J] = M(I, J);
  return v;
}

/// (delta_IK delta_JL + delta_IL delta_JK) / 2, the identity on symmetric tensors.
template <int d> TensorMap<d> symmetric_identity() {
  TensorMap<d> I = TensorMap<d>::Zero();
  for (int i = 0; i < d; ++i)
    for (int j = 0; j < d; ++j) {
      I(d * i + j, d * i + j) += 0.5;
      I(d * i + j, d * j + i) += 0.5;
    }
  return I;
}

/// The law at C: in 2D the in-plane law of its plane mode, in 3D the law itself.
MaterialPoint2d material_point(const HyperelasticLaw& law, const Eigen::Matrix2d& C,
                               bool with_tangent) {
  return law.in_plane(C, with_tangent);
}

MaterialPoint3d material_point(const HyperelasticLaw& law, const Eigen::Matrix3d& C,
                               bool with_tangent) {
  SIG_VERIFY(C.determinant() > 0.0,
             "hyperelastic law: det C = " << C.determinant() << " <= 0 (inverted element)");
  return law.at(C, with_tangent);
}

template <int d>
StepResponse<d> gonzalez(const HyperelasticLaw& law, const Tensor<d>& F_prev, double energy_prev,
                         const Tensor<d>& F, bool with_tangent) {
  const Tensor<d> C_prev = F_prev.transpose() * F_prev, C = F.transpose() * F;
  const Tensor<d> C_mid = 0.5 * (C + C_prev), dC = C - C_prev;
  // S(C_n) enters the tangent only; W(C_n) always.
  const auto mid = material_point(law, C_mid, with_tangent);
  const auto now = material_point(law, C, false);
  const Eigen::Matrix<double, d * d, 1> dc = voigt<d>(dC);
  const double norm2 = dc.squaredNorm();
  const bool rigid = norm2 <= kRigidStep * kRigidStep * C_mid.squaredNorm();

  Tensor<d> Sigma = mid.S;
  double beta = 0;
  if (!rigid) {
    beta = now.energy - energy_prev - 0.5 * (mid.S.array() * dC.array()).sum();
    Sigma += (2.0 * beta / norm2) * dC;
  }
  const Tensor<d> F_mid = 0.5 * (F + F_prev);
  StepResponse<d> out;
  out.energy = now.energy;
  out.stress = F_mid * Sigma;
  if (!with_tangent) return out;

  // D = dSigma / dC_n (header), then A(d i + J, d k + L) = delta_ik Sigma_JL / 2
  // + 2 F_mid,iI D(d I + J, d K + L) F_kK, D being symmetric in K, L.
  TensorMap<d> D = 0.25 * mid.CC;
  if (!rigid) {
    const Eigen::Matrix<double, d * d, 1> b = 0.5 * voigt<d>(now.S - mid.S) - 0.125 * (mid.CC * dc);
    D += (2.0 / norm2) * dc * b.transpose() +
         2.0 * beta *
             (symmetric_identity<d>() / norm2 - (2.0 / (norm2 * norm2)) * dc * dc.transpose());
  }
  TensorMap<d> T; // T(d i + J, c) = F_mid,iI D(d I + J, c)
  for (int i = 0; i < d; ++i)
    for (int J = 0; J < d; ++J) {
      T.row(d * i + J) = F_mid(i, 0) * D.row(J);
      for (int I = 1; I < d; ++I)
        T.row(d * i + J) += F_mid(i, I) * D.row(d * I + J);
    }
  for (int k = 0; k < d; ++k)
    for (int L = 0; L < d; ++L) {
      Eigen::Matrix<double, d * d, 1> column = T.col(L) * F(k, 0);
      for (int K = 1; K < d; ++K)
        column += T.col(d * K + L) * F(k, K);
      out.tangent.col(d * k + L) = 2.0 * column;
    }
  for (int i = 0; i < d; ++i)
    out.tangent.template block<d, d>(d * i, d * i) += 0.5 * Sigma;
  return out;
}

template <int d>
StepResponse<d> midpoint(const HyperelasticLaw& law, const Tensor<d>& F_prev, const Tensor<d>& F,
                         bool with_tangent) {
  StepResponse<d> out = piola_response(law, Tensor<d>(0.5 * (F + F_prev)), with_tangent);
  if (with_tangent) out.tangent *= 0.5; // dF_m = dF_n / 2
  out.energy = step_energy(law, F);
  return out;
}

template <int d>
StepResponse<d> step_response_in(const HyperelasticLaw& law, AlgorithmicStress kind,
                                 const Tensor<d>& F_prev, double energy_prev, const Tensor<d>& F,
                                 bool with_tangent) {
  SIG_VERIFY(F.determinant() > 0.0 && F_prev.determinant() > 0.0,
             "time step: det F = " << F.determinant() << " at the end, " << F_prev.determinant()
                                   << " at the start (inverted element)");
  return kind == AlgorithmicStress::gonzalez
             ? gonzalez<d>(law, F_prev, energy_prev, F, with_tangent)
             : midpoint<d>(law, F_prev, F, with_tangent);
}

} // namespace

double step_energy(const HyperelasticLaw& law, const Eigen::Matrix2d& F) {
  return law.in_plane(F.transpose() * F, false).energy;
}

double step_energy(const HyperelasticLaw& law, const Eigen::Matrix3d& F) {
  return material_point(law, Eigen::Matrix3d(F.transpose() * F), false).energy;
}

StepResponse<2> piola_response(const HyperelasticLaw& law, const Eigen::Matrix2d& F,
                               bool /*with_tangent: the 2D response computes it anyway*/) {
  const HyperelasticResponse r = law.response(F);
  return {r.stress, r.tangent, r.energy};
}

StepResponse<3> piola_response(const HyperelasticLaw& law, const Eigen::Matrix3d& F,
                               bool with_tangent) {
  SIG_VERIFY(F.determinant() > 0.0,
             "hyperelastic law: det F = " << F.determinant() << " <= 0 (inverted element)");
  const MaterialPoint3d point = law.at(F.transpose() * F, with_tangent);
  StepResponse<3> out;
  out.energy = point.energy;
  out.stress = F * point.S;
  if (with_tangent) out.tangent = first_piola_tangent(F, point);
  return out;
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

StepResponse<2> step_response(const HyperelasticLaw& law, AlgorithmicStress kind,
                              const Eigen::Matrix2d& F_prev, double energy_prev,
                              const Eigen::Matrix2d& F, bool with_tangent) {
  return step_response_in<2>(law, kind, F_prev, energy_prev, F, with_tangent);
}

StepResponse<3> step_response(const HyperelasticLaw& law, AlgorithmicStress kind,
                              const Eigen::Matrix3d& F_prev, double energy_prev,
                              const Eigen::Matrix3d& F, bool with_tangent) {
  return step_response_in<3>(law, kind, F_prev, energy_prev, F, with_tangent);
}

} // namespace sig
