// The condensed linear bulk (condensed_bulk.hpp): one Cholesky factorization of the default step
// matrix, and each step a dense problem on the tail of the order that holds the contact zone.
#include "solver/condensed_bulk.hpp"

#include "core/error.hpp"
#include "solver/dense_cholesky.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <numeric>

namespace sig {

CondensedBulk::CondensedBulk(CondensedProblem problem, Eigen::VectorXd default_normal_stiffness,
                             const Eigen::VectorXd& start)
    : p_(std::move(problem)) {
  const int n = static_cast<int>(p_.f.size());
  const int m = contacts();
  SIG_VERIFY(p_.S.rows() == n && p_.S.cols() == n, "condensed bulk: S is " << p_.S.rows() << " x "
                                                                           << p_.S.cols() << " for "
                                                                           << n << " unknowns");
  if (m > 0 && !p_.tangential_dof.empty())
    tangents_ = static_cast<int>(p_.tangential_dof.size()) / m;
  SIG_VERIFY(p_.gap.size() == m && (p_.tangential_dof.empty() ||
                                    (static_cast<int>(p_.tangential_dof.size()) == tangents_ * m &&
                                     (tangents_ == 1 || tangents_ == 2))),
             "condensed bulk: one gap (and one or two tangential dofs, if any) per contact node");
  if (default_normal_stiffness.size() == 0) default_normal_stiffness = Eigen::VectorXd::Zero(m);
  SIG_VERIFY(default_normal_stiffness.size() == m,
             "condensed bulk: one default stiffness per contact node");
  SIG_VERIFY(p_.regularization >= 0, "condensed bulk: negative regularization");

  node_of_.assign(n, -1);
  tangent_of_.assign(n, -1);
  default_stiffness_ = Eigen::VectorXd::Zero(n);
  const auto claim = [&](int dof, int node) {
    SIG_VERIFY(dof >= 0 && dof < n && node_of_[dof] < 0, "condensed bulk: contact node "
                                                             << node + 1 << " has dof " << dof
                                                             << ", out of range or shared");
    node_of_[dof] = node;
  };
  for (int p = 0; p < m; ++p) {
    claim(p_.normal_dof[p], p);
    if (has_tangential())
      for (int k = 0; k < tangents_; ++k) {
        claim(p_.tangential_dof[tangents_ * p + k], p);
        tangent_of_[p_.tangential_dof[tangents_ * p + k]] = k;
      }
    default_stiffness_[p_.normal_dof[p]] = default_normal_stiffness[p];
  }

  // At first the nodes by decreasing gap (stable, so equal gaps keep the element order).
  std::vector<int> nodes(m);
  std::iota(nodes.begin(), nodes.end(), 0);
  std::stable_sort(nodes.begin(), nodes.end(), [&](int a, int b) { return p_.gap[a] > p_.gap[b]; });
  order_nodes(nodes);

  w_ = start.size() ? start : Eigen::VectorXd::Zero(n);
  SIG_VERIFY(w_.size() == n, "condensed bulk: start of size " << w_.size() << " for " << n);
  base_ = w_;
  step_ = Eigen::VectorXd::Zero(n);
  Sw_ = p_.S * w_;
  last_normal_force_ = Eigen::VectorXd::Zero(m);
}

void CondensedBulk::restart(Eigen::VectorXd f, Eigen::VectorXd gap, const Eigen::VectorXd& start) {
  SIG_VERIFY(f.size() == p_.f.size() && gap.size() == p_.gap.size() &&
                 (start.size() == 0 || start.size() == w_.size()),
             "condensed bulk: a restart with a load of "
                 << f.size() << ", " << gap.size() << " origins and a start of " << start.size()
                 << " for " << p_.f.size() << " unknowns, " << p_.gap.size() << " nodes");
  p_.f = std::move(f);
  p_.gap = std::move(gap);
  if (start.size() > 0) {
    w_ = start;
    Sw_.noalias() = p_.S.selfadjointView<Eigen::Lower>() * w_;
  }
  base_ = w_;
  step_.setZero();
}

void CondensedBulk::order_nodes(const std::vector<int>& nodes) {
  // Far first: the unknowns of no contact node, then the nodes in the given order, each node's
  // unknowns together.
  const int n = static_cast<int>(p_.f.size());
  order_.clear();
  for (int d = 0; d < n; ++d)
    if (node_of_[d] < 0) order_.push_back(d);
  node_start_.assign(contacts(), 0);
  for (int p : nodes) {
    node_start_[p] = static_cast<int>(order_.size());
    if (has_tangential())
      for (int k = 0; k < tangents_; ++k)
        order_.push_back(p_.tangential_dof[tangents_ * p + k]);
    order_.push_back(p_.normal_dof[p]);
  }
  position_.assign(n, 0);
  for (int k = 0; k < n; ++k)
    position_[order_[k]] = k;
  factorized_ = false;
  tail_start_ = -1;
}

void CondensedBulk::reorder(const std::vector<char>& contact_zone) {
  // The zone last, the other nodes before it from the most separated to the closest, so that a
  // node about to touch sits next to the zone and the tail grows by little; within the zone the
  // weakest normal force first, the node most likely to leave it, so that it shrinks from its
  // start.
  const Eigen::VectorXd q = penetration();
  std::vector<int> nodes(contacts());
  std::iota(nodes.begin(), nodes.end(), 0);
  std::stable_sort(nodes.begin(), nodes.end(), [&](int a, int b) {
    if (contact_zone[a] != contact_zone[b]) return contact_zone[b] != 0;
    return contact_zone[a] ? last_normal_force_[a] < last_normal_force_[b] : q[a] < q[b];
  });
  order_nodes(nodes);
  ++reorders_;
}

void CondensedBulk::factorize() {
  const int n = static_cast<int>(p_.f.size());
  B_.resize(n, n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      B_(i, j) = p_.S(order_[i], order_[j]);
  for (int k = 0; k < n; ++k)
    B_(k, k) += p_.regularization + default_stiffness_[order_[k]];
  L_ = B_;
  ++factorizations_;
  SIG_VERIFY(cholesky_in_place(L_),
             "the condensed step matrix is not positive definite (a rigid mode that neither the "
             "bulk nor the proximal term holds)");
  factorized_ = true;
}

void CondensedBulk::tail_schur(int start) {
  // H = L22 L22^T for the tail from `start`. From the previous tail (from s0), with the block C
  // of L between them (rows of the longer tail, columns of the shift): a tail longer by
  // d = s0 - start gains d leading rows and columns, [[A A^T, A C^T], [C A^T, H0 + C C^T]]
  // (A the d x d diagonal block of L); one shorter by d loses them, H0 minus C C^T. That costs
  // t^2 d, against t^3 / 3 (L22 L22^T) or t^2 (n - t) (B_tail - L21 L21^T) afresh.
  const int n = static_cast<int>(p_.f.size());
  const int tail = n - start;
  const int shift = tail_start_ - start; // > 0: longer
  const bool incremental = tail_start_ >= 0 && 4 * std::abs(shift) < tail;
  tail_start_ = start;
  if (tail >= blas_min_rows) {
    // The same products as rank-k updates of H's lower triangle (dsyrk): half the flops of
    // Eigen's general products, in OpenBLAS's kernels. The longer tail's blocks are one update by
    // the panel [A; C] of L's columns, H0 in the corner.
    if (incremental && shift > 0) {
      const int old_tail = tail - shift;
      Eigen::MatrixXd H = Eigen::MatrixXd::Zero(tail, tail);
      H.bottomRightCorner(old_tail, old_tail) = H_;
      Eigen::MatrixXd panel = L_.block(start, start, tail, shift);
      panel.topRows(shift).triangularView<Eigen::StrictlyUpper>().setZero();
      add_gram(H, 1.0, panel);
      H_ = std::move(H);
    } else if (incremental) {
      Eigen::MatrixXd H = H_.bottomRightCorner(tail, tail);
      add_gram(H, -1.0, L_.block(start, start + shift, tail, -shift));
      H_ = std::move(H);
    } else if (3 * start < tail) {
      H_ = B_.bottomRightCorner(tail, tail);
      add_gram(H_, -1.0, L_.bottomLeftCorner(tail, start));
    } else {
      H_ = triangular_gram(L_.bottomRightCorner(tail, tail));
    }
    return;
  }
  if (incremental && shift > 0) {
    const int old_tail = tail - shift;
    const Eigen::MatrixXd A = L_.block(start, start, shift, shift).triangularView<Eigen::Lower>();
    const auto C = L_.block(start + shift, start, old_tail, shift);
    Eigen::MatrixXd H(tail, tail);
    H.topLeftCorner(shift, shift) = A * A.transpose();
    H.bottomLeftCorner(old_tail, shift) = C * A.transpose();
    H.topRightCorner(shift, old_tail) = H.bottomLeftCorner(old_tail, shift).transpose();
    H.bottomRightCorner(old_tail, old_tail) = H_;
    H.bottomRightCorner(old_tail, old_tail).noalias() += C * C.transpose();
    H_ = std::move(H);
  } else if (incremental) {
    const auto C = L_.block(start, start + shift, tail, -shift);
    Eigen::MatrixXd H = H_.bottomRightCorner(tail, tail);
    H.noalias() -= C * C.transpose();
    H_ = std::move(H);
  } else if (3 * start < tail) {
    H_ = B_.bottomRightCorner(tail, tail);
    H_.noalias() -= L_.bottomLeftCorner(tail, start) * L_.bottomLeftCorner(tail, start).transpose();
  } else {
    const Eigen::MatrixXd L22 = L_.bottomRightCorner(tail, tail).triangularView<Eigen::Lower>();
    H_ = L22.triangularView<Eigen::Lower>() * L22.transpose();
  }
}

bool CondensedBulk::is_default(int node, const NodeConditions& c) const {
  DofCondition normal;
  normal.stiffness = default_stiffness_[p_.normal_dof[node]];
  return c.normal == normal &&
         (!has_tangential() || (c.tangential == DofCondition{} && c.tangential2 == DofCondition{} &&
                                c.tangential_12 == 0));
}

Eigen::VectorXd CondensedBulk::penetration() const {
  Eigen::VectorXd q(contacts());
  for (int p = 0; p < contacts(); ++p)
    q[p] = w_[p_.normal_dof[p]] - p_.gap[p];
  return q;
}

Eigen::VectorXd CondensedBulk::slip() const {
  if (!has_tangential()) return Eigen::VectorXd::Zero(contacts());
  Eigen::VectorXd q(p_.tangential_dof.size());
  for (std::size_t k = 0; k < p_.tangential_dof.size(); ++k)
    q[static_cast<Eigen::Index>(k)] = w_[p_.tangential_dof[k]];
  return q;
}

double CondensedBulk::equilibrium_residual(const Eigen::VectorXd& N,
                                           const Eigen::VectorXd& T) const {
  Eigen::VectorXd r = Sw_ - p_.f;
  for (int p = 0; p < contacts(); ++p)
    r[p_.normal_dof[p]] += N[p];
  if (has_tangential())
    for (std::size_t k = 0; k < p_.tangential_dof.size(); ++k)
      r[p_.tangential_dof[k]] += T[static_cast<Eigen::Index>(k)];
  return r.norm();
}

double CondensedBulk::force_scale() const {
  return std::max(p_.f.norm(), 1e-300);
}

Eigen::VectorXd CondensedBulk::contact_stiffness() const {
  Eigen::VectorXd k(contacts());
  for (int p = 0; p < contacts(); ++p)
    k[p] = p_.S(p_.normal_dof[p], p_.normal_dof[p]);
  return k;
}

StepSolution CondensedBulk::solve(const std::vector<NodeConditions>& conditions,
                                  const Eigen::VectorXd&) {
  const int n = static_cast<int>(p_.f.size());
  const int m = contacts();
  SIG_VERIFY(static_cast<int>(conditions.size()) == m, "condensed bulk: one condition per node");

  // 1. The tail: from the first position of a node with non-default conditions. When it holds
  //    many more unknowns than those nodes (a contact zone away from the smallest gaps, or a
  //    wide first active set), its dense problem would cost more than a new factorization with
  //    the zone last: reorder.
  std::vector<char> zone(m, 0);
  int zone_unknowns = 0;
  for (int p = 0; p < m; ++p)
    if (!is_default(p, conditions[p])) {
      zone[p] = 1;
      zone_unknowns += has_tangential() ? 1 + tangents_ : 1;
    }
  const auto tail_start = [&] {
    int start = n;
    for (int p = 0; p < m; ++p)
      if (zone[p]) start = std::min(start, node_start_[p]);
    return start;
  };
  int start = tail_start();
  const double t = n - start, t_zone = zone_unknowns, size = n;
  if (t > 1.5 * t_zone + 32 && 4 * t * t * t > size * size * size) {
    reorder(zone);
    start = tail_start();
  }
  if (!factorized_) factorize();
  const int tail = n - start;
  if (tail > 0 && start != tail_start_) tail_schur(start);

  // 2. The step in the new iterate z = w + dw, not in dw: its right side f + (eps + D0) w has no
  //    cancellation (S w - f would carry round-off of ||S|| ||w|| into every reaction, and the
  //    increment test would never see a repeated step settle). Condensed onto the tail:
  //    y = L11^-1 b_far, c = b_tail - L21 y.
  Eigen::VectorXd b(n);
  for (int k = 0; k < n; ++k) {
    const int d = order_[k];
    b[k] = p_.f[d] + (p_.regularization + default_stiffness_[d]) * w_[d];
  }
  const auto L11 = L_.topLeftCorner(start, start).triangularView<Eigen::Lower>();
  const Eigen::VectorXd y = L11.solve(b.head(start));
  const Eigen::VectorXd c = b.tail(tail) - L_.bottomLeftCorner(tail, start) * y;

  // 3. The tail problem: per tail unknown i, (H z)_i - D0_i (z_i - w_i) + F_i = c_i, F_i the
  //    contact force of its condition, F = force + k (z - w) (+ coupling N); imposed unknowns
  //    z = w + value move to the right side, Coulomb's coupling brings in the normal row of the
  //    node (its reaction) or its spring.
  const auto condition = [&](int i) -> const DofCondition& {
    const int dof = order_[start + i];
    const NodeConditions& node = conditions[node_of_[dof]];
    return dof == p_.normal_dof[node_of_[dof]] ? node.normal : node.tangent(tangent_of_[dof]);
  };
  const auto k0 = [&](int i) { return default_stiffness_[order_[start + i]]; };
  const auto now = [&](int i) { return w_[order_[start + i]]; };
  const auto normal_of = [&](int i) {
    return position_[p_.normal_dof[node_of_[order_[start + i]]]] - start;
  };
  // 3D: the other tangent of tangential unknown i, and the stiffness between the two.
  const auto other_tangent_of = [&](int i) {
    const int dof = order_[start + i];
    return position_[p_.tangential_dof[tangents_ * node_of_[dof] + 1 - tangent_of_[dof]]] - start;
  };
  const auto tangential_12 = [&](int i) {
    const int dof = order_[start + i];
    return tangent_of_[dof] < 0 ? 0.0 : conditions[node_of_[dof]].tangential_12;
  };
  Eigen::VectorXd z_tail = Eigen::VectorXd::Zero(tail);
  std::vector<int> unknown(tail, -1), free;
  for (int i = 0; i < tail; ++i)
    if (condition(i).imposed)
      z_tail[i] = now(i) + condition(i).value;
    else {
      unknown[i] = static_cast<int>(free.size());
      free.push_back(i);
    }
  const int nu = static_cast<int>(free.size());
  // H is exactly symmetric for a BLAS-sized tail (tail_schur): its row i read as its column,
  // contiguous, as A's rows are.
  const bool large = tail >= blas_min_rows;
  const auto H_row = [&](int i) -> Eigen::RowVectorXd {
    return large ? Eigen::RowVectorXd(H_.col(i).transpose()) : Eigen::RowVectorXd(H_.row(i));
  };
  RowMatrixXd A(nu, nu);
  Eigen::VectorXd rhs(nu);
  bool coupled = false;
  Eigen::RowVectorXd row(tail);
  for (int a = 0; a < nu; ++a) {
    const int i = free[a];
    const DofCondition& ci = condition(i);
    row = H_row(i);
    row[i] += ci.stiffness - k0(i);
    double right = c[i] - ci.force + (ci.stiffness - k0(i)) * now(i);
    if (const double k12 = tangential_12(i); k12 != 0) {
      // The slip branch's block in 3D: symmetric, but not definite on a branch held where the
      // node sticks (|z| < s), so factorized as the coupled systems are.
      coupled = true;
      row[other_tangent_of(i)] += k12;
      right += k12 * now(other_tangent_of(i));
    }
    if (tangents_ == 2 && ci.stiffness < 0) coupled = true; // that block, diagonal
    if (ci.cross != 0) {
      coupled = true;
      row[normal_of(i)] += ci.cross;
      right += ci.cross * now(normal_of(i));
    }
    if (ci.coupling != 0) {
      coupled = true;
      const int nrow = normal_of(i);
      const DofCondition& cn = condition(nrow);
      if (cn.imposed) { // N = c_n - (H z)_n + D0_n (z_n - w_n), the reaction
        row -= ci.coupling * H_row(nrow);
        right -= ci.coupling * (c[nrow] + k0(nrow) * cn.value);
      } else { // N = force + k (z_n - w_n)
        row[nrow] += ci.coupling * cn.stiffness;
        right -= ci.coupling * (cn.force - cn.stiffness * now(nrow));
      }
    }
    for (int j = 0; j < tail; ++j)
      if (unknown[j] < 0)
        right -= row[j] * z_tail[j];
      else
        A(a, unknown[j]) = row[j];
    rhs[a] = right;
  }
  if (nu > 0) {
    // The factorization of the last A serves again when A repeats: the iteration that confirms
    // a Newton's converged branches, and every step of a march whose statuses hold (the laws'
    // springs and couplings depend on the branches only, not on the iterate).
    const bool repeated =
        A.rows() == tail_matrix_.rows() && coupled == tail_coupled_ && A == tail_matrix_;
    if (!repeated) {
      tail_matrix_ = std::move(A);
      tail_coupled_ = coupled;
      if (!coupled) {
        tail_llt_.compute(tail_matrix_);
        SIG_VERIFY(tail_llt_.info() == Eigen::Success,
                   "the contact step matrix is not positive definite (" << nu << " free of " << tail
                                                                        << " tail unknowns)");
      } else {
        tail_lu_.compute(tail_matrix_, large);
      }
      ++tail_factorizations_;
    }
    const Eigen::VectorXd x = coupled ? tail_lu_.solve(rhs) : Eigen::VectorXd(tail_llt_.solve(rhs));
    SIG_VERIFY(x.allFinite(), "the contact step matrix is singular");
    for (int a = 0; a < nu; ++a)
      z_tail[free[a]] = x[a];
  }

  // 4. Back to the far unknowns, z_far = L11^-T (y - L21^T z_tail), and the contact forces:
  //    F = c - H z + D0 (z - w) on the tail, the default spring D0 (z - w) elsewhere.
  Eigen::VectorXd z(n);
  z.tail(tail) = z_tail;
  z.head(start) = L11.transpose().solve(y - L_.bottomLeftCorner(tail, start).transpose() * z_tail);
  const Eigen::VectorXd F =
      tail > 0 ? Eigen::VectorXd(c - H_ * z_tail) : Eigen::VectorXd(Eigen::VectorXd::Zero(0));
  for (int k = 0; k < n; ++k)
    step_[order_[k]] = z[k] - w_[order_[k]];

  StepSolution s;
  s.normal_increment.resize(m);
  s.normal_force.resize(m);
  s.tangential_force = Eigen::VectorXd::Zero(has_tangential() ? tangents_ * m : m);
  const auto force_at = [&](int dof) {
    const int k = position_[dof];
    const double spring = default_stiffness_[dof] * step_[dof];
    return k >= start ? F[k - start] + spring : spring;
  };
  for (int p = 0; p < m; ++p) {
    s.normal_increment[p] = step_[p_.normal_dof[p]];
    s.normal_force[p] = force_at(p_.normal_dof[p]);
    if (has_tangential())
      for (int k = 0; k < tangents_; ++k)
        s.tangential_force[tangents_ * p + k] = force_at(p_.tangential_dof[tangents_ * p + k]);
  }
  s.proximal_force = p_.regularization * step_.norm();
  base_ = w_;
  last_normal_force_ = s.normal_force;
  // S w along the step, for the residuals of a line search: two symmetric products here (S w
  // afresh, so that round-off does not build up over the iterations, and S dw), then O(n) a
  // trial. A BLAS-sized S is read once for both (dsymm), its traffic their cost.
  if (n >= blas_min_rows) {
    Eigen::MatrixXd X(n, 2);
    X << w_, step_;
    const Eigen::MatrixXd Y = symmetric_product(p_.S, X);
    Sw_ = Y.col(0);
    S_step_ = Y.col(1);
  } else {
    Sw_.noalias() = p_.S.selfadjointView<Eigen::Lower>() * w_;
    S_step_.noalias() = p_.S.selfadjointView<Eigen::Lower>() * step_;
  }
  Sw_base_ = Sw_;
  return s;
}

bool CondensedBulk::move(double alpha) {
  w_ = base_ + alpha * step_;
  Sw_ = Sw_base_ + alpha * S_step_;
  return true;
}

void CondensedBulk::keep() {
  kept_ = w_;
  kept_Sw_ = Sw_;
}

void CondensedBulk::restore() {
  w_ = kept_;
  Sw_ = kept_Sw_;
}

void CondensedBulk::checkpoint() {
  checkpoint_w_ = w_;
  checkpoint_Sw_ = Sw_;
}

void CondensedBulk::rewind() {
  SIG_VERIFY(checkpoint_w_.size() == w_.size(), "condensed bulk: rewind without a checkpoint");
  w_ = checkpoint_w_;
  Sw_ = checkpoint_Sw_;
}

} // namespace sig
