// ParaView output of a 3D case (issue 26): tetrahedra (VTK_TETRA) with their x3, the
// displacement's three components, the stress tensor's six and von Mises, read back by VTK.
#include "material/mili.hpp"
#include "mesh/gmsh.hpp"
#include "post/solution_fields.hpp"
#include "post/vtk_writer.hpp"
#include "post_test_mesh.hpp"
#include "scratch_folder.hpp"

#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>

#include <filesystem>

namespace sig {
namespace {

/// The unit cube of the gmsh fuzz corpus, tetrahedra of sub-domain 1.
Mesh box() {
  return read_gmsh(std::filesystem::path(SIG_SOURCE_DIR) / "tests" / "fuzz" / "corpus" / "gmsh" /
                   "box_v41_ascii.msh");
}

/// Hooke's law E = 200, nu = 0.25 on sub-domain 1.
MaterialTable steel() {
  MaterialTable materials;
  SubdomainMaterial steel;
  steel.subdomain = 1;
  steel.hooke.E = 200;
  steel.hooke.nu = 0.25;
  materials.entries.push_back(steel);
  return materials;
}

TEST(Vtk3d, TetrahedraWithTheirStressTensor) {
  const Mesh mesh = box();
  const MaterialTable materials = steel();
  // u = (0, 0, -0.01 x3): a uniaxial strain e33 = -0.01, the stress of Hooke's 3D law.
  std::vector<double> u(3 * mesh.num_nodes(), 0.0);
  for (int i = 0; i < mesh.num_nodes(); ++i)
    u[3 * i + 2] = -0.01 * mesh.nodes[i].z();
  const SolutionFields fields = solution_fields_3d(mesh, u, materials);
  const testing::ScratchFolder scratch;
  const auto path = scratch.path() / "box_0000.vtu";
  write_vtu(path, mesh, fields.point, fields.cell, {{"title", "a cube"}});

  const auto grid = test::read_vtu(path);
  ASSERT_EQ(grid->GetNumberOfCells(), mesh.num_cells());
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
    ASSERT_EQ(grid->GetCellType(c), VTK_TETRA);
  double p[3];
  grid->GetPoint(mesh.num_nodes() - 1, p);
  EXPECT_EQ(p[2], mesh.nodes.back().z());
  EXPECT_EQ(grid->GetPointData()->GetArray("displacement")->GetNumberOfComponents(), 3);
  vtkDataArray* stress = grid->GetCellData()->GetArray("stress");
  ASSERT_EQ(stress->GetNumberOfComponents(), 6);
  const double lambda = 200 * 0.25 / (1.25 * 0.5), mu = 200 / 2.5;
  const double expected[6] = {-0.01 * lambda, -0.01 * lambda, -0.01 * (lambda + 2 * mu), 0, 0, 0};
  for (vtkIdType c = 0; c < stress->GetNumberOfTuples(); ++c)
    for (int k = 0; k < 6; ++k)
      EXPECT_NEAR(stress->GetComponent(c, k), expected[k], 1e-12) << c << " " << k;
  // von Mises of the uniaxial strain: |s33 - s11| = 2 mu 0.01.
  EXPECT_NEAR(grid->GetCellData()->GetArray("von_mises")->GetComponent(0, 0), 2 * mu * 0.01, 1e-12);
}

// A contact node's tangential traction and slip in 3D are vectors of the tangent plane: written
// as 3-component point fields (per unit area, global axes) beside their magnitudes.
TEST(Vtk3d, ContactNodesCarryTheirTangentialTractionAndSlipAsVectors) {
  const Mesh mesh = box();
  const MaterialTable materials = steel();
  ContactRow row;
  row.dim = 3;
  row.node = 2;
  row.weight = 0.5;
  row.tangential_force = {0.3, -0.4, 0.0};
  row.tangential_multiplier = 0.5;
  row.tangential_pressure = 1.0;
  row.slip_vector = {1e-3, 2e-3, 0.0};
  const std::vector<double> u(3 * mesh.num_nodes(), 0.0);
  const SolutionFields fields = solution_fields_3d(mesh, u, materials, {row});
  const testing::ScratchFolder scratch;
  const auto path = scratch.path() / "box_0000.vtu";
  write_vtu(path, mesh, fields.point, fields.cell, {{"title", "a cube"}});

  const auto grid = test::read_vtu(path);
  vtkDataArray* traction = grid->GetPointData()->GetArray("tangential_traction");
  vtkDataArray* slip = grid->GetPointData()->GetArray("slip");
  ASSERT_NE(traction, nullptr);
  ASSERT_NE(slip, nullptr);
  ASSERT_EQ(traction->GetNumberOfComponents(), 3);
  ASSERT_EQ(slip->GetNumberOfComponents(), 3);
  EXPECT_DOUBLE_EQ(traction->GetComponent(1, 0), 0.6);
  EXPECT_DOUBLE_EQ(traction->GetComponent(1, 1), -0.8);
  EXPECT_DOUBLE_EQ(slip->GetComponent(1, 1), 2e-3);
  EXPECT_EQ(traction->GetComponent(0, 0), 0.0); // not a contact node
  EXPECT_DOUBLE_EQ(grid->GetPointData()->GetArray("tangential_pressure")->GetComponent(1, 0), 1.0);
}

} // namespace
} // namespace sig
