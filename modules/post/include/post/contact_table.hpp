#pragma once
// The contact table of a solved case: one row per node-to-rigid contact element, in the order of
// case.cont (the boundary order of Gamma3), with the state the solver ended in. Signs follow
// contact/contact_elements.hpp: u_n = -n . u is positive towards the obstacle, Signorini reads
// u_n <= g, and the multiplier is the nodal contact force (>= 0 when pressing).
#include "core/ds.hpp"
#include "mesh/mesh.hpp"
#include "post/hertz.hpp"

#include <string>
#include <vector>

namespace sig {

struct ContactRow {
  int node = 0; ///< 1-based mesh node
  double x1 = 0, x2 = 0;
  double u1 = 0, u2 = 0;
  double gap = 0;        ///< current normal gap g - u_n, u_n = -n . u (n: obstacle normal)
  double multiplier = 0; ///< nodal contact force
  double pressure = 0;   ///< multiplier / weight (tributary length)
  double weight = 0;
  bool contact = false; ///< status 1 of case.b
};

/// Join case.cont (node, normal, gap, weight) with case.b (u, multiplier, status). Throws
/// sig::Error naming the file when arrays disagree in length or a node is out of range.
std::vector<ContactRow> contact_rows(const Mesh& mesh, const Ds& cont, const Ds& solution);

/// contact.csv: header `node,x1,x2,u1,u2,gap,multiplier,pressure,status`, status written as the
/// word `contact` or `free`, numbers with 17 significant digits.
std::string contact_csv(const std::vector<ContactRow>& rows);

/// The rows as Hertz samples, x measured from the vertical line x1 = centre_x1.
std::vector<PressureSample> pressure_samples(const std::vector<ContactRow>& rows, double centre_x1);

} // namespace sig
