#include "integrator/emm.hpp"

#include "core/error.hpp"
#include "core/log.hpp"

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <array>
#include <vector>

namespace sig {
namespace {

/// m, the scalar mass of M = m (x) I_d (d dofs per node, interleaved); sig::Error if M is not of
/// that form.
Eigen::SparseMatrix<double> scalar_mass(const Eigen::SparseMatrix<double>& M, int d) {
  const Eigen::Index n = M.rows() / d;
  std::vector<Eigen::Triplet<double>> entries;
  for (Eigen::Index j = 0; j < M.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(M, j); it; ++it) {
      if (it.value() == 0.0) continue; // the P1 pattern stores the couplings of components as 0
      bool same = it.row() % d == j % d;
      // Each entry of the first component against its copies in the others.
      for (int c = 1; same && j % d == 0 && c < d; ++c)
        same = M.coeff(it.row() + c, j + c) == it.value();
      SIG_VERIFY(same, "EMM: the mass is not the same in every direction (entry ("
                           << it.row() + 1 << ", " << j + 1 << "))");
      if (j % d == 0) entries.emplace_back(it.row() / d, j / d, it.value());
    }
  Eigen::SparseMatrix<double> m(n, n);
  m.setFromTriplets(entries.begin(), entries.end());
  return m;
}

/// me = m0 + sum beta_ab Pi Sym_P(phi_a phi_b^T) Pi over the affine fields phi (the columns: 1,
/// x1 .. xd) and every product (second_moments), or over the products with the constant field
/// only (the mass and the centre), beta from the moments' conditions (header); empty if me is not
/// positive definite off Gamma3.
Eigen::SparseMatrix<double> project(const Eigen::SparseMatrix<double>& m,
                                    const std::vector<char>& removed, const Eigen::MatrixXd& phi,
                                    bool second_moments) {
  const Eigen::Index n = m.rows();
  std::vector<std::array<int, 2>> pairs; // (a, b), a <= b: the conditions and the unknowns
  const auto fields = static_cast<int>(phi.cols());
  for (int a = 0; a < fields; ++a)
    for (int b = a; b < fields; ++b)
      if (second_moments || a == 0) pairs.push_back({a, b});
  const auto np = static_cast<Eigen::Index>(pairs.size());
  Eigen::SparseMatrix<double> m0 = m;
  m0.makeCompressed();
  std::vector<Eigen::SparseMatrix<double>> S(pairs.size(), m0); // m's pattern, values below
  for (Eigen::Index j = 0; j < n; ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(m0, j); it; ++it) {
      const Eigen::Index i = it.row();
      const bool off = removed[static_cast<std::size_t>(i)] || removed[static_cast<std::size_t>(j)];
      if (off) it.valueRef() = 0.0;
      const auto slot = &it.valueRef() - m0.valuePtr();
      for (std::size_t p = 0; p < pairs.size(); ++p) {
        const int a = pairs[p][0], b = pairs[p][1];
        S[p].valuePtr()[slot] = off ? 0.0 : 0.5 * (phi(i, a) * phi(j, b) + phi(i, b) * phi(j, a));
      }
    }
  // G beta = the removed moments: row (c, d), column (a, b) = phi_c^T S_ab phi_d.
  Eigen::MatrixXd G(np, np);
  Eigen::VectorXd lost(np);
  for (Eigen::Index q = 0; q < np; ++q) {
    const auto& [c, d] = pairs[static_cast<std::size_t>(q)];
    lost[q] = phi.col(c).dot((m - m0) * phi.col(d));
    for (Eigen::Index p = 0; p < np; ++p)
      G(q, p) = phi.col(c).dot(S[static_cast<std::size_t>(p)] * phi.col(d));
  }
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(G);
  if (!lu.isInvertible()) return {};
  Eigen::VectorXd beta = lu.solve(lost);
  beta += lu.solve(lost - G * beta); // one refinement: the moments to rounding
  Eigen::SparseMatrix<double> me = m0;
  for (std::size_t p = 0; p < pairs.size(); ++p)
    me += beta[static_cast<Eigen::Index>(p)] * S[p];

  // Positive definite off Gamma3 (the Gamma3 block is zero by construction).
  std::vector<int> index(static_cast<std::size_t>(n), -1);
  int kept = 0;
  for (Eigen::Index i = 0; i < n; ++i)
    if (!removed[static_cast<std::size_t>(i)]) index[static_cast<std::size_t>(i)] = kept++;
  std::vector<Eigen::Triplet<double>> entries;
  for (Eigen::Index j = 0; j < n; ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(me, j); it; ++it) {
      const int r = index[static_cast<std::size_t>(it.row())],
                c = index[static_cast<std::size_t>(j)];
      if (r >= 0 && c >= 0) entries.emplace_back(r, c, it.value());
    }
  Eigen::SparseMatrix<double> block(kept, kept);
  block.setFromTriplets(entries.begin(), entries.end());
  const Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> cholesky(block);
  if (cholesky.info() != Eigen::Success) return {};
  return me;
}

} // namespace

Eigen::SparseMatrix<double> equivalent_mass_matrix(const Eigen::SparseMatrix<double>& M,
                                                   const Eigen::MatrixXd& positions,
                                                   const std::vector<int>& contact_nodes) {
  const auto nodes = static_cast<int>(positions.rows());
  const auto d = static_cast<int>(positions.cols());
  SIG_VERIFY(d == 2 || d == 3, "EMM: positions of " << d << " coordinates");
  SIG_VERIFY(M.rows() == d * nodes && M.cols() == M.rows(),
             "EMM: a " << M.rows() << " x " << M.cols() << " mass for " << nodes << " nodes in "
                       << d << "D");
  SIG_VERIFY(!contact_nodes.empty(), "EMM: no contact node (the EMM would be M)");
  std::vector<char> removed(static_cast<std::size_t>(nodes), 0);
  for (int i : contact_nodes) {
    SIG_VERIFY(i >= 0 && i < nodes,
               "EMM: contact node " << i + 1 << " is not in the mesh (" << nodes << " nodes)");
    SIG_VERIFY(!removed[static_cast<std::size_t>(i)],
               "EMM: contact node " << i + 1 << " is given twice");
    removed[static_cast<std::size_t>(i)] = 1;
  }
  Eigen::RowVectorXd centre = Eigen::RowVectorXd::Zero(d);
  for (int i = 0; i < nodes; ++i)
    centre += positions.row(i) / nodes;
  Eigen::MatrixXd phi(nodes, d + 1);
  for (int i = 0; i < nodes; ++i) {
    phi(i, 0) = 1.0;
    phi.row(i).tail(d) = positions.row(i) - centre;
  }
  const Eigen::SparseMatrix<double> m = scalar_mass(M, d);
  Eigen::SparseMatrix<double> me = project(m, removed, phi, true);
  if (me.nonZeros() == 0) {
    log_warning("EMM: keeping the moments of inertia too makes the mass indefinite; only the "
                "total mass and the centre of mass are kept");
    me = project(m, removed, phi, false);
    SIG_VERIFY(me.nonZeros() > 0, "EMM: with the inertia of the "
                                      << contact_nodes.size()
                                      << " contact nodes removed, no positive definite mass of "
                                         "the pattern keeps the total mass and the centre");
  }
  // Me = me (x) I_d, on M's interleaved dofs.
  std::vector<Eigen::Triplet<double>> entries;
  for (Eigen::Index j = 0; j < me.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(me, j); it; ++it)
      if (it.value() != 0.0)
        for (int c = 0; c < d; ++c)
          entries.emplace_back(d * it.row() + c, d * j + c, it.value());
  Eigen::SparseMatrix<double> Me(M.rows(), M.cols());
  Me.setFromTriplets(entries.begin(), entries.end());
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
