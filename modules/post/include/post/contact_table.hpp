#pragma once
// The contact table of a solved case: one row per node-to-rigid contact element, in the order of
// case.cont (the boundary order of Gamma3), with the state the solver ended in. Signs follow
// contact/contact_elements.hpp: u_n = -n . u is positive towards the obstacle, the gap is
// d - u_n (negative: penetration), the multiplier is the nodal normal contact force (>= 0 when
// pressing), the slip u_t = t . u with t = (n2, -n1), the tangential multiplier the nodal
// tangential force T (the force on the body is -T t: it opposes the slip).
#include "contact/contact_status.hpp"
#include "core/ds.hpp"
#include "mesh/mesh.hpp"
#include "post/hertz.hpp"

#include <array>
#include <string>
#include <vector>

namespace sig {

struct ContactRow {
  int node = 0; ///< 1-based mesh node
  int dim = 2;  ///< the mesh's: x3 and u3 are 0 in 2D
  double x1 = 0, x2 = 0, x3 = 0;
  double u1 = 0, u2 = 0, u3 = 0;
  double gap = 0;        ///< current normal gap d - u_n, u_n = -n . u (n: obstacle normal)
  double multiplier = 0; ///< nodal normal contact force
  double pressure = 0;   ///< multiplier / weight (tributary length)
  double weight = 0;
  bool contact = false; ///< normal status not free (status 1 of case.b)
  NormalStatus normal_status = NormalStatus::free;
  FrictionStatus friction_status = FrictionStatus::none;
  double tangential_multiplier = 0; ///< nodal tangential force T
  double tangential_pressure = 0;   ///< T / weight
  double slip = 0;                  ///< u_t = t . u (3D: |u_t|, u_t = u - (n . u) n)
  /// 3D: u_t and the tangential force T1 t1 + T2 t2 in global axes
  std::array<double, 3> slip_vector{}, tangential_force{};
};

/// Join case.cont (node, normal, tangent, gap, weight) with case.b (u, multiplier,
/// tangential_multiplier, normal_status, friction_status). Throws sig::Error naming the file when
/// arrays disagree in length or hold a node or status code out of range.
std::vector<ContactRow> contact_rows(const Mesh& mesh, const Ds& cont, const Ds& solution);

/// contact.csv: header `node,x1,x2,u1,u2,gap,multiplier,pressure,status,normal_status,
/// friction_status,tangential_multiplier,tangential_pressure,slip,converged`; in 3D x3 after x2,
/// u3 after u2, and slip_1..3, tangential_force_1..3 (global axes) before converged, the scalar
/// tangential_multiplier, tangential_pressure and slip then their magnitudes. The status is
/// written as the word `contact`, `free` or `held` (a Dirichlet condition holds the normal
/// component), the statuses as the thesis's labels (free, CN, CU, held; -, S=, S+, S-), numbers
/// with 17 significant digits; `converged` is 0 on every row of a solve that did not converge
/// (Nv), so that no row reads as a result.
std::string contact_csv(const std::vector<ContactRow>& rows, bool converged);

/// The rows as Hertz samples, x measured from the vertical line x1 = centre_x1.
std::vector<PressureSample> pressure_samples(const std::vector<ContactRow>& rows, double centre_x1);

} // namespace sig
