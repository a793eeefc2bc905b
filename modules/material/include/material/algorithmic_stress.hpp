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
// Works in plane strain and plane stress alike, on the 2D law of HyperelasticLaw::in_plane.
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

/// The stress of a step and what goes with it.
struct StepResponse {
  Eigen::Matrix2d stress = Eigen::Matrix2d::Zero();  ///< Pi of the step
  Eigen::Matrix4d tangent = Eigen::Matrix4d::Zero(); ///< dPi / dF_n, Voigt order (2 i + J)
  double energy = 0.0;                               ///< W(F_n), per unit reference volume
};

/// W(F) as the step stress computes it (from the in-plane C): the energy a step starts from.
double step_energy(const HyperelasticLaw& law, const Eigen::Matrix2d& F);

/// Pi of the step from F_prev, whose energy is `energy_prev` = step_energy(F_prev) (computed once
/// per step), to F, and its tangent when `with_tangent`; the energy is step_energy(F). Throws
/// sig::Error as HyperelasticLaw::response outside the law's domain (det F <= 0 at F or at the
/// midpoint).
StepResponse step_response(const HyperelasticLaw& law, AlgorithmicStress kind,
                           const Eigen::Matrix2d& F_prev, double energy_prev,
                           const Eigen::Matrix2d& F, bool with_tangent = true);

} // namespace sig
