// The error in the norm of V (post/error_norm.hpp): exactly zero for a coarse P1 field on nested
// squares (its interpolant computed here independently, cell by cell), slope 1 in h for the P1
// interpolants of a smooth field (the rate of Figs 4.7, 5.12, 6.5), and the affine extension past a
// coarse boundary exact for an affine field.
#include "core/error.hpp"
#include "mesh/generators.hpp"
#include "post/error_norm.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

namespace sig {
namespace {

using Field = std::function<Eigen::Vector2d(const Eigen::Vector2d&)>;

Eigen::VectorXd nodal(const Mesh& mesh, const Field& f) {
  Eigen::VectorXd u(2 * mesh.num_nodes());
  for (int i = 0; i < mesh.num_nodes(); ++i)
    u.segment<2>(2 * i) = f(mesh.nodes[i]);
  return u;
}

/// The P1 interpolant on square(1, n) of the nodal values of f, evaluated at x by the cell
/// rule of the generator (diagonal (i, j)-(i+1, j+1) where i + j is even, else (i+1, j)-(i, j+1)):
/// an evaluation independent of prolongate's point location.
Eigen::Vector2d structured_interpolant(const Field& f, int n, const Eigen::Vector2d& x) {
  const int i = std::min(static_cast<int>(std::floor(x.x() * n)), n - 1);
  const int j = std::min(static_cast<int>(std::floor(x.y() * n)), n - 1);
  const double s = x.x() * n - i, t = x.y() * n - j;
  const auto at = [&](int di, int dj) {
    return f({static_cast<double>(i + di) / n, static_cast<double>(j + dj) / n});
  };
  if ((i + j) % 2 == 0)
    return s >= t ? Eigen::Vector2d((1 - s) * at(0, 0) + (s - t) * at(1, 0) + t * at(1, 1))
                  : Eigen::Vector2d((1 - t) * at(0, 0) + s * at(1, 1) + (t - s) * at(0, 1));
  return s + t <= 1
             ? Eigen::Vector2d((1 - s - t) * at(0, 0) + s * at(1, 0) + t * at(0, 1))
             : Eigen::Vector2d((1 - t) * at(1, 0) + (s + t - 1) * at(1, 1) + (1 - s) * at(0, 1));
}

const Field kSmooth = [](const Eigen::Vector2d& x) {
  return Eigen::Vector2d(std::sin(std::numbers::pi * x.x()) * std::sin(std::numbers::pi * x.y()),
                         x.x() * x.x() * x.y() + std::cos(2 * x.y()));
};

TEST(StrainError, ZeroForACoarseP1FieldOnNestedSquares) {
  for (int n : {2, 4, 8}) {
    const Mesh coarse = square(1.0, n), fine = square(1.0, 8 * n);
    const Eigen::VectorXd u_h = nodal(coarse, kSmooth);
    Eigen::VectorXd u_ref(2 * fine.num_nodes());
    for (int i = 0; i < fine.num_nodes(); ++i)
      u_ref.segment<2>(2 * i) = structured_interpolant(kSmooth, n, fine.nodes[i]);
    EXPECT_LT((prolongate(coarse, u_h, fine) - u_ref).cwiseAbs().maxCoeff(), 1e-14) << n;
    const StrainError e = strain_error(fine, u_ref, coarse, u_h);
    EXPECT_LT(e.error, 1e-12 * e.reference_norm) << n;
    EXPECT_GT(e.reference_norm, 1.0);
  }
}

TEST(StrainError, SlopeOneForTheInterpolantsOfASmoothField) {
  const Mesh reference = square(1.0, 256);
  const Eigen::VectorXd u_ref = nodal(reference, kSmooth);
  double previous = 0;
  for (int n : {4, 8, 16, 32}) {
    const Mesh coarse = square(1.0, n);
    const double error = strain_error(reference, u_ref, coarse, nodal(coarse, kSmooth)).error;
    if (previous > 0) {
      const double slope = std::log2(previous / error);
      EXPECT_NEAR(slope, 1.0, 0.1) << "n " << n;
    }
    previous = error;
  }
}

TEST(StrainError, AWindowIntegratesItsTrianglesOnly) {
  const Mesh coarse = square(1.0, 4), fine = square(1.0, 16);
  const Eigen::VectorXd u_ref = nodal(fine, kSmooth), u_h = nodal(coarse, kSmooth);
  const StrainError whole = strain_error(fine, u_ref, coarse, u_h);
  const StrainError all = strain_error(fine, u_ref, coarse, u_h, Window{-1, 2, -1, 2});
  EXPECT_NEAR(all.error, whole.error, 1e-14 * whole.error);
  EXPECT_NEAR(all.reference_norm, whole.reference_norm, 1e-14 * whole.reference_norm);
  // A reference field that differs from u_h only on x > 0.5: no error on the left half.
  Eigen::VectorXd u_right = prolongate(coarse, u_h, fine);
  for (int i = 0; i < fine.num_nodes(); ++i)
    if (fine.nodes[i].x() > 0.5) u_right.segment<2>(2 * i) += Eigen::Vector2d(0.1, -0.2);
  EXPECT_LT(strain_error(fine, u_right, coarse, u_h, Window{0, 0.45, 0, 1}).error, 1e-14);
  EXPECT_GT(strain_error(fine, u_right, coarse, u_h, Window{0, 0.55, 0, 1}).error, 1e-3);
  EXPECT_THROW(strain_error(fine, u_ref, coarse, u_h, Window{2, 3, 2, 3}), Error);
}

TEST(StrainError, AffineExtensionPastTheCoarseBoundary) {
  // Reference nodes up to 2 % outside the coarse square (a curved boundary's situation): an
  // affine field is carried exactly by the nearest coarse triangle's extension.
  const Field affine = [](const Eigen::Vector2d& x) {
    return Eigen::Vector2d(0.3 + 2 * x.x() - x.y(), -1 + 0.5 * x.x() + 3 * x.y());
  };
  const Mesh coarse = square(1.0, 4);
  Mesh fine = square(1.0, 12);
  for (Point& x : fine.nodes)
    x = Eigen::Vector2d(0.5, 0.5) + 1.02 * (x - Eigen::Vector2d(0.5, 0.5));
  EXPECT_LT(
      (prolongate(coarse, nodal(coarse, affine), fine) - nodal(fine, affine)).cwiseAbs().maxCoeff(),
      1e-13);
  EXPECT_THROW(prolongate(coarse, Eigen::VectorXd::Zero(3), fine), Error);
}

} // namespace
} // namespace sig
