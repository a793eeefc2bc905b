#include "assembly/pattern.hpp"

#include "core/error.hpp"
#include "mesh/mesh.hpp"

#include <algorithm>
#include <span>

namespace sig {

SparsityPattern::SparsityPattern(const Mesh& mesh)
    : dim_(mesh.dim), local_(mesh.dim * (mesh.dim + 1)) {
  const int n = mesh.num_nodes();
  const int d = dim_, vertices = d + 1, local = local_;

  // Node graph: each node's neighbours through the cells, itself included, sorted; one flat
  // array of per-node segments (start[m], start[m] + count[m]) rather than a vector per node,
  // whose allocations and regrowth were most of the cost (the pattern is built once per solve).
  std::vector<int> start(n + 1, 0);
  for (const auto& tri : mesh.cells)
    for (int a : tri)
      start[a + 1] += vertices;
  for (int m = 0; m < n; ++m)
    start[m + 1] += start[m];
  std::vector<int> graph(start[n]);
  std::vector<int> count(n, 0);
  for (const auto& tri : mesh.cells)
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

  // Column d m + c holds rows d k + 0 .. d k + d - 1 for every neighbour k of m: already sorted.
  outer_.assign(d * n + 1, 0);
  for (int m = 0; m < n; ++m)
    for (int c = 0; c < d; ++c)
      outer_[d * m + c + 1] = outer_[d * m + c] + d * count[m];
  inner_.resize(outer_.back());
  for (int m = 0; m < n; ++m)
    for (int c = 0; c < d; ++c) {
      int p = outer_[d * m + c];
      for (int k : neighbours(m))
        for (int r = 0; r < d; ++r)
          inner_[p++] = d * k + r;
    }

  // Scatter map: entry (d i + r, d j + c) of a cell lies in column d nj + c at the position of
  // node ni in the neighbour list of nj, times d, plus r.
  scatter_.resize(static_cast<std::size_t>(local) * local * mesh.cells.size());
  for (std::size_t t = 0; t < mesh.cells.size(); ++t) {
    const auto& cell = mesh.cells[t];
    for (int j = 0; j < vertices; ++j) {
      const std::span<const int> list = neighbours(cell[j]);
      for (int i = 0; i < vertices; ++i) {
        const int position =
            static_cast<int>(std::lower_bound(list.begin(), list.end(), cell[i]) - list.begin());
        for (int r = 0; r < d; ++r)
          for (int c = 0; c < d; ++c)
            scatter_[local * local * t + local * (d * i + r) + (d * j + c)] =
                outer_[d * cell[j] + c] + d * position + r;
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

void SparsityPattern::add(Eigen::SparseMatrix<double>& A, int t,
                          const Eigen::Ref<const Eigen::MatrixXd>& element) const {
  SIG_ASSERT(A.isCompressed() && A.nonZeros() == nnz() && A.cols() == num_dofs(),
             "matrix does not have the pattern's layout");
  SIG_ASSERT(element.rows() == local_ && element.cols() == local_,
             "element matrix of " << element.rows() << " rows for cells of " << local_ << " dofs");
  double* values = A.valuePtr();
  const int* slots = scatter_.data() + static_cast<std::size_t>(local_) * local_ * t;
  for (int i = 0; i < local_; ++i)
    for (int j = 0; j < local_; ++j)
      values[slots[local_ * i + j]] += element(i, j);
}

} // namespace sig
