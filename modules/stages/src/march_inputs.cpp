#include "stages/march_inputs.hpp"

#include "assembly/dirichlet.hpp"
#include "assembly/system.hpp"
#include "contact/contact_elements.hpp"
#include "core/error.hpp"
#include "integrator/emm.hpp"
#include "mesh/mesh.hpp"

#include <memory>
#include <utility>

namespace sig {

LoadHistory reduced_load(const ReducedSystem& reduced) {
  const TimeLoads& loads = reduced.time_loads;
  if (loads.empty()) return constant_load(reduced.f);
  if (loads.moving.empty())
    return [f = reduced.f, rate = reduced.restrict(loads.rate)](double t) {
      return Eigen::VectorXd(f + t * rate);
    };
  // What ReducedSystem::load_at reads, without the stiffness.
  auto moving = std::make_shared<ReducedSystem>();
  moving->f = reduced.f;
  moving->free_dofs = reduced.free_dofs;
  moving->reduced_index = reduced.reduced_index;
  moving->time_loads = loads;
  return [moving](double t) { return moving->load_at(t); };
}

Eigen::SparseMatrix<double> mass_matrix(const LinearSystem& system, MassChoice choice,
                                        const Mesh& mesh, const std::vector<int>& contact_nodes) {
  SIG_VERIFY(system.M.rows() == system.num_dofs() && system.M.nonZeros() > 0,
             "the system has no mass: give the MATERIAL cards a density rho > 0");
  switch (choice) {
  case MassChoice::consistent:
    return system.M;
  case MassChoice::lumped:
    return diagonal_mass(system.M_lumped);
  case MassChoice::emm:
    // Without contact nodes the EMM would be the consistent mass under another name.
    SIG_VERIFY(!contact_nodes.empty(), "mass=emm needs the contact nodes (a CONTACT card)");
    // The integrator sees positions, not the mesh (tests/layering).
    require_2d(mesh, "sig-march", "TIME mass=emm");
    return equivalent_mass_matrix(system.M, plane_positions(mesh), contact_nodes);
  }
  return system.M;
}

Elastodynamics reduced_elastodynamics(const ReducedSystem& reduced,
                                      const Eigen::SparseMatrix<double>& mass) {
  Elastodynamics problem;
  problem.K = reduced.K;
  problem.M = reduced.restrict_matrix(mass);
  problem.load = reduced_load(reduced);
  return problem;
}

ViscoelasticProblem viscoelastic_problem(const LinearSystem& system, const ReducedSystem& reduced,
                                         const Eigen::SparseMatrix<double>& mass) {
  ViscoelasticProblem problem;
  problem.K = reduced.K;
  if (system.V.size() > 0) problem.C = reduced.restrict_matrix(system.V);
  for (const MemoryStiffness& term : system.memory)
    problem.memory.push_back({term.beta, reduced.restrict_matrix(term.K)});
  if (mass.size() > 0) problem.M = reduced.restrict_matrix(mass);
  problem.load = reduced_load(reduced);
  return problem;
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
  std::vector<Eigen::Triplet<double>> normal, tangential;
  for (int i = 0; i < p; ++i) {
    const std::array<int, 2> dofs = reduced.contact_node_dofs(elements.node[i]);
    const Eigen::Vector2d t = contact_tangent(elements.normal[i]);
    for (int component = 0; component < 2; ++component) {
      normal.emplace_back(i, dofs[component], -elements.normal[i][component]);
      tangential.emplace_back(i, dofs[component], t[component]);
    }
  }
  b.B.resize(p, reduced.num_free());
  b.B.setFromTriplets(normal.begin(), normal.end());
  b.tangential.resize(p, reduced.num_free());
  b.tangential.setFromTriplets(tangential.begin(), tangential.end());
  return b;
}

VelocityContact velocity_contact(const ContactElements& elements, const ReducedSystem& reduced) {
  VelocityContact c;
  for (int p = 0; p < elements.size(); ++p)
    c.dofs.push_back(reduced.contact_node_dofs(elements.node[p]));
  c.normal.assign(elements.normal.begin(), elements.normal.end()); // 2D: sig-march requires it
  c.setting = {elements.law, elements.weight};
  return c;
}

} // namespace sig
