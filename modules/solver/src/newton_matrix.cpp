// The Newton matrix of the large-deformation contact solve (newton_matrix.hpp).
#include "solver/newton_matrix.hpp"

#include "core/error.hpp"
#include "solver/linear_solver.hpp"

#include <algorithm>

namespace sig {

NewtonMatrix::NewtonMatrix(Eigen::SparseMatrix<double> pattern, const std::vector<char>& dirichlet,
                           const std::vector<int>& contact_nodes, int d)
    : full_(std::move(pattern)), d_(d), nodes_(contact_nodes) {
  SIG_VERIFY(d == 2 || d == 3, "Newton matrix: " << d << " dofs a node");
  SIG_VERIFY(full_.isCompressed() && full_.rows() == full_.cols(),
             "the Newton pattern is not a compressed square matrix");
  full_.coeffs().setZero();
  const int n = static_cast<int>(full_.cols());
  const int* outer = full_.outerIndexPtr();
  const int* inner = full_.innerIndexPtr();
  free_index_.assign(n, -1);
  for (int i = 0; i < n; ++i)
    if (!dirichlet[i]) {
      free_index_[i] = static_cast<int>(free_dofs_.size());
      free_dofs_.push_back(i);
    }
  // The reduced pattern: the free rows of the free columns, in order (so still sorted).
  const int free = static_cast<int>(free_dofs_.size());
  diagonal_.assign(n, -1);
  std::vector<int> reduced_outer(free + 1, 0), reduced_inner;
  for (int j = 0; j < n; ++j)
    for (int k = outer[j]; k < outer[j + 1]; ++k) {
      if (inner[k] == j) diagonal_[j] = k;
      if (free_index_[j] < 0 || free_index_[inner[k]] < 0) continue;
      source_.push_back(k);
      reduced_inner.push_back(free_index_[inner[k]]);
      reduced_outer[free_index_[j] + 1] = static_cast<int>(reduced_inner.size());
    }
  for (int r = 0; r < free; ++r)
    reduced_outer[r + 1] = std::max(reduced_outer[r + 1], reduced_outer[r]);
  reduced_.resize(free, free);
  reduced_.resizeNonZeros(static_cast<Eigen::Index>(reduced_inner.size()));
  std::copy(reduced_outer.begin(), reduced_outer.end(), reduced_.outerIndexPtr());
  std::copy(reduced_inner.begin(), reduced_inner.end(), reduced_.innerIndexPtr());
  std::fill(reduced_.valuePtr(), reduced_.valuePtr() + reduced_inner.size(), 0.0);
  moved_ = Eigen::VectorXd::Zero(n);

  std::vector<int> first_dofs(nodes_.size());
  for (std::size_t p = 0; p < nodes_.size(); ++p)
    first_dofs[p] = d * nodes_[p];
  frames_ = std::make_unique<FrameRotation>(full_, std::move(first_dofs), d);
}

void NewtonMatrix::take_tangent(Eigen::SparseMatrix<double>& K) {
  SIG_VERIFY(K.isCompressed() && K.rows() == full_.rows() && K.nonZeros() == full_.nonZeros() &&
                 std::equal(K.outerIndexPtr(), K.outerIndexPtr() + K.outerSize() + 1,
                            full_.outerIndexPtr()),
             "tangent is not on the Newton pattern");
  full_.swap(K);
}

void NewtonMatrix::add_node_block(int p, const Eigen::Ref<const Eigen::MatrixXd>& block) {
  SIG_VERIFY(block.rows() == d_ && block.cols() == d_, "node block of " << block.rows() << " x "
                                                                        << block.cols() << " for "
                                                                        << d_ << " dofs a node");
  const int a = d_ * nodes_[p];
  for (int j = 0; j < d_; ++j)
    for (int i = 0; i < d_; ++i)
      if (block(i, j) != 0.0) value(a + i, a + j) += block(i, j);
}

void NewtonMatrix::rotate(const std::vector<Eigen::Vector2d>& normals) {
  frames_->rotate(full_, normals);
}

void NewtonMatrix::rotate(const std::vector<ContactFrame>& frames) {
  frames_->rotate(full_, frames);
}

Eigen::VectorXd NewtonMatrix::solve(const Eigen::VectorXd& r0,
                                    const std::vector<std::pair<int, double>>& imposed,
                                    LinearSolver& solver) {
  const int n = static_cast<int>(full_.rows());
  const double* v = full_.valuePtr();
  const int* outer = full_.outerIndexPtr();
  const int* inner = full_.innerIndexPtr();
  moved_.setZero(); // A(:, imposed) * imposed values
  for (const auto& [dof, value] : imposed)
    for (int k = outer[dof]; k < outer[dof + 1]; ++k)
      moved_[inner[k]] += v[k] * value;
  // A held row keeps its diagonal d (the scale of its neighbours' rows); d = 0, which a stable
  // tangent never has on a boundary node, would be singular, so it becomes 1.
  const auto held_diagonal = [&](int dof) {
    const double d = v[diagonal_[dof]];
    return d != 0.0 ? d : 1.0;
  };
  // The free block in one gather, then the few held rows and columns decoupled: a pass that
  // tested every entry for a held row or column cost more than the gather itself.
  double* reduced = reduced_.valuePtr();
  for (std::size_t r = 0; r < source_.size(); ++r)
    reduced[r] = v[source_[r]];
  const int* reduced_outer = reduced_.outerIndexPtr();
  const int* reduced_inner = reduced_.innerIndexPtr();
  for (const auto& [dof, value] : imposed) {
    const int c = free_index_[dof];
    if (c < 0) continue; // a Dirichlet dof: not in the reduced matrix
    for (int k = reduced_outer[c]; k < reduced_outer[c + 1]; ++k) {
      const int row = reduced_inner[k];
      if (row == c) {
        reduced[k] = held_diagonal(dof);
        continue;
      }
      reduced[k] = 0.0;
      // The mirror entry (c, row): the pattern is structurally symmetric.
      const int* end = reduced_inner + reduced_outer[row + 1];
      const int* at = std::lower_bound(reduced_inner + reduced_outer[row], end, c);
      SIG_ASSERT(at != end && *at == c, "the Newton pattern is not structurally symmetric");
      reduced[at - reduced_inner] = 0.0;
    }
  }
  Eigen::VectorXd rhs(static_cast<Eigen::Index>(free_dofs_.size()));
  for (std::size_t r = 0; r < free_dofs_.size(); ++r)
    rhs[static_cast<Eigen::Index>(r)] = -r0[free_dofs_[r]] - moved_[free_dofs_[r]];
  for (const auto& [dof, value] : imposed)
    if (free_index_[dof] >= 0) rhs[free_index_[dof]] = held_diagonal(dof) * value;

  solver.factorize(reduced_);
  const Eigen::VectorXd dw_free = solver.solve(rhs);
  Eigen::VectorXd dw(n);
  for (std::size_t r = 0; r < free_dofs_.size(); ++r)
    dw[free_dofs_[r]] = dw_free[static_cast<Eigen::Index>(r)];
  for (const auto& [dof, value] : imposed)
    dw[dof] = value; // exact, not value up to the round-off of the decoupled row
  return dw;
}

double NewtonMatrix::normal_row_times(int p, const Eigen::VectorXd& dw) const {
  return frames_->normal_row_times(full_, p, dw);
}

int NewtonMatrix::slot(int row, int column) const {
  const int* inner = full_.innerIndexPtr();
  const int* outer = full_.outerIndexPtr();
  const int* at = std::lower_bound(inner + outer[column], inner + outer[column + 1], row);
  return at != inner + outer[column + 1] && *at == row ? static_cast<int>(at - inner) : -1;
}

double& NewtonMatrix::value(int row, int column) {
  const int k = slot(row, column);
  SIG_VERIFY(k >= 0,
             "entry (" << row + 1 << ", " << column + 1 << ") is not on the Newton pattern");
  return full_.valuePtr()[k];
}

void NewtonMatrix::add_row(int target, int source, double factor) {
  // The pattern is structurally symmetric: the columns of row `source` are the rows of column
  // `source`, and a node's two rows have the same columns.
  const int* inner = full_.innerIndexPtr();
  const int* outer = full_.outerIndexPtr();
  double* v = full_.valuePtr();
  for (int k = outer[source]; k < outer[source + 1]; ++k) {
    const int column = inner[k];
    const int from = slot(source, column), to = slot(target, column);
    SIG_VERIFY(from >= 0 && to >= 0, "rows " << source + 1 << " and " << target + 1
                                             << " do not share column " << column + 1);
    v[to] += factor * v[from];
  }
}

double NewtonMatrix::row_times(int dof, const Eigen::VectorXd& dw) const {
  const int* inner = full_.innerIndexPtr();
  const int* outer = full_.outerIndexPtr();
  const double* v = full_.valuePtr();
  double sum = 0;
  for (int k = outer[dof]; k < outer[dof + 1]; ++k) {
    const int column = inner[k];
    sum += v[slot(dof, column)] * dw[column];
  }
  return sum;
}

} // namespace sig
