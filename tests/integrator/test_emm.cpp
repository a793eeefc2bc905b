// The Equivalent Mass Matrix (integrator/emm.hpp, ALGORITHMS.md 4.3 (D)): no inertia at all at
// the contact nodes (3.54 and both components), the total mass, the centre of mass and every
// second moment of the mass (the polar moment among them) unchanged, symmetric and positive
// definite off Gamma3, on M's own pattern, for a flat contact side and for the whole outer
// circle of a ring, from the consistent and from the lumped mass.
#include "core/error.hpp"
#include "integrator/elastodynamics.hpp"
#include "integrator/emm.hpp"
#include "test_bodies.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

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
    Me_ = equivalent_mass_matrix(M_, plane_positions(body_.mesh), body_.contact);
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
  EXPECT_THROW(equivalent_mass_matrix(s.M, plane_positions(b.mesh), all),
               Error); // no mass left anywhere
  std::vector<int> twice = b.contact;
  twice.push_back(twice.front());
  EXPECT_THROW(equivalent_mass_matrix(s.M, plane_positions(b.mesh), twice), Error);
  std::vector<int> outside = b.contact;
  outside.front() = b.mesh.num_nodes();
  EXPECT_THROW(equivalent_mass_matrix(s.M, plane_positions(b.mesh), outside), Error);
  EXPECT_THROW(equivalent_mass_matrix(s.M, plane_positions(b.mesh), {}), Error);
}

} // namespace
} // namespace sig
