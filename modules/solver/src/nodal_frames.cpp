#include "solver/nodal_frames.hpp"

namespace sig {

Eigen::SparseMatrix<double> nodal_frames(int n, const std::vector<std::array<int, 2>>& dofs,
                                         const std::vector<Eigen::Vector2d>& normals) {
  std::vector<char> rotated(n, 0);
  std::vector<Eigen::Triplet<double>> entries;
  for (std::size_t p = 0; p < dofs.size(); ++p) {
    const Eigen::Matrix2d R = nodal_frame(normals[p]);
    for (int a = 0; a < 2; ++a) {
      rotated[dofs[p][a]] = 1;
      for (int b = 0; b < 2; ++b)
        entries.emplace_back(dofs[p][a], dofs[p][b], R(a, b));
    }
  }
  for (int i = 0; i < n; ++i)
    if (!rotated[i]) entries.emplace_back(i, i, 1.0);
  Eigen::SparseMatrix<double> Q(n, n);
  Q.setFromTriplets(entries.begin(), entries.end());
  return Q;
}

} // namespace sig
