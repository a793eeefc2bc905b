#include "integrator/emm.hpp"

#include "core/error.hpp"
#include "integrator/elastodynamics.hpp"
#include "mesh/mesh.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <set>
#include <vector>

namespace sig {
namespace {

std::vector<std::vector<int>> node_neighbours(const Mesh& mesh) {
  std::vector<std::set<int>> sets(mesh.nodes.size());
  for (const auto& t : mesh.triangles)
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        if (a != b) sets[t[a]].insert(t[b]);
  std::vector<std::vector<int>> neighbours(sets.size());
  for (std::size_t i = 0; i < sets.size(); ++i)
    neighbours[i].assign(sets[i].begin(), sets[i].end());
  return neighbours;
}

// Rows 1, (x_j - x_i) / h, (y_j - y_i) / h over the receivers: the affine constraints on the
// weights, centred and scaled so that their conditioning depends on the shape of the receiver
// cloud only.
Eigen::MatrixXd affine_constraints(const Mesh& mesh, int node, const std::vector<int>& receivers) {
  const Eigen::Vector2d x = mesh.nodes[node];
  double h = 0.0;
  for (int j : receivers)
    h = std::max(h, (mesh.nodes[j] - x).norm());
  Eigen::MatrixXd A(3, static_cast<Eigen::Index>(receivers.size()));
  for (std::size_t c = 0; c < receivers.size(); ++c) {
    const Eigen::Vector2d d = (mesh.nodes[receivers[c]] - x) / h;
    A.col(static_cast<Eigen::Index>(c)) << 1.0, d.x(), d.y();
  }
  return A;
}

// True if the receivers span the plane affinely: A A^T is well conditioned.
bool spans_plane(const Eigen::MatrixXd& A) {
  if (A.cols() < 3) return false;
  const Eigen::Vector3d eig =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(A * A.transpose()).eigenvalues(); // ascending
  return eig(0) > 1e-6 * eig(2);
}

// The non-contact nodes of the smallest ring around `node` (1-ring, 2-ring, ...) that spans the
// plane, with their minimum-norm affine weights c = A^T (A A^T)^{-1} (1, 0, 0).
MassTransfer transfer_of(const Mesh& mesh, const std::vector<std::vector<int>>& neighbours,
                         const std::vector<char>& is_contact, int node,
                         const Eigen::Vector2d& normal) {
  MassTransfer transfer;
  transfer.node = node;
  transfer.normal = normal.normalized();
  std::vector<char> seen(mesh.nodes.size(), 0);
  seen[node] = 1;
  std::vector<int> front = {node};
  Eigen::MatrixXd A;
  while (!front.empty()) {
    std::vector<int> next;
    for (int i : front)
      for (int j : neighbours[i])
        if (!seen[j]) {
          seen[j] = 1;
          next.push_back(j);
          if (!is_contact[j]) transfer.receivers.push_back(j);
        }
    front = std::move(next);
    A = affine_constraints(mesh, node, transfer.receivers);
    if (spans_plane(A)) break;
  }
  SIG_VERIFY(spans_plane(A), "EMM: the non-contact nodes connected to contact node "
                                 << node + 1 << " do not span the plane ("
                                 << transfer.receivers.size() << " receivers)");
  // Minimum-norm solution by a complete orthogonal decomposition (no normal equations), with
  // one step of refinement: the moments are kept only as exactly as the weights are affine.
  const Eigen::Vector3d b(1.0, 0.0, 0.0);
  const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(A);
  Eigen::VectorXd c = cod.solve(b);
  c += cod.solve(b - A * c);
  transfer.weights.assign(c.data(), c.data() + c.size());
  return transfer;
}

} // namespace

std::vector<MassTransfer> mass_transfers(const Mesh& mesh, const ContactNormals& contact) {
  const int n = mesh.num_nodes();
  SIG_VERIFY(contact.nodes.size() == contact.normals.size(),
             "EMM: " << contact.nodes.size() << " contact nodes but " << contact.normals.size()
                     << " normals");
  std::vector<char> is_contact(mesh.nodes.size(), 0);
  for (std::size_t c = 0; c < contact.nodes.size(); ++c) {
    const int i = contact.nodes[c];
    SIG_VERIFY(i >= 0 && i < n,
               "EMM: contact node " << i + 1 << " is not in the mesh (" << n << " nodes)");
    SIG_VERIFY(!is_contact[i], "EMM: contact node " << i + 1 << " is given twice");
    SIG_VERIFY(contact.normals[c].norm() > 0, "EMM: zero normal at contact node " << i + 1);
    is_contact[i] = 1;
  }
  const auto neighbours = node_neighbours(mesh);
  std::vector<MassTransfer> transfers;
  transfers.reserve(contact.nodes.size());
  for (std::size_t c = 0; c < contact.nodes.size(); ++c)
    transfers.push_back(
        transfer_of(mesh, neighbours, is_contact, contact.nodes[c], contact.normals[c]));
  return transfers;
}

Eigen::SparseMatrix<double> emm_transfer_matrix(int num_nodes,
                                                const std::vector<MassTransfer>& transfers) {
  std::vector<char> is_contact(static_cast<std::size_t>(num_nodes), 0);
  std::vector<Eigen::Triplet<double>> entries;
  auto add_block = [&entries](int row_node, int col_node, const Eigen::Matrix2d& B) {
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b)
        if (B(a, b) != 0.0) entries.emplace_back(2 * row_node + a, 2 * col_node + b, B(a, b));
  };
  for (const MassTransfer& t : transfers) {
    SIG_VERIFY(t.node >= 0 && t.node < num_nodes,
               "EMM: contact node " << t.node + 1 << " out of range");
    is_contact[t.node] = 1;
    const Eigen::Vector2d& nu = t.normal;
    // I - nu nu^T written as tau tau^T: tau tau^T nu is then exactly zero in floating point.
    const Eigen::Vector2d tau(-nu.y(), nu.x());
    add_block(t.node, t.node, tau * tau.transpose());
    for (std::size_t r = 0; r < t.receivers.size(); ++r)
      add_block(t.node, t.receivers[r], t.weights[r] * nu * nu.transpose());
  }
  for (int i = 0; i < num_nodes; ++i)
    if (!is_contact[i]) add_block(i, i, Eigen::Matrix2d::Identity());
  Eigen::SparseMatrix<double> T(2 * num_nodes, 2 * num_nodes);
  T.setFromTriplets(entries.begin(), entries.end());
  return T;
}

Eigen::SparseMatrix<double> equivalent_mass_matrix(const Eigen::SparseMatrix<double>& M,
                                                   const Mesh& mesh,
                                                   const ContactNormals& contact) {
  SIG_VERIFY(M.rows() == 2 * mesh.num_nodes() && M.cols() == M.rows(),
             "EMM: a " << M.rows() << " x " << M.cols() << " mass for " << mesh.num_nodes()
                       << " nodes");
  const Eigen::SparseMatrix<double> T =
      emm_transfer_matrix(mesh.num_nodes(), mass_transfers(mesh, contact));
  const Eigen::SparseMatrix<double> TtMT = T.transpose() * (M * T);
  Eigen::SparseMatrix<double> Me = 0.5 * (TtMT + Eigen::SparseMatrix<double>(TtMT.transpose()));
  Me.prune(0.0);
  Me.makeCompressed();
  return Me;
}

MassMoments mass_moments(const Eigen::SparseMatrix<double>& M,
                         const std::vector<Eigen::Vector2d>& nodes) {
  const auto n = static_cast<Eigen::Index>(nodes.size());
  SIG_VERIFY(M.rows() == 2 * n && M.cols() == 2 * n,
             "mass moments: a " << M.rows() << " x " << M.cols() << " mass for " << n << " nodes");
  // The fields e1, e2, x1 e1, x2 e1, x1 e2, x2 e2 at the interleaved dofs.
  Eigen::MatrixXd Phi = Eigen::MatrixXd::Zero(2 * n, 6);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Vector2d& x = nodes[static_cast<std::size_t>(i)];
    Phi(2 * i, 0) = 1.0;
    Phi(2 * i + 1, 1) = 1.0;
    Phi(2 * i, 2) = x.x();
    Phi(2 * i, 3) = x.y();
    Phi(2 * i + 1, 4) = x.x();
    Phi(2 * i + 1, 5) = x.y();
  }
  MassMoments m;
  m.affine = Phi.transpose() * (M * Phi);
  const Eigen::Matrix<double, 6, 6>& G = m.affine;
  m.mass = 0.5 * (G(0, 0) + G(1, 1));
  m.centre = Eigen::Vector2d(G(0, 2) + G(1, 4), G(0, 3) + G(1, 5)) / (2.0 * m.mass);
  // rho(x) = (-(x2 - c2), x1 - c1) = c2 e1 - c1 e2 - x2 e1 + x1 e2.
  Eigen::Matrix<double, 6, 1> rho;
  rho << m.centre.y(), -m.centre.x(), 0.0, -1.0, 1.0, 0.0;
  m.polar = rho.dot(G * rho);
  return m;
}

} // namespace sig
