#include "integrator/dynamic_contact.hpp"

#include "core/error.hpp"
#include "integrator/elastodynamics.hpp"
#include "integrator/time_scheme.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <vector>

namespace sig {

Eigen::VectorXd ContactBoundary::penetration(const Eigen::VectorXd& x) const {
  return (x - geometric_gap).cwiseMax(0.0);
}

namespace {

/// `top` over `bottom` (the same columns).
Eigen::SparseMatrix<double> stacked(const Eigen::SparseMatrix<double>& top,
                                    const Eigen::SparseMatrix<double>& bottom) {
  SIG_VERIFY(top.cols() == bottom.cols(), "contact boundary: a tangential operator of "
                                              << bottom.cols() << " dofs, the normal one "
                                              << top.cols());
  std::vector<Eigen::Triplet<double>> entries;
  const auto add = [&entries](const Eigen::SparseMatrix<double>& block, Eigen::Index shift) {
    for (Eigen::Index j = 0; j < block.outerSize(); ++j)
      for (Eigen::SparseMatrix<double>::InnerIterator it(block, j); it; ++it)
        entries.emplace_back(it.row() + shift, it.col(), it.value());
  };
  add(top, 0);
  add(bottom, top.rows());
  Eigen::SparseMatrix<double> G(top.rows() + bottom.rows(), top.cols());
  G.setFromTriplets(entries.begin(), entries.end());
  return G;
}

} // namespace

CondensedContact condense_contact(const TimeScheme& scheme, const ContactBoundary& boundary) {
  CondensedContact c;
  c.G = boundary.setting.has_friction() ? stacked(boundary.B, boundary.tangential) : boundary.B;
  const Eigen::MatrixXd Gt = Eigen::MatrixXd(c.G.transpose());
  c.Z = scheme.solve_step_operator(Gt);
  Eigen::MatrixXd C = c.G * c.Z;
  C = 0.5 * (C + C.transpose()).eval();
  const Eigen::LLT<Eigen::MatrixXd> cholesky(2.0 * C);
  SIG_VERIFY(cholesky.info() == Eigen::Success, "the step operator condensed on the "
                                                    << boundary.size()
                                                    << " contact nodes is not positive definite "
                                                       "(a node in two contact elements?)");
  c.A = cholesky.solve(Eigen::MatrixXd::Identity(C.rows(), C.cols()));
  c.A = 0.5 * (c.A + c.A.transpose()).eval();
  return c;
}

} // namespace sig
