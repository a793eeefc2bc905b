#pragma once
// The a posteriori error estimate of sig-estimate: Zienkiewicz and Zhu's recovery estimator
// (O. C. Zienkiewicz, J. Z. Zhu, "A simple error estimator and adaptive procedure for practical
// engineering analysis", IJNME 24 (1987) 337-357), written in the norm of V that sig-error
// measures (thesis (2.6), ALGORITHMS.md 0.6), ||v||_V = ||eps(v)||_L2, so that the estimate and
// the true error are in the same units and their ratio is the effectivity index:
//
//   eta_T^2 = integral over T of |G eps_h - eps_h|^2,      eta^2 = sum over T of eta_T^2,
//
// eps_h the P1 strain (constant on T), G eps_h its recovery: the continuous P1 field whose value
// at a vertex is the area-weighted mean of eps_h over the triangles around it (the nodal
// averaging of ZZ 1987), taken per sub-domain, since the strain jumps where the material does.
// |e|^2 = e : e = e11^2 + e22^2 + 2 e12^2. On smooth solutions G eps_h approximates eps(u) to a
// higher order than eps_h (superconvergent on structured meshes), so eta / ||eps(u - u_h)||
// tends to 1. The estimator uses u_h only: on Gamma3 no contact term enters it (unlike the
// residual estimators of Hild and Nicaise, M2AN 41 (2007), or Coorevits, Hild and Pelle, CMAME
// 186 (2000)); contact enters through u_h, whose strain the active set shapes. Its effectivity on
// a contact problem is measured against a reference solution (tests/pipeline/estimate.sh).
#include "mesh/mesh.hpp"

#include <Eigen/Core>

#include <array>
#include <vector>

namespace sig {

/// The recovered strain G eps_h, (e11, e22, 2 e12) at each vertex of each triangle (3 per
/// triangle, in the triangle's vertex order): the mean over the triangles of the same sub-domain
/// around that vertex, weighted by their areas.
std::vector<std::array<Eigen::Vector3d, 3>> recovered_strains(const Mesh& mesh,
                                                              const Eigen::VectorXd& u);

/// integral over a triangle of area `area` of |g|^2, g the linear field with vertex values
/// `g` (Voigt strains, engineering shear): exact, area / 12 (sum |g_i|^2 + |sum g_i|^2).
double linear_strain_square_integral(double area, const std::array<Eigen::Vector3d, 3>& g);

struct ErrorIndicators {
  std::vector<double> eta; ///< eta_T per triangle
  double estimate = 0;     ///< eta = (sum of eta_T^2)^(1/2), in the units of sig-error's error
};

/// eta_T and eta of the formula above for the displacement u (2 values per node).
ErrorIndicators recovery_indicators(const Mesh& mesh, const Eigen::VectorXd& u);

/// A march's indicators for one mesh adapted to the whole march (drivers/adapt.sh): eta of each
/// kept state, and per triangle the largest of its eta_T over the kept states, so that a
/// triangle is marked when its error is large at any kept time (the worst time of each place).
struct MarchIndicators {
  std::vector<double> eta;       ///< max over the states of eta_T(t_n), per triangle
  std::vector<double> estimates; ///< eta(t_n), per kept state
};

/// The indicators of `states` (displacements of 2 values per node, one per kept time level).
MarchIndicators worst_time_indicators(const Mesh& mesh, const std::vector<Eigen::VectorXd>& states);

} // namespace sig
