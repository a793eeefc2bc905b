#include "solver/nodal_frames.hpp"

#include "core/error.hpp"

#include <algorithm>

namespace sig {

FrameRotation::FrameRotation(const Eigen::SparseMatrix<double>& A, std::vector<int> first_dofs)
    : first_(std::move(first_dofs)) {
  SIG_VERIFY(A.isCompressed() && A.rows() == A.cols(), "frame rotation: A must be compressed");
  const int* outer = A.outerIndexPtr();
  const int* inner = A.innerIndexPtr();
  // Per contact node (dofs a, b = a + 1): its two columns hold the same rows; row a sits just
  // above row b in each neighbouring column j.
  row_slots_.resize(first_.size());
  for (std::size_t p = 0; p < first_.size(); ++p) {
    const int a = first_[p], b = a + 1;
    SIG_VERIFY(a >= 0 && b < A.cols() && outer[a + 1] - outer[a] == outer[b + 1] - outer[b],
               "contact node " << p + 1 << " (dofs " << a + 1 << ", " << b + 1
                               << "): its two dofs have different patterns");
    for (int k = outer[a]; k < outer[a + 1]; ++k) {
      const int j = inner[k];
      const int* first = inner + outer[j];
      const int* last = inner + outer[j + 1];
      const int* row = std::lower_bound(first, last, a);
      SIG_VERIFY(row != last && *row == a && row + 1 != last && *(row + 1) == b,
                 "contact node " << p + 1 << ": its node block in column " << j + 1
                                 << " is not full");
      row_slots_[p].push_back(static_cast<int>(row - inner));
    }
  }
}

void FrameRotation::rotate(Eigen::SparseMatrix<double>& A,
                           const std::vector<Eigen::Vector2d>& normals) const {
  double* v = A.valuePtr();
  const int* outer = A.outerIndexPtr();
  for (std::size_t p = 0; p < first_.size(); ++p) {
    const Eigen::Matrix2d R = nodal_frame(normals[p]);
    const int a = first_[p], b = a + 1;
    const int length = outer[a + 1] - outer[a];
    for (int k = 0; k < length; ++k) { // A Q on the columns a, b
      const double ca = v[outer[a] + k], cb = v[outer[b] + k];
      v[outer[a] + k] = ca * R(0, 0) + cb * R(1, 0);
      v[outer[b] + k] = ca * R(0, 1) + cb * R(1, 1);
    }
    for (const int slot : row_slots_[p]) { // Q^T (A Q) on the rows a, b
      const double ra = v[slot], rb = v[slot + 1];
      v[slot] = R(0, 0) * ra + R(1, 0) * rb;
      v[slot + 1] = R(0, 1) * ra + R(1, 1) * rb;
    }
  }
}

void FrameRotation::to_frames(Eigen::VectorXd& v,
                              const std::vector<Eigen::Vector2d>& normals) const {
  for (std::size_t p = 0; p < first_.size(); ++p)
    v.segment<2>(first_[p]) = nodal_frame(normals[p]).transpose() * v.segment<2>(first_[p]);
}

void FrameRotation::from_frames(Eigen::VectorXd& v,
                                const std::vector<Eigen::Vector2d>& normals) const {
  for (std::size_t p = 0; p < first_.size(); ++p)
    v.segment<2>(first_[p]) = nodal_frame(normals[p]) * v.segment<2>(first_[p]);
}

double FrameRotation::normal_row_times(const Eigen::SparseMatrix<double>& A, int p,
                                       const Eigen::VectorXd& w) const {
  const double* v = A.valuePtr();
  const int* inner = A.innerIndexPtr();
  const int* outer = A.outerIndexPtr();
  const int a = first_[p];
  double sum = 0;
  for (std::size_t k = 0; k < row_slots_[p].size(); ++k)
    sum += v[row_slots_[p][k] + 1] * w[inner[outer[a] + static_cast<int>(k)]];
  return sum;
}

} // namespace sig
