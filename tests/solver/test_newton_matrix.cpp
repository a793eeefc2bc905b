// The Newton matrix of the large-deformation contact solve (solver/newton_matrix.hpp): its
// in-place rotation is Q^T A Q, its decoupled solve on the fixed pattern is the solution by
// elimination of the imposed dofs, and the reaction row is the row of the rotated matrix.
// Checked against dense algebra on a deliberately unsymmetric matrix (a transposed row or
// column would show) and, through MUMPS's LDL^T which reads one triangle only, on a symmetric
// one (a held row left coupled would show).
#include "assembly/pattern.hpp"
#include "contact/contact_law.hpp"
#include "core/error.hpp"
#include "mesh/generators.hpp"
#include "mesh/gmsh.hpp"
#include "solver/linear_solver.hpp"
#include "solver/newton_matrix.hpp"
#include "solver/nodal_frames.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>

namespace {

struct Case {
  sig::Mesh mesh = sig::rectangle(1.0, 0.5, 5, 3);
  sig::SparsityPattern pattern{mesh};
  std::vector<int> contact_nodes = mesh.nodes_with_ref(3); // the bottom side
  std::vector<char> dirichlet;
  Eigen::SparseMatrix<double> K = pattern.zero_matrix();
  std::vector<Eigen::Vector2d> normals;

  explicit Case(bool symmetric = false) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    const int n = pattern.num_dofs();
    // Unsymmetric values on the pattern, diagonally dominant so every block is regular.
    for (int j = 0; j < n; ++j)
      for (Eigen::SparseMatrix<double>::InnerIterator it(K, j); it; ++it)
        it.valueRef() = it.row() == j ? 40.0 + uniform(random) : uniform(random);
    if (symmetric)
      K = Eigen::SparseMatrix<double>(0.5 * (K + Eigen::SparseMatrix<double>(K.transpose())));
    dirichlet.assign(n, 0);
    for (int node : mesh.nodes_with_ref(1)) // the left side, but not a contact node
      if (std::find(contact_nodes.begin(), contact_nodes.end(), node) == contact_nodes.end())
        dirichlet[2 * node] = dirichlet[2 * node + 1] = 1;
    for (std::size_t p = 0; p < contact_nodes.size(); ++p) {
      const double angle = 1.2 + 0.3 * static_cast<double>(p);
      normals.emplace_back(std::cos(angle), std::sin(angle));
    }
  }

  /// Q as a dense matrix: the node's frame on its two dofs, the identity elsewhere.
  Eigen::MatrixXd frames() const {
    Eigen::MatrixXd Q = Eigen::MatrixXd::Identity(pattern.num_dofs(), pattern.num_dofs());
    for (std::size_t p = 0; p < contact_nodes.size(); ++p)
      Q.block<2, 2>(2 * contact_nodes[p], 2 * contact_nodes[p]) = sig::nodal_frame(normals[p]);
    return Q;
  }
};

TEST(NewtonMatrix, RotationInPlaceIsQTransposeAQ) {
  const Case c;
  sig::NewtonMatrix J(c.pattern.zero_matrix(), c.dirichlet, c.contact_nodes);
  Eigen::SparseMatrix<double> K = c.K;
  J.take_tangent(K);
  const Eigen::Matrix2d block = (Eigen::Matrix2d() << 3.0, -1.0, 0.5, 2.0).finished();
  J.add_node_block(1, block);
  J.rotate(c.normals);

  Eigen::MatrixXd A = Eigen::MatrixXd(c.K);
  const int a = 2 * c.contact_nodes[1];
  A.block<2, 2>(a, a) += block;
  const Eigen::MatrixXd Q = c.frames();
  const Eigen::MatrixXd expected = Q.transpose() * A * Q;
  EXPECT_LE((Eigen::MatrixXd(J.matrix()) - expected).norm(), 1e-13 * expected.norm());
}

// In 3D: the frames of contact_frame (two tangents and -n) on the three dofs of each contact
// node of gmsh's unit cube (its base), and a 3 x 3 node block.
TEST(NewtonMatrix, RotationInPlaceIsQTransposeAQIn3d) {
  const sig::Mesh mesh = sig::read_gmsh(std::filesystem::path(SIG_SOURCE_DIR) / "tests" / "fuzz" /
                                        "corpus" / "gmsh" / "box_v41_ascii.msh");
  const sig::SparsityPattern pattern(mesh);
  const std::vector<int> nodes = mesh.nodes_with_ref(1);
  const int n = pattern.num_dofs();
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::SparseMatrix<double> K = pattern.zero_matrix();
  for (int j = 0; j < n; ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(K, j); it; ++it)
      it.valueRef() = it.row() == j ? 40.0 + uniform(random) : uniform(random);
  std::vector<sig::ContactFrame> frames;
  Eigen::MatrixXd Q = Eigen::MatrixXd::Identity(n, n);
  for (std::size_t p = 0; p < nodes.size(); ++p) {
    const Eigen::Vector3d normal =
        Eigen::Vector3d(uniform(random), uniform(random), 1.0 + uniform(random)).normalized();
    frames.push_back(sig::contact_frame(normal));
    Q.block<3, 3>(3 * nodes[p], 3 * nodes[p]) = frames.back();
  }
  sig::NewtonMatrix J(pattern.zero_matrix(), std::vector<char>(n, 0), nodes, 3);
  Eigen::SparseMatrix<double> tangent = K;
  J.take_tangent(tangent);
  Eigen::Matrix3d block;
  block << 3.0, -1.0, 0.5, 2.0, 1.0, -0.3, 0.2, 0.7, 4.0;
  J.add_node_block(1, block);
  J.rotate(frames);

  Eigen::MatrixXd A(K);
  A.block<3, 3>(3 * nodes[1], 3 * nodes[1]) += block;
  const Eigen::MatrixXd expected = Q.transpose() * A * Q;
  EXPECT_LE((Eigen::MatrixXd(J.matrix()) - expected).norm(), 1e-13 * expected.norm());
  EXPECT_THROW(J.add_node_block(0, Eigen::Matrix2d::Identity()), sig::Error);
}

void check_decoupled_solve(bool symmetric) {
  const Case c(symmetric);
  const int n = c.pattern.num_dofs();
  sig::NewtonMatrix J(c.pattern.zero_matrix(), c.dirichlet, c.contact_nodes);
  Eigen::SparseMatrix<double> K = c.K;
  J.take_tangent(K);
  J.rotate(c.normals);
  const Eigen::MatrixXd A = Eigen::MatrixXd(J.matrix());
  const auto solver = symmetric ? sig::make_linear_solver("mumps", sig::MatrixKind::symmetric)
                                : sig::make_linear_solver("umfpack", sig::MatrixKind::general);
  const Eigen::VectorXd r0 = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);

  // Two active sets on the same pattern: the second holds other normal dofs, so a stale
  // decoupling from the first solve would show.
  for (const std::vector<int>& held_nodes : {std::vector<int>{0, 2}, std::vector<int>{1, 3, 4}}) {
    std::vector<std::pair<int, double>> imposed;
    for (int i = 0; i < n; ++i)
      if (c.dirichlet[i]) imposed.emplace_back(i, 0.01 * i);
    for (int p : held_nodes)
      imposed.emplace_back(2 * c.contact_nodes[p] + 1, -0.1 * (p + 1));
    std::sort(imposed.begin(), imposed.end());
    const Eigen::VectorXd dw = J.solve(r0, imposed, *solver);

    // Elimination, dense: dw_I given, A_FF dw_F = -r0_F - A_FI dw_I.
    std::vector<char> is_imposed(n, 0);
    Eigen::VectorXd expected = Eigen::VectorXd::Zero(n);
    for (const auto& [dof, value] : imposed) {
      is_imposed[dof] = 1;
      expected[dof] = value;
    }
    std::vector<int> free;
    for (int i = 0; i < n; ++i)
      if (!is_imposed[i]) free.push_back(i);
    const int m = static_cast<int>(free.size());
    Eigen::MatrixXd A_ff(m, m);
    Eigen::VectorXd rhs(m);
    const Eigen::VectorXd moved = A * expected;
    for (int r = 0; r < m; ++r) {
      rhs[r] = -r0[free[r]] - moved[free[r]];
      for (int s = 0; s < m; ++s)
        A_ff(r, s) = A(free[r], free[s]);
    }
    const Eigen::VectorXd dw_free = A_ff.partialPivLu().solve(rhs);
    for (int r = 0; r < m; ++r)
      expected[free[r]] = dw_free[r];
    EXPECT_LE((dw - expected).norm(), 1e-12 * expected.norm());
    for (const auto& [dof, value] : imposed)
      EXPECT_EQ(dw[dof], value) << "dof " << dof;

    // The reaction row of each contact node is its row of the rotated matrix.
    const Eigen::VectorXd product = A * dw;
    for (std::size_t p = 0; p < c.contact_nodes.size(); ++p)
      EXPECT_NEAR(J.normal_row_times(static_cast<int>(p), dw), product[2 * c.contact_nodes[p] + 1],
                  1e-12 * product.norm());
  }
}

TEST(NewtonMatrix, DecoupledSolveIsTheEliminatedSolve) {
  check_decoupled_solve(false);
}

TEST(NewtonMatrix, DecoupledSolveStaysSymmetricForLDLT) {
  check_decoupled_solve(true);
}

} // namespace
