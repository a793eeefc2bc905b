#pragma once
// The stress of one time step of the implicit midpoint rule in large deformation (thesis
// (3.39)-(3.42), (8.26); ALGORITHMS.md 4.2): the step from the deformation gradient F_{n-1} to
// F_n is driven by a first Piola stress Pi of the pair, and the internal force of the step is
// int Pi : grad v. Two stresses:
//
//   gonzalez  (3.41), Gonzalez's algorithmic stress: Pi = F_m Sigma with F_m = (F_n + F_{n-1}) / 2
//             and, with C_m = (C_n + C_{n-1}) / 2, dC = C_n - C_{n-1}, S(C) = 2 dW/dC,
//                 Sigma = S(C_m) + 2 [W(C_n) - W(C_{n-1}) - S(C_m) : dC / 2] dC / (dC : dC).
//             Since F_m^T (F_n - F_{n-1}) = dC / 2 + a skew part and Sigma is symmetric, it
//             obeys the energy identity (3.42) exactly,
//                 Pi : (F_n - F_{n-1}) = W(C_n) - W(C_{n-1}),
//             so the midpoint rule conserves the discrete energy (8.33) of any hyperelastic law,
//             and, Sigma being symmetric, the angular momentum too. A rigid step (dC = 0) has
//             Sigma = S(C_m), the limit of the formula: it is used once |dC| < 1e-6 |C_m|, where
//             the bracket, a difference of nearly equal energies, would be rounding divided by
//             |dC|^2 (the limit then differs from the formula by O(|dC|^3), far below rounding
//             of the energy);
//   midpoint  the plain midpoint configuration, Pi = P(F_m) = dW/dF at F_m: conserves the
//             angular momentum but not the energy of a nonlinear law (the contrast Gonzalez's
//             stress is built to remove).
//
// Both come with their derivative with respect to F_n (F_{n-1} is data of the step), for a
// Newton method that converges quadratically. Gonzalez's is non-symmetric,
//     dPi = dF_n Sigma / 2 + F_m dSigma,  dSigma = D : dC_n,  dC_n = dF_n^T F_n + F_n^T dF_n,
//     D = CC_m / 4 + (2 / |dC|^2) dC (x) [(S(C_n) - S(C_m)) / 2 - CC_m : dC / 8]
//         + 2 beta [Isym / |dC|^2 - 2 dC (x) dC / |dC|^4],      CC = 2 dS/dC,
// beta the bracket of Sigma (ALGORITHMS.md 4.2), so the step's Newton matrix needs an LU solver.
// In 2D it works in plane strain and plane stress alike, on the 2D law of
// HyperelasticLaw::in_plane; in 3D on the law's C itself (HyperelasticLaw::at). One formula for
// both, templated on the dimension d.
#include "material/hyperelastic.hpp"

#include <Eigen/Core>
#include <string>

namespace sig {

/// Card field `TIME stress=`.
enum class AlgorithmicStress { gonzalez, midpoint };
inline constexpr const char* algorithmic_stress_names = "gonzalez | midpoint";
std::string to_string(AlgorithmicStress stress);
/// sig::Error listing the names for anything else.
AlgorithmicStress algorithmic_stress_named(const std::string& name);

/// A d x d tensor (d = 2 or 3, the mesh's dimension) and a map between two of them in the
/// row-major Voigt order of the header (index d i + J).
template <int d> using Tensor = Eigen::Matrix<double, d, d>;
template <int d> using TensorMap = Eigen::Matrix<double, d * d, d * d>;

/// The stress of a step and what goes with it, in R^d.
template <int d> struct StepResponse {
  Tensor<d> stress = Tensor<d>::Zero();        ///< Pi of the step
  TensorMap<d> tangent = TensorMap<d>::Zero(); ///< dPi / dF_n, Voigt order (d i + J)
  double energy = 0.0;                         ///< W(F_n), per unit reference volume
};

/// W(F) as the step stress computes it (from C = F^T F; in 2D the in-plane C of the plane
/// mode, in 3D the law itself): the energy a step starts from.
double step_energy(const HyperelasticLaw& law, const Eigen::Matrix2d& F);
double step_energy(const HyperelasticLaw& law, const Eigen::Matrix3d& F);

/// Pi of the step from F_prev, whose energy is `energy_prev` = step_energy(F_prev) (computed once
/// per step), to F, and its tangent when `with_tangent`; the energy is step_energy(F). One
/// formula for d = 2 and 3 (in 3D the thesis's (3.41) on the whole C). Throws sig::Error as
/// HyperelasticLaw::response outside the law's domain (det F <= 0 at F or at the midpoint).
StepResponse<2> step_response(const HyperelasticLaw& law, AlgorithmicStress kind,
                              const Eigen::Matrix2d& F_prev, double energy_prev,
                              const Eigen::Matrix2d& F, bool with_tangent = true);
StepResponse<3> step_response(const HyperelasticLaw& law, AlgorithmicStress kind,
                              const Eigen::Matrix3d& F_prev, double energy_prev,
                              const Eigen::Matrix3d& F, bool with_tangent = true);

/// The law's own response at F: W(F), P = dW/dF and dP/dF (when `with_tangent`; in 2D always),
/// in the same form as a step's (a static solve's stress). 2D: HyperelasticLaw::response (plane
/// strain or stress); 3D: the law at C = F^T F, P = F S. Throws as HyperelasticLaw::response.
StepResponse<2> piola_response(const HyperelasticLaw& law, const Eigen::Matrix2d& F,
                               bool with_tangent = true);
StepResponse<3> piola_response(const HyperelasticLaw& law, const Eigen::Matrix3d& F,
                               bool with_tangent = true);

} // namespace sig
