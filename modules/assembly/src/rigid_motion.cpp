#include "assembly/rigid_motion.hpp"

#include "core/error.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <sstream>

namespace sig {

std::string free_rigid_motions(const Mesh& mesh, const std::vector<int>& dirichlet_dofs) {
  // A rigid motion is a (translation) + c (-(y - yc), x - xc) / L; it is held when no non-zero
  // (a, b, c) vanishes at every Dirichlet dof: the null space of the 3 x 3 C^T C, C having a row
  // per imposed dof. Scaling the rotation by the size L makes the three columns comparable.
  Eigen::Vector2d low = mesh.nodes.front(), high = low, centre = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& x : mesh.nodes) {
    low = low.cwiseMin(x);
    high = high.cwiseMax(x);
    centre += x;
  }
  centre /= static_cast<double>(mesh.nodes.size());
  const double size = std::max((high - low).norm(), 1e-300);
  Eigen::Matrix3d ctc = Eigen::Matrix3d::Zero();
  for (const int dof : dirichlet_dofs) {
    const Eigen::Vector2d d = (mesh.nodes[dof / 2] - centre) / size;
    const Eigen::Vector3d row =
        dof % 2 == 0 ? Eigen::Vector3d(1, 0, -d.y()) : Eigen::Vector3d(0, 1, d.x());
    ctc += row * row.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(ctc);
  const double tolerance = 1e-10 * std::max(1.0, eigen.eigenvalues()(2));
  // A translation is free when no dof of its component is imposed; a rotation when the null
  // space holds more than the free translations.
  bool x_free = true, y_free = true;
  for (const int dof : dirichlet_dofs)
    (dof % 2 == 0 ? x_free : y_free) = false;
  std::vector<std::string> motions;
  if (x_free) motions.push_back("the translation along x1");
  if (y_free) motions.push_back("the translation along x2");
  int null = 0, rotation = -1;
  for (int k = 0; k < 3; ++k) {
    if (eigen.eigenvalues()(k) > tolerance) continue;
    ++null;
    if (rotation < 0 ||
        std::abs(eigen.eigenvectors()(2, k)) > std::abs(eigen.eigenvectors()(2, rotation)))
      rotation = k;
  }
  if (null > int(x_free) + int(y_free)) {
    Eigen::Vector3d v = eigen.eigenvectors().col(rotation);
    if (x_free) v.x() = 0; // the free translations are listed already
    if (y_free) v.y() = 0;
    // The point the motion (a, b) + c (-(y - yc), x - xc) / L leaves fixed.
    const Eigen::Vector2d pivot = centre + size * Eigen::Vector2d(-v.y(), v.x()) / v.z();
    std::ostringstream motion;
    motion.precision(6);
    motion << "the rotation about (" << pivot.x() << ", " << pivot.y() << ")";
    motions.push_back(motion.str());
  }
  std::string text;
  for (std::size_t k = 0; k < motions.size(); ++k)
    text += (k == 0 ? "" : k + 1 == motions.size() ? " and " : ", ") + motions[k];
  return text;
}

void verify_rigid_motions_held(const Mesh& mesh, const std::vector<int>& dirichlet_dofs,
                               const std::string& deck) {
  const std::string free = free_rigid_motions(mesh, dirichlet_dofs);
  if (!free.empty())
    throw InputError(
        deck, 0, "",
        "the body is free to move: nothing holds " + free + " (" +
            std::to_string(dirichlet_dofs.size()) +
            " imposed dofs, no CONTACT card), so the static problem has no unique "
            "solution; add DIRICHLET cards (ux=, uy=) on references that hold the body");
}

} // namespace sig
