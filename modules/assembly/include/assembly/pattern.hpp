#pragma once
// The sparsity pattern of P1 elasticity on a mesh and the scatter map of its cells, computed
// once: global assembly is then a loop adding element entries at precomputed slots of the value
// array, with no search, no triplets and no reallocation (DESIGN.md: "no triplets in a Newton
// loop").
//
// Dofs are interleaved, dof = d node + component (d the mesh's dimension). The pattern holds the
// full symmetric matrix (both triangles of it) with sorted indices. Because it is structurally
// symmetric, its compressed column storage (what Eigen::SparseMatrix<double> = ColMajor holds) and
// its compressed row storage coincide: outer() is both the column pointer and the CSR row pointer,
// inner() both the row and the column indices. Every matrix built by zero_matrix() shares this
// layout, so K and M can be combined value by value (K + c M on the same pattern).
#include "assembly/p1.hpp"

#include <Eigen/SparseCore>
#include <vector>

namespace sig {

struct Mesh;

class SparsityPattern {
public:
  explicit SparsityPattern(const Mesh& mesh);

  int num_dofs() const { return static_cast<int>(outer_.size()) - 1; }
  int dofs_per_node() const { return dim_; } ///< the mesh's dimension
  int nnz() const { return static_cast<int>(inner_.size()); }
  const std::vector<int>& outer() const { return outer_; } ///< size num_dofs() + 1
  const std::vector<int>& inner() const { return inner_; } ///< sorted within each column

  /// Index in the value array of local entry (i, j) (row i, column j, local dofs 0..d(d+1)-1)
  /// of cell t.
  int slot(int t, int i, int j) const {
    return scatter_[static_cast<std::size_t>(local_) * local_ * t + local_ * i + j];
  }

  /// A compressed column-major matrix with this pattern and zero values.
  Eigen::SparseMatrix<double> zero_matrix() const;

  /// A += element matrix of cell t (d(d+1) x d(d+1)). A must come from zero_matrix() (checked
  /// in debug).
  void add(Eigen::SparseMatrix<double>& A, int t,
           const Eigen::Ref<const Eigen::MatrixXd>& element) const;

private:
  int dim_ = 2;   ///< the mesh's dimension: dofs per node
  int local_ = 6; ///< dofs per cell, d (d + 1)
  std::vector<int> outer_, inner_;
  std::vector<int> scatter_; ///< local_^2 slots per cell
};

} // namespace sig
