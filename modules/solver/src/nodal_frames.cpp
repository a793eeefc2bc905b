#include "solver/nodal_frames.hpp"

namespace sig {

Eigen::SparseMatrix<double> nodal_frames(int n, const std::vector<std::array<int, 2>>& dofs,
                                         const std::vector<Eigen::Vector2d>& normals) {
  std::vector<char> rotated(n, 0);
  std::vector<Eigen::Triplet<double>> entries;
  for (std::size_t p = 0; p < dofs.size(); ++p) {
    const Eigen::Vector2d& normal = normals[p];
    const Eigen::Vector2d tangent(-normal.y(), normal.x());
    for (int a = 0; a < 2; ++a) {
      rotated[dofs[p][a]] = 1;
      entries.emplace_back(dofs[p][a], dofs[p][0], tangent[a]);
      entries.emplace_back(dofs[p][a], dofs[p][1], -normal[a]);
    }
  }
  for (int i = 0; i < n; ++i)
    if (!rotated[i]) entries.emplace_back(i, i, 1.0);
  Eigen::SparseMatrix<double> Q(n, n);
  Q.setFromTriplets(entries.begin(), entries.end());
  return Q;
}

} // namespace sig
