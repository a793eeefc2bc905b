#pragma once
// Manufactured sparse problems shared by the linear solver and Schur complement tests: the P1
// plane-strain stiffness of a structured rectangle mesh, its rigid modes, and the usual
// reductions (Dirichlet clamping, submatrices).
#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <vector>

namespace sig::test {

/// Structured mesh of [0, nx] x [0, ny]: nodes (i, j), each unit square cut into 2 triangles.
struct Grid {
  int nx, ny;
  int nodes() const { return (nx + 1) * (ny + 1); }
  int node(int i, int j) const { return j * (nx + 1) + i; }
  int dofs() const { return 2 * nodes(); }
  double x(int node) const { return node % (nx + 1); }
  double y(int node) const { return node / (nx + 1); }
  bool on_boundary(int i, int j) const { return i == 0 || j == 0 || i == nx || j == ny; }
};

/// P1 plane-strain stiffness, dofs (2 node, 2 node + 1); no boundary condition, so its kernel
/// is the 3 rigid motions.
inline Eigen::SparseMatrix<double> elasticity_stiffness(const Grid& g, double E = 1.0,
                                                        double nu = 0.3) {
  const double c = E / ((1 + nu) * (1 - 2 * nu));
  Eigen::Matrix3d D;
  D << c * (1 - nu), c * nu, 0, c * nu, c * (1 - nu), 0, 0, 0, c * (1 - 2 * nu) / 2;
  std::vector<Eigen::Triplet<double>> t;
  auto add_triangle = [&](int a, int b, int d) {
    const int v[3] = {a, b, d};
    double x[3], y[3];
    for (int k = 0; k < 3; ++k)
      x[k] = g.x(v[k]), y[k] = g.y(v[k]);
    const double area2 = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
    Eigen::Matrix<double, 3, 6> B = Eigen::Matrix<double, 3, 6>::Zero();
    for (int k = 0; k < 3; ++k) {
      const double bk = y[(k + 1) % 3] - y[(k + 2) % 3];
      const double ck = x[(k + 2) % 3] - x[(k + 1) % 3];
      B(0, 2 * k) = bk / area2;
      B(1, 2 * k + 1) = ck / area2;
      B(2, 2 * k) = ck / area2;
      B(2, 2 * k + 1) = bk / area2;
    }
    const Eigen::Matrix<double, 6, 6> Ke = 0.5 * area2 * B.transpose() * D * B;
    for (int p = 0; p < 6; ++p)
      for (int q = 0; q < 6; ++q)
        t.emplace_back(2 * v[p / 2] + p % 2, 2 * v[q / 2] + q % 2, Ke(p, q));
  };
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      add_triangle(g.node(i, j), g.node(i + 1, j), g.node(i + 1, j + 1));
      add_triangle(g.node(i, j), g.node(i + 1, j + 1), g.node(i, j + 1));
    }
  Eigen::SparseMatrix<double> K(g.dofs(), g.dofs());
  K.setFromTriplets(t.begin(), t.end());
  return K;
}

/// The rigid motions (translations x, y and the rotation (-y, x)) as 3 columns.
inline Eigen::MatrixXd rigid_modes(const Grid& g) {
  Eigen::MatrixXd R = Eigen::MatrixXd::Zero(g.dofs(), 3);
  for (int v = 0; v < g.nodes(); ++v) {
    R(2 * v, 0) = 1;
    R(2 * v + 1, 1) = 1;
    R(2 * v, 2) = -g.y(v);
    R(2 * v + 1, 2) = g.x(v);
  }
  return R;
}

/// Sorted dofs of the nodes accepted by keep(i, j).
template <class Pred> std::vector<int> dofs_where(const Grid& g, Pred keep) {
  std::vector<int> dofs;
  for (int v = 0; v < g.nodes(); ++v) {
    const int i = v % (g.nx + 1), j = v / (g.nx + 1);
    if (keep(i, j)) {
      dofs.push_back(2 * v);
      dofs.push_back(2 * v + 1);
    }
  }
  return dofs;
}

/// A(rows, cols) for sorted index lists.
inline Eigen::SparseMatrix<double> submatrix(const Eigen::SparseMatrix<double>& A,
                                             const std::vector<int>& rows,
                                             const std::vector<int>& cols) {
  std::vector<int> row_of(A.rows(), -1), col_of(A.cols(), -1);
  for (size_t k = 0; k < rows.size(); ++k)
    row_of[rows[k]] = static_cast<int>(k);
  for (size_t k = 0; k < cols.size(); ++k)
    col_of[cols[k]] = static_cast<int>(k);
  std::vector<Eigen::Triplet<double>> t;
  for (int j = 0; j < A.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it)
      if (row_of[it.row()] >= 0 && col_of[j] >= 0)
        t.emplace_back(row_of[it.row()], col_of[j], it.value());
  Eigen::SparseMatrix<double> S(static_cast<long>(rows.size()), static_cast<long>(cols.size()));
  S.setFromTriplets(t.begin(), t.end());
  return S;
}

/// The complement of a sorted index list in [0, n).
/// The block of a dense matrix on the rows r and the columns s.
inline Eigen::MatrixXd dense_block(const Eigen::MatrixXd& A, const std::vector<int>& r,
                                   const std::vector<int>& s) {
  Eigen::MatrixXd B(r.size(), s.size());
  for (size_t p = 0; p < r.size(); ++p)
    for (size_t q = 0; q < s.size(); ++q)
      B(p, q) = A(r[p], s[q]);
  return B;
}

inline std::vector<int> complement(const std::vector<int>& dofs, int n) {
  std::vector<int> rest;
  for (int d = 0; d < n; ++d)
    if (!std::binary_search(dofs.begin(), dofs.end(), d)) rest.push_back(d);
  return rest;
}

/// The stiffness of the rectangle clamped on its left edge x = 0: symmetric positive definite.
inline Eigen::SparseMatrix<double> clamped_stiffness(const Grid& g) {
  const auto free = dofs_where(g, [](int i, int) { return i > 0; });
  return submatrix(elasticity_stiffness(g), free, free);
}

/// A smooth manufactured solution with entries of order 1.
inline Eigen::VectorXd manufactured(int n, double phase = 0.0) {
  Eigen::VectorXd x(n);
  for (int k = 0; k < n; ++k)
    x[k] = std::sin(0.01 * k + phase) + 0.5 * std::cos(0.37 * k);
  return x;
}

} // namespace sig::test
