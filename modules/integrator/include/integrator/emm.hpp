#pragma once
// The Equivalent Mass Matrix (EMM, ch. 3.3.5, [80]): a mass Me under which the contact nodes of
// Gamma3 carry no inertia, "n'aient plus d'inertie" (l.5477), so that in particular
//     nu_i^T Me nu_j = 0   for all contact nodes i, j                          (3.54)
// while the total mass, the centre of mass and the moment of inertia of the body are those of
// the standard mass M (l.5488-5491). The thesis states these properties, not a construction.
//
// Ours is the constrained projection of ALGORITHMS.md 4.3 (D) ([choice] C16), on the scalar mass:
// a P1 mass (consistent or lumped) is M = m (x) I_d, m the nodes' scalar mass matrix, and
//   1. m0 = m with every row and column of the Gamma3 nodes zeroed (full removal: (3.54) in
//      every component);
//   2. the affine fields phi_1 = 1, phi_2 = x1 - c1, phi_3 = x2 - c2 (3D: and phi_4 = x3 - c3;
//      c the centre of the nodes, for conditioning);
//   3. me = m0 + sum_{a <= b} beta_ab Pi Sym_P(phi_a phi_b^T) Pi, Sym_P keeping m's nonzero
//      pattern and symmetrizing, Pi zeroing the Gamma3 rows and columns;
//   4. beta from the six conditions phi_a^T me phi_b = phi_a^T m phi_b, a <= b: the mass, its
//      first moments (the centre of mass) and its three second moments (the moments of inertia
//      about any point, the polar moment among them), a 6 x 6 linear system (3D: ten conditions,
//      10 x 10);
//   5. Me = me (x) I_d. me restricted to the other nodes must be positive definite (a Cholesky
//      checks it); otherwise the second moments are dropped (mass and centre only) with a
//      warning.
// D states its conditions with the three vector rigid modes r = e1, e2, e3 x x; every r_a^T M r_b
// is a combination of the scalar moments kept here, so Me satisfies D's six conditions and
// more, and, being me (x) I_2 with me symmetric, it leaves the angular momentum of the midpoint
// rule exact as M does (sum_ab me_ab v_a x v_b = 0); D's vector form would couple the components
// and lose that. The mass removed from Gamma3 is spread over m's pattern as a quadratic
// function of position; Me keeps M's pattern (a hyperelastic step's Newton matrix has it).
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <vector>

namespace sig {

/// Me of the construction above for a full-size consistent or lumped mass M (d dofs per node,
/// interleaved, M = m (x) I_d), the nodes' positions (the rows of `positions`, num_nodes x d,
/// d = 2 or 3: mesh/mesh.hpp's node_positions) and the 0-based nodes of Gamma3. In 3D the affine
/// fields are 1, x1, x2, x3 and the conditions ten (mass, three first moments, six second
/// moments). sig::Error for a node out of range or given twice, a mass that is not m (x) I_d, or
/// if even the mass and the centre alone cannot be kept with a positive definite Me.
Eigen::SparseMatrix<double> equivalent_mass_matrix(const Eigen::SparseMatrix<double>& M,
                                                   const Eigen::MatrixXd& positions,
                                                   const std::vector<int>& contact_nodes);

/// The inertia of a mass matrix seen by the affine velocity fields.
struct MassMoments {
  /// G = Phi^T M Phi over the six fields (e1, e2, x1 e1, x2 e1, x1 e2, x2 e2): every moment of
  /// order 0, 1 and 2 of the mass, component by component.
  Eigen::Matrix<double, 6, 6> affine;
  double mass = 0.0;      ///< (e1.M e1 + e2.M e2) / 2
  Eigen::Vector2d centre; ///< first moments over the mass, both components averaged
  double polar = 0.0;     ///< rho.M rho for the rotation rho(x) = (-(x2 - c2), x1 - c1)
};

MassMoments mass_moments(const Eigen::SparseMatrix<double>& M,
                         const std::vector<Eigen::Vector2d>& nodes);

} // namespace sig
