// The Equivalent Mass Matrix (3.54): no normal inertia at the contact nodes, with the total
// mass, the centre of mass, every second moment and the polar moment of the mass unchanged, for
// a flat contact side (normal (0, 1)) and for the bottom arc of a ring (radial normals), from
// the consistent and from the lumped mass.
#include "core/error.hpp"
#include "integrator/elastodynamics.hpp"
#include "integrator/emm.hpp"
#include "test_bodies.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace sig {
namespace {

struct Body {
  std::string name;
  Mesh mesh;
  ContactNormals contact;
};

Body flat_body() {
  Body b{"rectangle", test::perturbed_rectangle(2.0, 1.0, 10, 5), {}};
  b.contact.nodes = b.mesh.nodes_with_ref(3); // bottom side
  b.contact.normals.assign(b.contact.nodes.size(), Eigen::Vector2d(0.0, 1.0));
  return b;
}

// The ring of scene 8b's shape placed as in scene 8a (centre (100, 100)): large coordinates
// make the moments about the origin dwarf those about the centre of mass.
Body ring_body() {
  const Eigen::Vector2d c(100.0, 100.0);
  Body b{"ring", ring(c, 8.0, 10.0, 48), {}};
  for (int i : b.mesh.nodes_with_ref(3)) {
    b.contact.nodes.push_back(i);
    b.contact.normals.push_back((b.mesh.nodes[i] - c).normalized());
  }
  return b;
}

struct Case {
  Body body;
  bool lumped;
};

class Emm : public ::testing::TestWithParam<int> {
protected:
  void SetUp() override {
    c_.body = GetParam() / 2 == 0 ? flat_body() : ring_body();
    c_.lumped = GetParam() % 2 == 1;
    const LinearSystem s = test::free_body_system(c_.body.mesh, test::unit_material(1.0, 0.3, 7.5));
    M_ = c_.lumped ? diagonal_mass(s.M_lumped) : s.M;
    Me_ = equivalent_mass_matrix(M_, c_.body.mesh, c_.body.contact);
    ASSERT_GE(c_.body.contact.nodes.size(), 5u);
  }
  std::string label() const { return c_.body.name + (c_.lumped ? " lumped" : " consistent"); }
  // nu (or tau) at the two dofs of contact node number c.
  Eigen::VectorXd at_node(std::size_t c, const Eigen::Vector2d& w) const {
    Eigen::VectorXd x = Eigen::VectorXd::Zero(M_.rows());
    x.segment<2>(2 * c_.body.contact.nodes[c]) = w;
    return x;
  }
  Case c_;
  Eigen::SparseMatrix<double> M_, Me_;
};

TEST_P(Emm, KeepsMassCentreAndMomentsOfInertia) {
  const MassMoments before = mass_moments(M_, c_.body.mesh.nodes);
  const MassMoments after = mass_moments(Me_, c_.body.mesh.nodes);
  EXPECT_NEAR(after.mass, before.mass, 1e-12 * before.mass) << label();
  const double size = 10.0;
  EXPECT_LT((after.centre - before.centre).norm(), 1e-12 * (before.centre.norm() + size))
      << label();
  EXPECT_NEAR(after.polar, before.polar, 1e-12 * before.polar) << label();
  // Every moment of order <= 2, component by component, on its Cauchy-Schwarz scale.
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) {
      const double scale = std::sqrt(before.affine(i, i) * before.affine(j, j));
      EXPECT_NEAR(after.affine(i, j), before.affine(i, j), 1e-12 * scale)
          << label() << " G(" << i << "," << j << ")";
    }
  // The rectangle's mass, centre and polar moment by hand: uniform density 7.5 on [0,2]x[0,1].
  // P1 interpolates x exactly, so the consistent mass integrates the moments exactly whatever
  // the interior shift; lumping is exact up to the first moments only.
  if (c_.body.name == "rectangle") {
    const double m = 7.5 * 2.0;
    EXPECT_NEAR(after.mass, m, 1e-12 * m);
    EXPECT_LT((after.centre - Eigen::Vector2d(1.0, 0.5)).norm(), 1e-12);
    if (!c_.lumped) {
      EXPECT_NEAR(after.polar, m * (4.0 + 1.0) / 12, 1e-12 * m);
    }
  }

  // Removing the normal inertia without redistribution would not keep them: the test can fail.
  Eigen::SparseMatrix<double> Q(M_.rows(), M_.cols());
  Q.setIdentity();
  for (std::size_t c = 0; c < c_.body.contact.nodes.size(); ++c) {
    const Eigen::Vector2d& nu = c_.body.contact.normals[c];
    const Eigen::VectorXd n = at_node(c, nu);
    Q -= (n * n.transpose()).sparseView();
  }
  const Eigen::SparseMatrix<double> zeroed = Q * M_ * Q;
  EXPECT_GT(std::abs(mass_moments(zeroed, c_.body.mesh.nodes).mass - before.mass),
            1e-3 * before.mass);
}

TEST_P(Emm, ContactNodesHaveNoNormalInertia) {
  const auto& contact = c_.body.contact;
  const double scale = Eigen::VectorXd(M_.diagonal()).maxCoeff();
  const bool flat = c_.body.name == "rectangle";
  for (std::size_t c = 0; c < contact.nodes.size(); ++c) {
    const Eigen::VectorXd nu_i = at_node(c, contact.normals[c]);
    const Eigen::Vector2d tau(-contact.normals[c].y(), contact.normals[c].x());
    const Eigen::VectorXd Me_nu = Me_ * nu_i;
    // Flat side: the normal dofs are dofs of the matrix, exactly zero rows; curved side: zero
    // up to the rounding of nu.
    if (flat)
      EXPECT_EQ(Me_nu.lpNorm<Eigen::Infinity>(), 0.0) << label() << " node " << contact.nodes[c];
    else
      EXPECT_LT(Me_nu.lpNorm<Eigen::Infinity>(), 1e-14 * scale) << label();
    for (std::size_t d = 0; d < contact.nodes.size(); ++d)
      EXPECT_LE(std::abs(at_node(d, contact.normals[d]).dot(Me_nu)), 1e-14 * scale); // (3.54)
    // The tangential inertia stays.
    EXPECT_GT(at_node(c, tau).dot(Me_ * at_node(c, tau)), 0.1 * scale * (c_.lumped ? 1 : 0.1))
        << label();
  }
}

TEST_P(Emm, IsSymmetricPositiveSemidefiniteWithTheNormalsAsKernel) {
  const Eigen::MatrixXd D(Me_);
  EXPECT_EQ((D - D.transpose()).lpNorm<Eigen::Infinity>(), 0.0) << label();
  const Eigen::VectorXd eig = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(D).eigenvalues();
  const double top = eig.maxCoeff();
  EXPECT_GT(eig.minCoeff(), -1e-13 * top) << label();
  const auto kernel = (eig.array().abs() < 1e-12 * top).count();
  EXPECT_EQ(kernel, static_cast<Eigen::Index>(c_.body.contact.nodes.size())) << label();
}

INSTANTIATE_TEST_SUITE_P(BodiesAndMasses, Emm, ::testing::Range(0, 4), [](const auto& info) {
  return std::string(info.param / 2 == 0 ? "rectangle" : "ring") +
         (info.param % 2 ? "_lumped" : "_consistent");
});

TEST(EmmTransfer, WeightsAreAffineAndUseNonContactNodesOnly) {
  for (const Body& b : {flat_body(), ring_body()}) {
    const std::vector<MassTransfer> transfers = mass_transfers(b.mesh, b.contact);
    ASSERT_EQ(transfers.size(), b.contact.nodes.size());
    for (const MassTransfer& t : transfers) {
      EXPECT_NEAR(t.normal.norm(), 1.0, 1e-15);
      ASSERT_GE(t.receivers.size(), 3u);
      double sum = 0;
      Eigen::Vector2d x = Eigen::Vector2d::Zero();
      for (std::size_t r = 0; r < t.receivers.size(); ++r) {
        EXPECT_EQ(std::count(b.contact.nodes.begin(), b.contact.nodes.end(), t.receivers[r]), 0);
        sum += t.weights[r];
        x += t.weights[r] * (b.mesh.nodes[t.receivers[r]] - b.mesh.nodes[t.node]);
      }
      EXPECT_NEAR(sum, 1.0, 1e-13) << b.name;
      EXPECT_LT(x.norm(), 1e-12) << b.name;
    }
  }
}

TEST(EmmTransfer, RejectsImpossibleContactSets) {
  const Body b = flat_body();
  ContactNormals all;
  for (int i = 0; i < b.mesh.num_nodes(); ++i) {
    all.nodes.push_back(i);
    all.normals.emplace_back(0.0, 1.0);
  }
  EXPECT_THROW(mass_transfers(b.mesh, all), Error); // no receiver anywhere
  ContactNormals twice = b.contact;
  twice.nodes.push_back(twice.nodes.front());
  twice.normals.emplace_back(0.0, 1.0);
  EXPECT_THROW(mass_transfers(b.mesh, twice), Error);
  ContactNormals zero = b.contact;
  zero.normals.front().setZero();
  EXPECT_THROW(mass_transfers(b.mesh, zero), Error);
  ContactNormals outside = b.contact;
  outside.nodes.front() = b.mesh.num_nodes();
  EXPECT_THROW(mass_transfers(b.mesh, outside), Error);
}

} // namespace
} // namespace sig
