// The Equivalent Mass Matrix (integrator/emm.hpp, ALGORITHMS.md 4.3 (D)): no inertia at all at
// the contact nodes (3.54 and both components), the total mass, the centre of mass and every
// second moment of the mass (the polar moment among them) unchanged, symmetric and positive
// definite off Gamma3, on M's own pattern, for a flat contact side and for the whole outer
// circle of a ring, from the consistent and from the lumped mass; in 3D on a cube of tetrahedra.
#include "core/error.hpp"
#include "integrator/elastodynamics.hpp"
#include "integrator/emm.hpp"
#include "test_bodies.hpp"

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

namespace sig {
namespace {

struct Body {
  std::string name;
  Mesh mesh;
  std::vector<int> contact;
};

Body flat_body() {
  Body b{"rectangle", test::perturbed_rectangle(2.0, 1.0, 10, 10), {}};
  b.contact = b.mesh.nodes_with_ref(3); // bottom side
  return b;
}

// The ring of scene 8b, coarser, placed as in the thesis (centre (100, 100)): large coordinates
// make the moments about the origin dwarf those about the centre of mass; Gamma3 is the whole
// outer circle, as in scene 8b.
Body ring_body() {
  RingOptions options;
  options.layers = 5;
  options.gamma3_below = 1e9;
  options.gamma1_above = 1e9;
  Body b{"ring", ring({100.0, 100.0}, 9.0, 10.0, 48, options), {}};
  b.contact = b.mesh.nodes_with_ref(3);
  return b;
}

class Emm : public ::testing::TestWithParam<int> {
protected:
  void SetUp() override {
    body_ = GetParam() / 2 == 0 ? flat_body() : ring_body();
    lumped_ = GetParam() % 2 == 1;
    const LinearSystem s = test::free_body_system(body_.mesh, test::unit_material(1.0, 0.3, 7.5));
    M_ = lumped_ ? diagonal_mass(s.M_lumped) : s.M;
    Me_ = equivalent_mass_matrix(M_, node_positions(body_.mesh), body_.contact);
    ASSERT_GE(body_.contact.size(), 5u);
  }
  std::string label() const { return body_.name + (lumped_ ? " lumped" : " consistent"); }
  bool on_contact(Eigen::Index dof) const {
    return std::find(body_.contact.begin(), body_.contact.end(), dof / 2) != body_.contact.end();
  }
  Body body_;
  bool lumped_ = false;
  Eigen::SparseMatrix<double> M_, Me_;
};

TEST_P(Emm, KeepsMassCentreAndPolarMoment) {
  const MassMoments before = mass_moments(M_, plane_positions(body_.mesh));
  const MassMoments after = mass_moments(Me_, plane_positions(body_.mesh));
  EXPECT_NEAR(after.mass, before.mass, 1e-12 * before.mass) << label();
  // Every moment of order <= 2, component by component, on its Cauchy-Schwarz scale.
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) {
      const double scale = std::sqrt(before.affine(i, i) * before.affine(j, j));
      EXPECT_NEAR(after.affine(i, j), before.affine(i, j), 1e-12 * scale)
          << label() << " G(" << i << "," << j << ")";
    }
  const double size = 10.0;
  EXPECT_LT((after.centre - before.centre).norm(), 1e-12 * (before.centre.norm() + size))
      << label();
  EXPECT_NEAR(after.polar, before.polar, 1e-12 * before.polar) << label();
  // The rectangle's mass, centre and polar moment by hand: uniform density 7.5 on [0,2]x[0,1].
  // P1 interpolates x exactly, so the consistent mass integrates the moments exactly whatever
  // the interior shift; lumping is exact up to the first moments only.
  if (body_.name == "rectangle") {
    const double m = 7.5 * 2.0;
    EXPECT_NEAR(after.mass, m, 1e-12 * m);
    EXPECT_LT((after.centre - Eigen::Vector2d(1.0, 0.5)).norm(), 1e-12);
    if (!lumped_) {
      EXPECT_NEAR(after.polar, m * (4.0 + 1.0) / 12, 1e-12 * m);
    }
  }
  // Removing the inertia without redistribution would not keep them: the test can fail.
  Eigen::SparseMatrix<double> zeroed = M_;
  for (Eigen::Index j = 0; j < zeroed.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(zeroed, j); it; ++it)
      if (on_contact(it.row()) || on_contact(j)) it.valueRef() = 0;
  EXPECT_GT(before.mass - mass_moments(zeroed, plane_positions(body_.mesh)).mass,
            1e-3 * before.mass);
}

TEST_P(Emm, ContactNodesHaveNoInertiaAndThePatternIsM) {
  for (Eigen::Index j = 0; j < Me_.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(Me_, j); it; ++it) {
      if (on_contact(it.row()) || on_contact(j)) {
        EXPECT_EQ(it.value(), 0.0) << label() << " (" << it.row() << ", " << j << ")";
      }
      // M's nonzero pattern, and the same scalar mass in both directions.
      EXPECT_NE(M_.coeff(it.row(), j), 0.0) << label() << ": entry off M's pattern";
      EXPECT_EQ(it.row() % 2, j % 2) << label();
    }
}

TEST_P(Emm, IsSymmetricPositiveDefiniteOffGammaThree) {
  const Eigen::MatrixXd D(Me_);
  EXPECT_EQ((D - D.transpose()).lpNorm<Eigen::Infinity>(), 0.0) << label();
  const Eigen::VectorXd eig = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(D).eigenvalues();
  const double top = eig.maxCoeff();
  EXPECT_GT(eig.minCoeff(), -1e-13 * top) << label();
  const auto kernel = (eig.array().abs() < 1e-12 * top).count();
  EXPECT_EQ(kernel, static_cast<Eigen::Index>(2 * body_.contact.size())) << label();
}

INSTANTIATE_TEST_SUITE_P(BodiesAndMasses, Emm, ::testing::Range(0, 4), [](const auto& info) {
  return std::string(info.param / 2 == 0 ? "rectangle" : "ring") +
         (info.param % 2 ? "_lumped" : "_consistent");
});

TEST(Emm, RejectsImpossibleContactSets) {
  const Body b = flat_body();
  const LinearSystem s = test::free_body_system(b.mesh, test::unit_material());
  std::vector<int> all(static_cast<std::size_t>(b.mesh.num_nodes()));
  for (int i = 0; i < b.mesh.num_nodes(); ++i)
    all[static_cast<std::size_t>(i)] = i;
  EXPECT_THROW(equivalent_mass_matrix(s.M, node_positions(b.mesh), all),
               Error); // no mass left anywhere
  std::vector<int> twice = b.contact;
  twice.push_back(twice.front());
  EXPECT_THROW(equivalent_mass_matrix(s.M, node_positions(b.mesh), twice), Error);
  std::vector<int> outside = b.contact;
  outside.front() = b.mesh.num_nodes();
  EXPECT_THROW(equivalent_mass_matrix(s.M, node_positions(b.mesh), outside), Error);
  EXPECT_THROW(equivalent_mass_matrix(s.M, node_positions(b.mesh), {}), Error);
}

// A cube [0, 1]^3 of n^3 small cubes, each cut into the six tetrahedra of Kuhn's subdivision
// (positively oriented), one sub-domain.
Mesh kuhn_cube(int n) {
  Mesh mesh;
  mesh.dim = 3;
  const auto id = [n](int i, int j, int k) { return i + (n + 1) * (j + (n + 1) * k); };
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i)
        mesh.nodes.emplace_back(double(i) / n, double(j) / n, double(k) / n);
  const int paths[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (const auto& path : paths) {
          std::array<int, 3> at{i, j, k};
          std::array<int, 4> tet{};
          tet[0] = id(i, j, k);
          for (int step = 0; step < 3; ++step) {
            ++at[static_cast<std::size_t>(path[step])];
            tet[static_cast<std::size_t>(step) + 1] = id(at[0], at[1], at[2]);
          }
          const auto x = [&](int a) {
            return Eigen::Vector3d(
                mesh.nodes[static_cast<std::size_t>(tet[static_cast<std::size_t>(a)])]);
          };
          if ((x(1) - x(0)).cross(x(2) - x(0)).dot(x(3) - x(0)) < 0) std::swap(tet[2], tet[3]);
          mesh.cells.emplace_back(tet);
          mesh.subdomain.push_back(1);
        }
  return mesh;
}

// The EMM of a 3D body (issue 28): a cube of tetrahedra, Gamma3 a corner patch of its base x3 = 0
// (a contact zone: with the whole base, a tenth of the mass at n = 5, no positive definite mass of
// the pattern keeps even the mass and the centre, and the EMM says so). The ten moments
// of the scalar mass (1, x1, x2, x3 and their products) of every component kept, no inertia at
// the base nodes in any component, M's pattern with no coupling of components, symmetric and
// positive definite off Gamma3.
TEST(Emm, ThreeDimensionalCube) {
  const Mesh mesh = kuhn_cube(5);
  std::vector<int> base;
  for (int i = 0; i < mesh.num_nodes(); ++i) {
    const Point& x = mesh.nodes[static_cast<std::size_t>(i)];
    if (x.z() == 0.0 && x.x() < 0.5 && x.y() < 0.5) base.push_back(i);
  }
  ASSERT_EQ(base.size(), 9u);
  for (const bool lumped : {false, true}) {
    const LinearSystem s = test::free_body_system(mesh, test::unit_material(1.0, 0.3, 7.5));
    const Eigen::SparseMatrix<double> M = lumped ? diagonal_mass(s.M_lumped) : s.M;
    const Eigen::SparseMatrix<double> Me = equivalent_mass_matrix(M, node_positions(mesh), base);
    const int n = mesh.num_nodes();
    // The affine fields of component c: Phi_c = [e_c, x1 e_c, x2 e_c, x3 e_c].
    for (int c = 0; c < 3; ++c) {
      Eigen::MatrixXd Phi = Eigen::MatrixXd::Zero(3 * n, 4);
      for (int i = 0; i < n; ++i) {
        Phi(3 * i + c, 0) = 1.0;
        for (int a = 0; a < 3; ++a)
          Phi(3 * i + c, 1 + a) = mesh.nodes[static_cast<std::size_t>(i)][a];
      }
      const Eigen::MatrixXd before = Phi.transpose() * (M * Phi);
      const Eigen::MatrixXd after = Phi.transpose() * (Me * Phi);
      EXPECT_LT((after - before).cwiseAbs().maxCoeff(), 1e-12 * before(0, 0))
          << (lumped ? "lumped" : "consistent") << ", component " << c;
    }
    std::vector<char> on_base(static_cast<std::size_t>(n), 0);
    for (int i : base)
      on_base[static_cast<std::size_t>(i)] = 1;
    for (Eigen::Index j = 0; j < Me.outerSize(); ++j)
      for (Eigen::SparseMatrix<double>::InnerIterator it(Me, j); it; ++it) {
        if (on_base[static_cast<std::size_t>(it.row() / 3)] ||
            on_base[static_cast<std::size_t>(j / 3)]) {
          EXPECT_EQ(it.value(), 0.0) << "(" << it.row() << ", " << j << ")";
        }
        EXPECT_NE(M.coeff(it.row(), j), 0.0) << "entry off M's pattern";
        EXPECT_EQ(it.row() % 3, j % 3);
      }
    const Eigen::MatrixXd D(Me);
    EXPECT_EQ((D - D.transpose()).lpNorm<Eigen::Infinity>(), 0.0);
    const Eigen::VectorXd eig = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(D).eigenvalues();
    const double top = eig.maxCoeff();
    EXPECT_GT(eig.minCoeff(), -1e-13 * top);
    EXPECT_EQ((eig.array().abs() < 1e-12 * top).count(),
              static_cast<Eigen::Index>(3 * base.size()));
  }
}

} // namespace
} // namespace sig
