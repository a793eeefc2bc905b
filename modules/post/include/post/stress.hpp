#pragma once
// Stresses for the ParaView output: the P1 strain (or deformation gradient) is constant on each
// triangle, and the law of the triangle's sub-domain (MILI) turns it into a stress: Hooke's, with
// sigma33 for plane strain, or the Cauchy stress of a hyperelastic law.
#include "material/mili.hpp"
#include "mesh/mesh.hpp"

#include <Eigen/Core>
#include <vector>

namespace sig {

/// Small strain (e11, e22, 2 e12) of triangle t for interleaved nodal displacements
/// u = (u1, u2) per node.
Eigen::Vector3d triangle_strain(const Mesh& mesh, const std::vector<double>& u, int t);

struct CellStress {
  std::vector<double> stress;    ///< 4 per triangle: s11, s22, s12, s33 (0 in plane stress)
  std::vector<double> von_mises; ///< 1 per triangle
};

/// Stress on every triangle. Throws sig::Error if a sub-domain has no material or u has the
/// wrong size.
CellStress cell_stresses(const Mesh& mesh, const std::vector<double>& u,
                         const MaterialTable& materials);

/// Strain energy: sum over triangles of W x area x thickness (W(eps) of Hooke, 1/2 a(u, u), or
/// W(F) of a hyperelastic law); with the work of
/// the loads it gives the total potential energy, whose differences between meshes measure the
/// energy-norm error (the thesis's Fig 7.10 is an error in the norm of V).
double strain_energy(const Mesh& mesh, const std::vector<double>& u,
                     const MaterialTable& materials);

} // namespace sig
