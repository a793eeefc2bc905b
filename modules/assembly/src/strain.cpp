#include "assembly/strain.hpp"

#include "assembly/p1.hpp"
#include "assembly/p1_simplex.hpp"
#include "core/error.hpp"
#include "material/mili.hpp"
#include "mesh/mesh.hpp"

#include <cmath>

namespace sig {

std::vector<Eigen::Vector3d> element_strains(const Mesh& mesh, const Eigen::VectorXd& u) {
  SIG_VERIFY(u.size() == 2 * mesh.num_nodes(),
             "element_strains: " << u.size() << " values for " << mesh.num_nodes() << " nodes");
  std::vector<Eigen::Vector3d> strains(mesh.cells.size());
  for (int t = 0; t < mesh.num_cells(); ++t) {
    Vector6d ue;
    for (int i = 0; i < 3; ++i)
      ue.segment<2>(2 * i) = u.segment<2>(2 * mesh.cells[t][i]);
    strains[t] = p1_strain_matrix(p1_gradients(triangle_vertices(mesh, t))) * ue;
  }
  return strains;
}

double strain_norm(const Mesh& mesh, const Eigen::VectorXd& u) {
  return strain_norm(mesh, u, [](int) { return true; });
}

namespace {

/// The integral of eps : eps over the counted cells of a mesh of dimension d.
template <int d>
double squared_strain_norm(const Mesh& mesh, const Eigen::VectorXd& u,
                           const std::function<bool(int)>& counts) {
  constexpr int shears = voigt_size(d) - d;
  double sum = 0;
  for (int t = 0; t < mesh.num_cells(); ++t) {
    if (!counts(t)) continue;
    const SimplexVertices<d> x = simplex_vertices<d>(mesh, t);
    SimplexVector<d> ue;
    for (int i = 0; i <= d; ++i)
      ue.template segment<d>(d * i) = u.segment<d>(d * mesh.cells[t][i]);
    const Eigen::Matrix<double, voigt_size(d), 1> e =
        p1_simplex_strain_matrix<d>(p1_simplex_gradients<d>(x)) * ue;
    // Voigt with engineering shears: eps : eps = the normal components squared plus half of
    // each shear squared (2D: e11^2 + e22^2 + 2 e12^2).
    sum += std::abs(p1_measure<d>(x)) *
           (e.template head<d>().squaredNorm() + 0.5 * e.template tail<shears>().squaredNorm());
  }
  return sum;
}

} // namespace

double strain_norm(const Mesh& mesh, const Eigen::VectorXd& u,
                   const std::function<bool(int)>& counts) {
  SIG_VERIFY(u.size() == mesh.dim * mesh.num_nodes(),
             "strain_norm: " << u.size() << " values for " << mesh.num_nodes() << " nodes in "
                             << mesh.dim << "D");
  return std::sqrt(with_dimension(mesh.dim, [&](auto dim) {
    return squared_strain_norm<decltype(dim)::value>(mesh, u, counts);
  }));
}

std::vector<Eigen::Vector3d> element_stresses(const Mesh& mesh, const MaterialTable& table,
                                              const Eigen::VectorXd& u) {
  std::vector<Eigen::Vector3d> stresses = element_strains(mesh, u);
  for (int t = 0; t < mesh.num_cells(); ++t)
    stresses[t] = table.of(mesh.subdomain[t]).hooke.stress(stresses[t]);
  return stresses;
}

} // namespace sig
