// The rigid motions of a 3D body left free by its Dirichlet dofs (issue 26): the six motions u(x)
// = a + w x (x - c) of the whole body must be held. The 2D analysis (rigid_motion.cpp) also
// splits the mesh into parts joined by single nodes; in 3D the body is taken whole.
#include "assembly/rigid_motion.hpp"
#include "core/error.hpp"
#include "mesh/mesh.hpp"

#include <Eigen/Dense>
#include <sstream>

namespace sig {

void verify_rigid_motions_held_3d(const Mesh& mesh, const std::vector<int>& dirichlet_dofs,
                                  const std::string& deck, const std::vector<int>& contact_nodes,
                                  const std::vector<Point>& contact_normals, bool friction) {
  SIG_VERIFY(contact_nodes.size() == contact_normals.size(),
             "verify_rigid_motions_held_3d: " << contact_nodes.size() << " contact nodes with "
                                              << contact_normals.size() << " normals");
  SIG_VERIFY(mesh.dim == 3, "verify_rigid_motions_held_3d: the mesh is " << mesh.dim << "D");
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const Point& x : mesh.nodes)
    centre += Eigen::Vector3d(x);
  centre /= mesh.num_nodes();
  const double size = std::max(diameter(mesh), 1e-300);
  // Row per hold (node n along the unit direction e): e . (the six motions at x_n); the motions
  // are held when this matrix has rank 6.
  // A frictional contact node holds its tangent plane too (the static solve condenses its
  // slips): three directions.
  const std::size_t per_node = friction ? 3 : 1;
  const auto rows =
      static_cast<Eigen::Index>(dirichlet_dofs.size() + per_node * contact_nodes.size());
  Eigen::MatrixXd R(rows, 6);
  const auto hold = [&](Eigen::Index r, int node, const Eigen::Vector3d& e) {
    const Eigen::Vector3d x = (Eigen::Vector3d(mesh.nodes[node]) - centre) / size;
    for (int k = 0; k < 3; ++k) {
      R(r, k) = e[k];
      R(r, 3 + k) = e.dot(Eigen::Vector3d::Unit(k).cross(x));
    }
  };
  Eigen::Index r = 0;
  for (const int dof : dirichlet_dofs)
    hold(r++, dof / 3, Eigen::Vector3d::Unit(dof % 3));
  for (std::size_t p = 0; p < contact_nodes.size(); ++p) {
    const Eigen::Vector3d n(contact_normals[p]);
    hold(r++, contact_nodes[p], n);
    if (friction) {
      const Eigen::Vector3d t = n.unitOrthogonal();
      hold(r++, contact_nodes[p], t);
      hold(r++, contact_nodes[p], n.cross(t));
    }
  }
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(R, Eigen::ComputeFullV);
  const Eigen::VectorXd sigma = svd.singularValues();
  const Eigen::Index rank = (sigma.array() > 1e-8).count();
  if (rank == 6) return;
  const Eigen::VectorXd free = svd.matrixV().col(5); // the motion held least
  std::ostringstream what;
  what << "the body is free to move: the " << dirichlet_dofs.size() << " imposed dofs";
  if (!contact_nodes.empty())
    what << " and " << contact_nodes.size() << " contact nodes"
         << (friction ? "" : " (frictionless: along their normals)");
  what << " leave the rigid motion of translation (" << free(0) << ", " << free(1) << ", "
       << free(2) << ") and rotation (" << free(3) << ", " << free(4) << ", " << free(5)
       << ") free, so the static problem has no unique solution; add DIRICHLET cards (ux=, uy=, "
          "uz=) on references that hold the body";
  throw InputError(deck, 0, "", what.str());
}

} // namespace sig
