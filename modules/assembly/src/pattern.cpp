#include "assembly/pattern.hpp"

#include "core/error.hpp"
#include "mesh/mesh.hpp"

#include <algorithm>
#include <span>

namespace sig {

SparsityPattern::SparsityPattern(const Mesh& mesh) {
  const int n = mesh.num_nodes();

  // Node graph: each node's neighbours through the triangles, itself included, sorted; one flat
  // array of per-node segments (start[m], start[m] + count[m]) rather than a vector per node,
  // whose allocations and regrowth were most of the cost (the pattern is built once per solve).
  std::vector<int> start(n + 1, 0);
  for (const auto& tri : mesh.triangles)
    for (int a : tri)
      start[a + 1] += 3;
  for (int m = 0; m < n; ++m)
    start[m + 1] += start[m];
  std::vector<int> graph(start[n]);
  std::vector<int> count(n, 0);
  for (const auto& tri : mesh.triangles)
    for (int a : tri)
      for (int b : tri)
        graph[start[a] + count[a]++] = b;
  for (int m = 0; m < n; ++m) {
    const auto first = graph.begin() + start[m];
    std::sort(first, first + count[m]);
    count[m] = static_cast<int>(std::unique(first, first + count[m]) - first);
  }
  const auto neighbours = [&](int m) {
    return std::span<const int>(graph.data() + start[m], static_cast<std::size_t>(count[m]));
  };

  // Column 2 m + c holds rows 2 k + 0, 2 k + 1 for every neighbour k of m: already sorted.
  outer_.assign(2 * n + 1, 0);
  for (int m = 0; m < n; ++m)
    for (int c = 0; c < 2; ++c)
      outer_[2 * m + c + 1] = outer_[2 * m + c] + 2 * count[m];
  inner_.resize(outer_.back());
  for (int m = 0; m < n; ++m)
    for (int c = 0; c < 2; ++c) {
      int p = outer_[2 * m + c];
      for (int k : neighbours(m)) {
        inner_[p++] = 2 * k;
        inner_[p++] = 2 * k + 1;
      }
    }

  // Scatter map: entry (2 i + c, 2 j + d) of a triangle lies in column 2 nj + d at the position
  // of node ni in the neighbour list of nj, plus c.
  scatter_.resize(36 * mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    for (int j = 0; j < 3; ++j) {
      const std::span<const int> list = neighbours(tri[j]);
      for (int i = 0; i < 3; ++i) {
        const int position =
            static_cast<int>(std::lower_bound(list.begin(), list.end(), tri[i]) - list.begin());
        for (int c = 0; c < 2; ++c)
          for (int d = 0; d < 2; ++d)
            scatter_[36 * t + 6 * (2 * i + c) + (2 * j + d)] =
                outer_[2 * tri[j] + d] + 2 * position + c;
      }
    }
  }
}

Eigen::SparseMatrix<double> SparsityPattern::zero_matrix() const {
  Eigen::SparseMatrix<double> A(num_dofs(), num_dofs());
  A.resizeNonZeros(nnz());
  std::copy(outer_.begin(), outer_.end(), A.outerIndexPtr());
  std::copy(inner_.begin(), inner_.end(), A.innerIndexPtr());
  std::fill(A.valuePtr(), A.valuePtr() + nnz(), 0.0);
  return A;
}

void SparsityPattern::add(Eigen::SparseMatrix<double>& A, int t, const Matrix6d& element) const {
  SIG_ASSERT(A.isCompressed() && A.nonZeros() == nnz() && A.cols() == num_dofs(),
             "matrix does not have the pattern's layout");
  double* values = A.valuePtr();
  const int* slots = scatter_.data() + 36 * t;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      values[slots[6 * i + j]] += element(i, j);
}

} // namespace sig
