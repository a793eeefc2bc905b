// The words for a matrix that fails to factorize (assembly/singular_matrix.hpp): a free part
// first, with or without mass in a march; with every part held, the defect of the matrices no
// deck makes (a diagonal entry <= 0, an asymmetric entry, a diagonal spanning 1e20), and the
// plain statement when none of these shows.
#include "assembly/singular_matrix.hpp"
#include "two_triangles.hpp"

#include <gtest/gtest.h>

namespace sig {
namespace {

/// A system whose K is the identity scaled by `diagonal` but with entry (i, j) = value.
LinearSystem system_with(double diagonal, int i, int j, double value, std::vector<int> imposed) {
  LinearSystem system;
  Eigen::MatrixXd K = diagonal * Eigen::MatrixXd::Identity(8, 8);
  K(i, j) = value;
  system.K = K.sparseView();
  system.f = Eigen::VectorXd::Zero(8);
  system.dirichlet_dofs = std::move(imposed);
  return system;
}

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(FailedFactorization, NamesTheFreePartThenTheMatrixDefect) {
  const Mesh mesh = test::two_triangle_square();
  const std::vector<int> clamped = {0, 1, 6, 7}; // nodes 1 and 4: the left side
  const FailedFactorization failed{"out/case.tae", false, "CHOLMOD: not positive definite"};
  // Nothing holds the square.
  std::string why =
      explain_failed_factorization(mesh, system_with(1, 0, 0, 1, {}), holds_of({}), failed);
  EXPECT_TRUE(has(why, "the body is free to move")) << why;
  EXPECT_TRUE(has(why, "(CHOLMOD: not positive definite)")) << why;
  // In a march without mass: nothing holds it, not even a mass.
  why = explain_failed_factorization(mesh, system_with(1, 0, 0, 1, {}), holds_of({}),
                                     {"out/case.tae", true, "x"});
  EXPECT_TRUE(has(why, "it has no mass either (MATERIAL rho=0")) << why;
  // Held: the defects of K.
  why = explain_failed_factorization(mesh, system_with(1, 4, 4, -5, clamped), holds_of(clamped),
                                     failed);
  EXPECT_TRUE(has(why, "out/case.tae: array 'K_val': the diagonal entry of u1 of node 3 is -5"))
      << why;
  why = explain_failed_factorization(mesh, system_with(1, 2, 4, 3, clamped), holds_of(clamped),
                                     failed);
  EXPECT_TRUE(has(why, "array 'K_val' is not symmetric (entries differing by 3")) << why;
  why = explain_failed_factorization(mesh, system_with(1, 4, 4, 1e20, clamped), holds_of(clamped),
                                     failed);
  EXPECT_TRUE(has(why, "its diagonal spans 1 (u1 of node 2) to 1e+20 (u1 of node 3)")) << why;
  why = explain_failed_factorization(mesh, system_with(1, 0, 0, 1, clamped), holds_of(clamped),
                                     failed);
  EXPECT_TRUE(has(why, "every part of the body is held (4 imposed dofs, no CONTACT card), yet the "
                       "stiffness is not positive definite"))
      << why;
}

} // namespace
} // namespace sig
