#include "integrator/dynamic_contact.hpp"

#include "assembly/dirichlet.hpp"
#include "contact/contact_elements.hpp"
#include "core/error.hpp"
#include "integrator/elastodynamics.hpp"
#include "integrator/time_scheme.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

namespace sig {

Eigen::VectorXd ContactBoundary::penetration(const Eigen::VectorXd& x) const {
  return (x - geometric_gap).cwiseMax(0.0);
}

ContactBoundary contact_boundary(const ContactElements& elements, const Mesh& mesh,
                                 const ReducedSystem& reduced) {
  ContactBoundary b;
  b.nodes = elements.node;
  b.setting = {elements.law, elements.weight};
  b.geometric_gap = elements.gap;
  const int p = elements.size();
  for (int i = 0; i < p; ++i)
    SIG_VERIFY(elements.node[i] >= 0 && elements.node[i] < mesh.num_nodes(),
               "contact element " << i + 1 << ": node " << elements.node[i] + 1
                                  << " is not a node of the mesh");
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < p; ++i) {
    const std::array<int, 2> dofs = reduced.contact_node_dofs(elements.node[i]);
    for (int component = 0; component < 2; ++component)
      entries.emplace_back(i, dofs[component], -elements.normal[i][component]);
  }
  b.B.resize(p, reduced.num_free());
  b.B.setFromTriplets(entries.begin(), entries.end());
  return b;
}

CondensedContact condense_contact(const TimeScheme& scheme, const ContactBoundary& boundary) {
  CondensedContact c;
  const Eigen::MatrixXd Bt = Eigen::MatrixXd(boundary.B.transpose());
  c.Z = scheme.solve_step_operator(Bt);
  Eigen::MatrixXd C = boundary.B * c.Z;
  C = 0.5 * (C + C.transpose()).eval();
  const Eigen::LLT<Eigen::MatrixXd> cholesky(2.0 * C);
  SIG_VERIFY(cholesky.info() == Eigen::Success, "the step operator condensed on the "
                                                    << boundary.size()
                                                    << " contact nodes is not positive definite "
                                                       "(a node in two contact elements?)");
  c.A = cholesky.solve(Eigen::MatrixXd::Identity(boundary.size(), boundary.size()));
  c.A = 0.5 * (c.A + c.A.transpose()).eval();
  return c;
}

} // namespace sig
