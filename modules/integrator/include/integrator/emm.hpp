#pragma once
// The Equivalent Mass Matrix (EMM, ch. 3.3.5, [80]): a mass Me under which the contact nodes of
// Gamma3 carry no normal inertia,
//     nu_i^T Me nu_j = 0   for all contact nodes i, j                          (3.54)
// (nu_i the unit normal at node i, placed at the node's two dofs), while the total mass, the
// centre of mass and the moments of inertia of the body are those of the standard mass M.
//
// The thesis states these properties, not a construction. Ours is a kinematic substitution:
// the normal velocity of a contact node is no longer its own but the one extrapolated from
// nearby non-contact nodes ("receivers" R_i) by affine weights,
//     nu_i . v_i  ->  nu_i . sum_{j in R_i} c_ij v_j,  sum_j c_ij = 1,  sum_j c_ij x_j = x_i,
// which is the linear map T = I - sum_i nu_i nu_i^T [at (i, i)] + sum_{i, j} c_ij nu_i nu_i^T
// [at (i, j)], and
//     Me = T^T M T.
// Then (a) Me nu_i = 0, because T nu_i = 0 (the (i, i) block of T is tau_i tau_i^T, tau_i the
// unit tangent, and no receiver is a contact node): exactly for an axis normal such as the
// plane foundation's (0, 1), to rounding for others; (b) Me is symmetric and positive
// semidefinite; (c) T reproduces every field affine in x (v(x) = a + B x, since the weights are
// affine), so for all such fields phi, psi: phi.Me psi = phi.M psi. The affine fields hold the
// rigid motions and the fields x_a e_b, so the zeroth, first and second moments of the mass
// (total mass, centre of mass, second moments and polar moment of inertia) are kept exactly.
// The mass removed from the contact nodes is thus redistributed onto their receivers (with
// couplings between receivers of the same node: the lumped mass becomes non-diagonal there).
// The receivers of a node are its non-contact neighbours in the mesh (the ring grows until
// they span the plane); the weights are the minimum-norm affine ones, c_i = A^+ (1, x_i, y_i).
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <vector>

namespace sig {

struct ContactNormals;
struct Mesh;

/// The affine extrapolation of one contact node from its receivers.
struct MassTransfer {
  int node = 0;
  Eigen::Vector2d normal; ///< unit
  std::vector<int> receivers;
  std::vector<double> weights; ///< sum 1, sum weights x_receiver = x_node
};

/// The transfer of every contact node; sig::Error for a node out of range, a repeated node, a
/// zero normal, or a node whose receivers cannot span the plane (the mesh has too few
/// non-contact nodes).
std::vector<MassTransfer> mass_transfers(const Mesh& mesh, const ContactNormals& contact);

/// T of the construction above, 2 n x 2 n (interleaved dofs, dof = 2 node + component).
Eigen::SparseMatrix<double> emm_transfer_matrix(int num_nodes,
                                                const std::vector<MassTransfer>& transfers);

/// Me = T^T M T, symmetrized (exactly symmetric in floating point), for a consistent or lumped
/// (diagonal) full-size mass M.
Eigen::SparseMatrix<double> equivalent_mass_matrix(const Eigen::SparseMatrix<double>& M,
                                                   const Mesh& mesh, const ContactNormals& contact);

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
