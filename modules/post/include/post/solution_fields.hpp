#pragma once
// What a solved static case shows in ParaView: displacement (z = 0) and, on Gamma3, the contact
// pressure and status at the nodes; stress, von Mises and sub-domain on the triangles.
#include "material/mili.hpp"
#include "mesh/mesh.hpp"
#include "post/contact_table.hpp"
#include "post/vtk_writer.hpp"

#include <vector>

namespace sig {

struct SolutionFields {
  std::vector<VtkField> point; ///< displacement (3), [contact_pressure, contact_status]
  std::vector<VtkField> cell;  ///< stress (4: s11, s22, s12, s33), von_mises, subdomain
};

/// The fields of one state; contact fields only when `contact` is not empty, 0 off Gamma3
/// (status 1 = contact, 0 = free or not on Gamma3). A 3D mesh's are solution_fields_3d's.
SolutionFields solution_fields(const Mesh& mesh, const std::vector<double>& u,
                               const MaterialTable& materials,
                               const std::vector<ContactRow>& contact);

/// The fields of a 3D static state (solution_fields_3d.cpp): displacement (3) and the contact
/// fields of solution_fields at the nodes; stress (6: s11, s22, s33, s23, s13, s12), von_mises
/// and subdomain on the tetrahedra.
SolutionFields solution_fields_3d(const Mesh& mesh, const std::vector<double>& u,
                                  const MaterialTable& materials,
                                  const std::vector<ContactRow>& contact = {});

/// The contact fields at the n nodes (contact_pressure, contact_status, normal_status,
/// friction_status, tangential_pressure; in 3D also the vectors tangential_traction and slip;
/// 0 off Gamma3), none when `contact` is empty.
void add_contact_fields(SolutionFields& f, std::size_t n, const std::vector<ContactRow>& contact);

/// The stored energy sum over the tetrahedra of |T| eps.D.eps / 2 of a 3D state.
double strain_energy_3d(const Mesh& mesh, const std::vector<double>& u,
                        const MaterialTable& materials);

} // namespace sig
