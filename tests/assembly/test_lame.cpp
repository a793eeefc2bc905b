// Convergence on Lame's thick cylinder: a quarter of the ring 1 <= r <= 2 under internal
// pressure p, plane strain, with the symmetry conditions u1 = 0 on x1 = 0 and u2 = 0 on x2 = 0.
// The exact solution is radial, u_r = (1 + nu)/E ((1 - 2 nu) C1 r + C2 / r) with
// C1 = p a^2 / (b^2 - a^2), C2 = p a^2 b^2 / (b^2 - a^2) (sigma_rr = C1 - C2 / r^2, so
// sigma_rr(a) = -p, sigma_rr(b) = 0). P1 errors must fall as h in the energy norm and as h^2 in
// L2; both are integrated with a high-order rule on each triangle.
#include "assembly/dirichlet.hpp"
#include "assembly/p1.hpp"
#include "assembly/strain.hpp"
#include "assembly/system.hpp"
#include "core/datafile.hpp"
#include "material/mili.hpp"
#include "test_meshes.hpp"

#include <Eigen/SparseCholesky>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

namespace sig {
namespace {

constexpr double a = 1.0, b = 2.0, p = 1.0, E = 1.0, nu = 0.3;
constexpr double C1 = p * a * a / (b * b - a * a);
constexpr double C2 = p * a * a * b * b / (b * b - a * a);

Eigen::Vector2d exact_u(const Eigen::Vector2d& x) {
  const double r = x.norm();
  const double ur = (1 + nu) / E * ((1 - 2 * nu) * C1 * r + C2 / r);
  return ur * x / r;
}

// Engineering strain (e11, e22, 2 e12) of the exact solution.
Eigen::Vector3d exact_strain(const Eigen::Vector2d& x) {
  const double r = x.norm(), c = x.x() / r, s = x.y() / r;
  const double err = (1 + nu) / E * ((1 - 2 * nu) * C1 - C2 / (r * r));
  const double ett = (1 + nu) / E * ((1 - 2 * nu) * C1 + C2 / (r * r));
  return {err * c * c + ett * s * s, err * s * s + ett * c * c, 2 * (err - ett) * s * c};
}

// A collapsed (Duffy) Gauss rule with 6 x 6 points on the reference triangle, exact well beyond
// the degree needed here; points as barycentric weights of vertices 1 and 2, weights sum to 1/2.
struct Quadrature {
  std::vector<std::array<double, 3>> points; // (l1, l2, w)
  Quadrature() {
    const double x[6] = {-0.9324695142031521, -0.6612093864662645, -0.2386191860831969,
                         0.2386191860831969,  0.6612093864662645,  0.9324695142031521};
    const double w[6] = {0.1713244923791704, 0.3607615730481386, 0.4679139345726910,
                         0.4679139345726910, 0.3607615730481386, 0.1713244923791704};
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j) {
        const double s = 0.5 * (x[i] + 1), t = 0.5 * (x[j] + 1);
        points.push_back({s, t * (1 - s), 0.25 * w[i] * w[j] * (1 - s)});
      }
  }
};

struct Errors {
  double h, energy, l2;
};

Errors solve_and_measure(int nr, int nt) {
  const Mesh mesh = test::quarter_ring_mesh(nr, nt, a, b);
  const Datafile datafile = Datafile::parse("MATERIAL law=hooke E=1 nu=0.3 plane=strain\n"
                                            "PRESSURE ref=1 p=1\n"
                                            "DIRICHLET ref=3 uy=0\n"
                                            "DIRICHLET ref=4 ux=0\n",
                                            "lame.dat");
  const MaterialTable table = material_table_from_cards(datafile, mesh);
  const LinearSystem system = assemble_system(mesh, table, datafile);
  const ReducedSystem reduced = reduce(system);
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(reduced.K);
  EXPECT_EQ(ldlt.info(), Eigen::Success);
  const Eigen::VectorXd u = reduced.expand(ldlt.solve(reduced.f));

  const Eigen::Matrix3d D = table.of(1).hooke.D();
  const std::vector<Eigen::Vector3d> strains = element_strains(mesh, u);
  const Quadrature rule;
  double energy2 = 0, l2 = 0, h = 0;
  for (int t = 0; t < mesh.num_cells(); ++t) {
    const Matrix23 x = triangle_vertices(mesh, t);
    const double area = p1_area(x);
    for (int i = 0; i < 3; ++i)
      h = std::max(h, (x.col(i) - x.col((i + 1) % 3)).norm());
    for (const auto& [l1, l2w, w] : rule.points) {
      const Eigen::Vector3d lambda(1 - l1 - l2w, l1, l2w);
      const Eigen::Vector2d point = x * lambda;
      Eigen::Vector2d uh = Eigen::Vector2d::Zero();
      for (int i = 0; i < 3; ++i)
        uh += lambda(i) * u.segment<2>(2 * mesh.cells[t][i]);
      const Eigen::Vector3d de = exact_strain(point) - strains[t];
      energy2 += 2 * area * w * de.dot(D * de);
      l2 += 2 * area * w * (exact_u(point) - uh).squaredNorm();
    }
  }
  return {h, std::sqrt(energy2), std::sqrt(l2)};
}

TEST(Lame, ThickCylinderConvergesAtOrderOneInEnergyAndTwoInL2) {
  const std::array<Errors, 3> e = {solve_and_measure(4, 6), solve_and_measure(8, 12),
                                   solve_and_measure(16, 24)};
  for (int k = 0; k < 2; ++k) {
    const double ratio = std::log(e[k].h / e[k + 1].h);
    const double energy_slope = std::log(e[k].energy / e[k + 1].energy) / ratio;
    const double l2_slope = std::log(e[k].l2 / e[k + 1].l2) / ratio;
    EXPECT_GE(energy_slope, 0.85) << "meshes " << k << "-" << k + 1;
    EXPECT_LE(energy_slope, 1.2) << "meshes " << k << "-" << k + 1;
    EXPECT_GE(l2_slope, 1.8) << "meshes " << k << "-" << k + 1;
    EXPECT_LE(l2_slope, 2.3) << "meshes " << k << "-" << k + 1;
    std::printf("h %.4f -> %.4f: energy error %.3e -> %.3e (slope %.3f), L2 %.3e -> %.3e "
                "(slope %.3f)\n",
                e[k].h, e[k + 1].h, e[k].energy, e[k + 1].energy, energy_slope, e[k].l2,
                e[k + 1].l2, l2_slope);
  }
  // The error is small against the solution itself: |u(a)| = 1.3 (0.4/3 + 4/3) ~ 1.91.
  EXPECT_LT(e[2].l2, 1e-2);
}

} // namespace
} // namespace sig
