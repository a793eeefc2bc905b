#include "integrator/dynamic_contact.hpp"

#include "core/error.hpp"
#include "integrator/elastodynamics.hpp"
#include "integrator/time_scheme.hpp"
#include "solver/contact_condensation.hpp"

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

CondensedContact::CondensedContact(const TimeScheme& scheme, const ContactBoundary& boundary) {
  const int p = boundary.size();
  SIG_VERIFY(std::ssize(boundary.first_dof) == p && std::ssize(boundary.frame) == p,
             "contact boundary: " << boundary.first_dof.size() << " first dofs and "
                                  << boundary.frame.size() << " frames for " << p << " nodes");
  const bool friction = boundary.setting.has_friction();
  G_ = friction ? stacked(boundary.B, boundary.tangential) : boundary.B;
  // S is positive definite (the mass holds every rigid motion): CHOLMOD factorizes it whole.
  condensation_ = std::make_unique<ContactCondensation>(
      scheme.step_operator(), boundary.first_dof, boundary.frame, friction, scheme.linear_solver(),
      true, scheme.rank_rows());
  // G's row of node i's normal is i, of its slips p + (d - 1) i + k: where the condensation
  // keeps them.
  position_ = condensation_->normal_unknowns();
  const std::vector<int>& slips = condensation_->tangential_unknowns();
  position_.insert(position_.end(), slips.begin(), slips.end());
  const auto m = std::ssize(position_);
  SIG_VERIFY(m == G_.rows(), "contact boundary: " << G_.rows() << " components for " << m
                                                  << " unknowns of the condensation");
  const Eigen::MatrixXd& condensed = condensation_->schur();
  Eigen::MatrixXd Sc(m, m);
  for (Eigen::Index a = 0; a < m; ++a)
    for (Eigen::Index b = 0; b < m; ++b)
      Sc(a, b) = condensed(position_[a], position_[b]);
  Sc = 0.5 * (Sc + Sc.transpose()).eval();
  schur_.compute(Sc);
  SIG_VERIFY(schur_.info() == Eigen::Success, "the step operator condensed on the "
                                                  << p
                                                  << " contact nodes is not positive definite");
  A_ = 0.5 * Sc;
}

CondensedContact::~CondensedContact() = default;
CondensedContact::CondensedContact(CondensedContact&&) noexcept = default;
CondensedContact& CondensedContact::operator=(CondensedContact&&) noexcept = default;

Eigen::VectorXd CondensedContact::condense(const Eigen::VectorXd& b) {
  const Eigen::VectorXd condensed = condensation_->condense(b);
  Eigen::VectorXd g(std::ssize(position_));
  for (Eigen::Index a = 0; a < g.size(); ++a)
    g[a] = condensed[position_[a]];
  return g;
}

Eigen::VectorXd CondensedContact::increment(const Eigen::VectorXd& w) {
  Eigen::VectorXd unknowns(w.size());
  for (Eigen::Index a = 0; a < w.size(); ++a)
    unknowns[position_[a]] = w[a];
  return condensation_->expand(unknowns);
}

std::string CondensedContact::ordering() const {
  return condensation_->ordering();
}

} // namespace sig
