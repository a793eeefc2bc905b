#include "solver/nodal_frames.hpp"

#include "core/error.hpp"

#include <algorithm>

namespace sig {

std::vector<ContactFrame> frames_of(const std::vector<Eigen::Vector2d>& normals) {
  std::vector<ContactFrame> frames;
  frames.reserve(normals.size());
  for (const Eigen::Vector2d& n : normals)
    frames.emplace_back(nodal_frame(n));
  return frames;
}

FrameRotation::FrameRotation(const Eigen::SparseMatrix<double>& A, std::vector<int> first_dofs,
                             int d)
    : d_(d), first_(std::move(first_dofs)) {
  SIG_VERIFY(d_ == 2 || d_ == 3, "frame rotation: " << d_ << " dofs per node");
  SIG_VERIFY(A.isCompressed() && A.rows() == A.cols(), "frame rotation: A must be compressed");
  const int* outer = A.outerIndexPtr();
  const int* inner = A.innerIndexPtr();
  // Per contact node (dofs a, ..., a + d - 1): its d columns hold the same rows; its rows sit
  // one above the other in each neighbouring column j.
  row_slots_.resize(first_.size());
  for (std::size_t p = 0; p < first_.size(); ++p) {
    const int a = first_[p], last_dof = a + d_ - 1;
    SIG_VERIFY(a >= 0 && last_dof < A.cols(), "contact node " << p + 1 << ": dofs " << a + 1 << ".."
                                                              << last_dof + 1
                                                              << " outside the matrix");
    for (int c = 1; c < d_; ++c)
      SIG_VERIFY(outer[a + c + 1] - outer[a + c] == outer[a + 1] - outer[a],
                 "contact node " << p + 1 << " (dofs " << a + 1 << ".." << last_dof + 1
                                 << "): its dofs have different patterns");
    for (int k = outer[a]; k < outer[a + 1]; ++k) {
      const int j = inner[k];
      const int* first = inner + outer[j];
      const int* last = inner + outer[j + 1];
      const int* row = std::lower_bound(first, last, a);
      bool full = last - row >= d_;
      for (int c = 0; full && c < d_; ++c)
        full = row[c] == a + c;
      SIG_VERIFY(full, "contact node " << p + 1 << ": its node block in column " << j + 1
                                       << " is not full");
      row_slots_[p].push_back(static_cast<int>(row - inner));
    }
  }
}

void FrameRotation::rotate(Eigen::SparseMatrix<double>& A,
                           const std::vector<ContactFrame>& frames) const {
  double* v = A.valuePtr();
  const int* outer = A.outerIndexPtr();
  Eigen::Matrix<double, 1, Eigen::Dynamic, Eigen::RowMajor, 1, 3> row(d_);
  Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, 3, 1> column(d_);
  for (std::size_t p = 0; p < first_.size(); ++p) {
    const ContactFrame& R = frames[p];
    const int a = first_[p];
    const int length = outer[a + 1] - outer[a];
    for (int k = 0; k < length; ++k) { // A Q on the columns a, ..., a + d - 1
      for (int c = 0; c < d_; ++c)
        row[c] = v[outer[a + c] + k];
      row = row * R;
      for (int c = 0; c < d_; ++c)
        v[outer[a + c] + k] = row[c];
    }
    for (const int slot : row_slots_[p]) { // Q^T (A Q) on the rows a, ..., a + d - 1
      column = R.transpose() * Eigen::Map<const Eigen::VectorXd>(v + slot, d_);
      Eigen::Map<Eigen::VectorXd>(v + slot, d_) = column;
    }
  }
}

void FrameRotation::to_frames(Eigen::VectorXd& v, const std::vector<ContactFrame>& frames) const {
  for (std::size_t p = 0; p < first_.size(); ++p)
    v.segment(first_[p], d_) = frames[p].transpose() * v.segment(first_[p], d_);
}

void FrameRotation::from_frames(Eigen::VectorXd& v, const std::vector<ContactFrame>& frames) const {
  for (std::size_t p = 0; p < first_.size(); ++p)
    v.segment(first_[p], d_) = frames[p] * v.segment(first_[p], d_);
}

double FrameRotation::normal_row_times(const Eigen::SparseMatrix<double>& A, int p,
                                       const Eigen::VectorXd& w) const {
  const double* v = A.valuePtr();
  const int* inner = A.innerIndexPtr();
  const int* outer = A.outerIndexPtr();
  const int a = first_[p];
  double sum = 0;
  for (std::size_t k = 0; k < row_slots_[p].size(); ++k)
    sum += v[row_slots_[p][k] + d_ - 1] * w[inner[outer[a] + static_cast<int>(k)]];
  return sum;
}

} // namespace sig
