// The nodal frames of the contact solves in 3D (issue 26): the in-place rotation of a sparse
// matrix against the dense Q^T A Q, the normal row, the vectors' round trip, and the 2D frame as
// the 2D case of the one contact frame.
#include "contact/contact_law.hpp"
#include "core/error.hpp"
#include "solver/nodal_frames.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <gtest/gtest.h>
#include <vector>

namespace sig {
namespace {

const std::vector<Eigen::Vector3d> kNormals = {{0.6, 0, 0.8}, {0.48, -0.6, 0.64}, {1, 1, 1}};

TEST(ContactFrame3d, TwoDimensionalFrameIsTheNodalFrame) {
  for (const double angle : {0.0, 0.3, 2.0, -1.2}) {
    const Eigen::Vector2d n(std::cos(angle), std::sin(angle));
    EXPECT_EQ(Eigen::Matrix2d(contact_frame(n)), nodal_frame(n));
  }
}

// A symmetric matrix whose d x d node blocks are full (dense pattern, stored sparse).
Eigen::SparseMatrix<double> dense_pattern(int n) {
  Eigen::MatrixXd A = Eigen::MatrixXd::Random(n, n);
  A = (A * A.transpose()).eval() + n * Eigen::MatrixXd::Identity(n, n);
  Eigen::SparseMatrix<double> S = A.sparseView(0, 0);
  S.makeCompressed();
  return S;
}

TEST(FrameRotation3d, InPlaceRotationIsQtAQ) {
  const int n = 13;
  Eigen::SparseMatrix<double> A = dense_pattern(n);
  const std::vector<int> first = {0, 4, 9};
  std::vector<ContactFrame> frames;
  Eigen::MatrixXd Q = Eigen::MatrixXd::Identity(n, n);
  for (std::size_t p = 0; p < first.size(); ++p) {
    frames.push_back(contact_frame(kNormals[p].normalized()));
    Q.block(first[p], first[p], 3, 3) = frames.back();
  }
  const Eigen::MatrixXd expected = Q.transpose() * Eigen::MatrixXd(A) * Q;
  const FrameRotation rotation(A, first, 3);
  rotation.rotate(A, frames);
  EXPECT_NEAR((Eigen::MatrixXd(A) - expected).norm(), 0, 1e-12 * expected.norm());
  const Eigen::VectorXd w = Eigen::VectorXd::LinSpaced(n, 1, 2);
  for (std::size_t p = 0; p < first.size(); ++p)
    EXPECT_NEAR(rotation.normal_row_times(A, static_cast<int>(p), w), (expected * w)[first[p] + 2],
                1e-12 * expected.norm());
  Eigen::VectorXd v = w;
  rotation.to_frames(v, frames);
  EXPECT_NEAR((v - Q.transpose() * w).norm(), 0, 1e-14);
  rotation.from_frames(v, frames);
  EXPECT_NEAR((v - w).norm(), 0, 1e-14);
}

TEST(FrameRotation3d, NodeBlockMustBeFull) {
  Eigen::SparseMatrix<double> A = dense_pattern(6);
  A.coeffRef(1, 2) = 0;
  A.prune(0.0);
  A.makeCompressed();
  EXPECT_THROW(FrameRotation(A, {0}, 3), Error);
}

} // namespace
} // namespace sig
