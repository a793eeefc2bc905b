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

namespace {

// The rotations with the node block's size D known at compile time, in scalar loops: the finite-
// strain Newton rotates its tangent every iteration, and small dynamic Eigen products cost about
// 20 times these (measured on 200 2D nodes).
template <int D>
void rotate_blocks(double* v, const int* outer, const std::vector<int>& first,
                   const std::vector<std::vector<int>>& row_slots,
                   const std::vector<ContactFrame>& frames) {
  for (std::size_t p = 0; p < first.size(); ++p) {
    const Eigen::Matrix<double, D, D> R = frames[p];
    const int a = first[p];
    const int length = outer[a + 1] - outer[a];
    double in[D], out[D];
    for (int k = 0; k < length; ++k) { // A Q on the columns a, ..., a + D - 1
      for (int c = 0; c < D; ++c)
        in[c] = v[outer[a + c] + k];
      for (int j = 0; j < D; ++j) {
        out[j] = in[0] * R(0, j);
        for (int c = 1; c < D; ++c)
          out[j] += in[c] * R(c, j);
      }
      for (int c = 0; c < D; ++c)
        v[outer[a + c] + k] = out[c];
    }
    for (const int slot : row_slots[p]) { // Q^T (A Q) on the rows a, ..., a + D - 1
      for (int c = 0; c < D; ++c)
        in[c] = v[slot + c];
      for (int j = 0; j < D; ++j) {
        out[j] = R(0, j) * in[0];
        for (int c = 1; c < D; ++c)
          out[j] += R(c, j) * in[c];
      }
      for (int c = 0; c < D; ++c)
        v[slot + c] = out[c];
    }
  }
}

template <int D, bool Transposed>
void rotate_vector(Eigen::VectorXd& v, const std::vector<int>& first,
                   const std::vector<ContactFrame>& frames) {
  for (std::size_t p = 0; p < first.size(); ++p) {
    const Eigen::Matrix<double, D, D> R = frames[p];
    const Eigen::Matrix<double, D, 1> x = v.segment<D>(first[p]);
    if constexpr (Transposed)
      v.segment<D>(first[p]) = R.transpose() * x;
    else
      v.segment<D>(first[p]) = R * x;
  }
}

} // namespace

void FrameRotation::rotate(Eigen::SparseMatrix<double>& A,
                           const std::vector<ContactFrame>& frames) const {
  if (d_ == 2)
    rotate_blocks<2>(A.valuePtr(), A.outerIndexPtr(), first_, row_slots_, frames);
  else
    rotate_blocks<3>(A.valuePtr(), A.outerIndexPtr(), first_, row_slots_, frames);
}

void FrameRotation::to_frames(Eigen::VectorXd& v, const std::vector<ContactFrame>& frames) const {
  if (d_ == 2)
    rotate_vector<2, true>(v, first_, frames);
  else
    rotate_vector<3, true>(v, first_, frames);
}

void FrameRotation::from_frames(Eigen::VectorXd& v, const std::vector<ContactFrame>& frames) const {
  if (d_ == 2)
    rotate_vector<2, false>(v, first_, frames);
  else
    rotate_vector<3, false>(v, first_, frames);
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
