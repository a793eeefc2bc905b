// The assembled system of a 3D body (issue 26): loads on faces and tetrahedra with their exact
// resultants, three Dirichlet components, the 2D fields refused, the stiffness's kernel the six
// rigid motions.
#include "assembly/system.hpp"
#include "core/datafile.hpp"
#include "core/error.hpp"
#include "material/mili.hpp"
#include "mesh/gmsh.hpp"
#include "mesh/mesh.hpp"
#include "two_triangles.hpp"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <sstream>

#include <filesystem>
#include <string>

namespace sig {
namespace {

// The unit cube of gmsh's tetrahedra: faces ref 1 the base x3 = 0, 2 the top, 3 the sides.
Mesh cube() {
  return read_gmsh(std::filesystem::path(SIG_SOURCE_DIR) / "tests" / "fuzz" / "corpus" / "gmsh" /
                   "box_v41_ascii.msh");
}

LinearSystem assemble(const Mesh& mesh, const std::string& deck) {
  const Datafile datafile = Datafile::parse("MATERIAL law=hooke E=200 nu=0.3\n" + deck, "c.dat");
  return assemble_system(mesh, material_table_from_cards(datafile, mesh), datafile);
}

Eigen::Vector3d resultant(const Eigen::VectorXd& f) {
  return Eigen::Map<const Eigen::Matrix<double, 3, Eigen::Dynamic>>(f.data(), 3, f.size() / 3)
      .rowwise()
      .sum();
}

TEST(System3d, LoadResultants) {
  const Mesh mesh = cube();
  // Body force on the unit volume, traction on the unit top, pressure on the closed sides.
  const LinearSystem s = assemble(mesh, "BODYFORCE f=0,0,-2\nTRACTION ref=2 f=1,2,3\n");
  EXPECT_LT((resultant(s.f) - Eigen::Vector3d(1, 2, 1)).norm(), 1e-12);
  EXPECT_EQ(s.num_dofs(), 3 * mesh.num_nodes());
  // A pressure pushes each side inward: the four sides' resultants cancel, the top's is -p.
  EXPECT_LT(resultant(assemble(mesh, "PRESSURE ref=3 p=5\n").f).norm(), 1e-12);
  EXPECT_LT(
      (resultant(assemble(mesh, "PRESSURE ref=2 p=5\n").f) - Eigen::Vector3d(0, 0, -5)).norm(),
      1e-12);
}

TEST(System3d, DirichletTakesThreeComponents) {
  const Mesh mesh = cube();
  const LinearSystem s = assemble(mesh, "DIRICHLET ref=1 uz=0.5\nDIRICHLET ref=2 ux=0 uy=0\n");
  const int base = static_cast<int>(mesh.nodes_with_ref(1).size());
  const int top = static_cast<int>(mesh.nodes_with_ref(2).size());
  EXPECT_EQ(static_cast<int>(s.dirichlet_dofs.size()), base + 2 * top);
  for (std::size_t k = 0; k < s.dirichlet_dofs.size(); ++k) {
    if (s.dirichlet_dofs[k] % 3 == 2) {
      EXPECT_EQ(s.dirichlet_values[static_cast<Eigen::Index>(k)], 0.5);
    }
  }
}

TEST(System3d, TheStiffnessHoldsNoRigidMotionButItsKernel) {
  const Mesh mesh = cube();
  const LinearSystem s = assemble(mesh, "");
  Eigen::VectorXd u(3 * mesh.num_nodes());
  for (int m = 0; m < 6; ++m) {
    for (int i = 0; i < mesh.num_nodes(); ++i) {
      const Eigen::Vector3d x = mesh.nodes[i];
      u.segment<3>(3 * i) = m < 3 ? Eigen::Vector3d(Eigen::Vector3d::Unit(m))
                                  : Eigen::Vector3d(Eigen::Vector3d::Unit(m - 3).cross(x));
    }
    EXPECT_LT((s.K * u).norm(), 1e-10 * s.K.norm()) << "motion " << m;
  }
  EXPECT_LT((Eigen::MatrixXd(s.K) - Eigen::MatrixXd(s.K).transpose()).norm(), 1e-12 * s.K.norm());
}

TEST(System3d, TwoDimensionalFieldsAreRefused) {
  const Mesh mesh = cube();
  EXPECT_THROW(assemble(mesh, "BODYFORCE f=0,-1\n"), InputError);
  EXPECT_THROW(assemble(mesh, "TRACTION ref=2 f=0,-1 ramp=1\n"), InputError);
  const Datafile plane = Datafile::parse("MATERIAL law=hooke E=1 nu=0.3 plane=stress\n", "p.dat");
  EXPECT_THROW(material_table_from_cards(plane, mesh), InputError);
  // The hyperelastic laws and Kelvin-Voigt's are written on the 3D tensors: a 3D body takes them
  // (issue 28; the viscous operator: ViscoelasticSystem3d below).
  const Datafile svk = Datafile::parse("MATERIAL law=svk E=1 nu=0.3\n", "s.dat");
  EXPECT_TRUE(material_table_from_cards(svk, mesh).entries.front().hyperelastic);
  // And the other way round: a 2D deck has no uz.
  Mesh square = test::two_triangle_square();
  square.facets.push_back({{0, 1}, 1});
  EXPECT_NO_THROW(assemble(square, "DIRICHLET ref=1 ux=0 uy=0\n"));
  EXPECT_THROW(assemble(square, "DIRICHLET ref=1 ux=0 uz=0\n"), InputError);
}

// Kelvin-Voigt on a 3D body (issue 28): the viscosity A (eta1, eta2) is Hooke's 3D operator with
// the Lame constants (eta1, eta2 / 2), a memory term's matrix its tensor's 3D stiffness; a
// ramped traction's rate is the constant traction's load over the ramp, f itself then 0.
TEST(ViscoelasticSystem3d, ViscosityMemoryAndRampedLoad) {
  const Mesh mesh = cube();
  const double E = 100, nu = 0.3;
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  std::ostringstream deck;
  deck.precision(17);
  deck << "MATERIAL law=kelvin-voigt E=7 nu=0.2 eta1=" << lambda << " eta2=" << 2 * mu << "\n"
       << "MEMORY E=20 nu=0.1 beta=10\nTRACTION ref=2 f=1,2,-3 ramp=0.5\n";
  // assemble() gives its deck a Hooke law: these decks carry their own.
  const auto own = [&mesh](const std::string& text) {
    const Datafile datafile = Datafile::parse(text, "v.dat");
    return assemble_system(mesh, material_table_from_cards(datafile, mesh), datafile);
  };
  const LinearSystem kv = own(deck.str());
  const LinearSystem hooke = own("MATERIAL E=100 nu=0.3\nTRACTION ref=2 f=1,2,-3\n");
  EXPECT_LT((kv.V - hooke.K).norm(), 1e-12 * hooke.K.norm());
  EXPECT_LT((kv.K - own("MATERIAL E=7 nu=0.2\n").K).norm(), 1e-12 * kv.K.norm());
  ASSERT_EQ(kv.memory.size(), 1u);
  EXPECT_EQ(kv.memory[0].beta, 10);
  const LinearSystem memory = own("MATERIAL E=20 nu=0.1\n");
  EXPECT_LT((kv.memory[0].K - memory.K).norm(), 1e-12 * memory.K.norm());
  EXPECT_EQ(kv.f.norm(), 0.0);
  ASSERT_EQ(kv.time_loads.rate.size(), hooke.f.size());
  EXPECT_LT((0.5 * kv.time_loads.rate - hooke.f).norm(), 1e-14 * hooke.f.norm());
  EXPECT_GT(hooke.f.norm(), 0.0);
}

} // namespace
} // namespace sig
